/* The CLI's words for what a core refusal asks to change: the core's
 * sentence names quantities and sets ADH_FIX_* bits (adhere/status.h); the
 * CLI names the flags, or the scene's keys where the scene set them. */
#ifndef ADH_CLI_ADVICE_H
#define ADH_CLI_ADVICE_H

#include <stddef.h>

#include "scene/config.h"

/* Whose line the advice is for: a run's, adhere fit's, whose turn is no
 * flag but a step below its measured curve's deepest position, or a
 * --cost run's, whose N and eps are --cost-nodes' and --cost-eps'. */
typedef enum { CLI_ADVICE_RUN, CLI_ADVICE_FIT, CLI_ADVICE_COST } cli_advice_for;

/* Appends the settings of the bits in fix to the sentence in why, as
 * " (--turn, -R)"; nothing for 0. For who (a
 * fit's turn is named as its data's: " (-R; the turn
 * is the fit's, a step below the deepest position in --data)"; a --cost
 * run's N as --cost-nodes), in the words each key was given in (cfg NULL:
 * the flags): a key the scene set by its name, where it was written
 * ("nodes at a.scene:3, spacing at line 4"; the file once, with what the
 * sentence in why names: a key it names with its file and line by its
 * name alone), a flag's by the flag; a key nobody set in the scene's
 * words when the keys the list names that were set are the scene's
 * alone (or none was, and the sentence placed a key in the scene), else
 * as a flag (as cli_options_words says a sentence). */
void cli_advice_append_cfg(const adh_config *cfg, cli_advice_for who, char *why, size_t whylen, unsigned fix);
/* The room a sentence and its advice take whole: a core's sentence, a
 * scene's name (PATH_MAX) and the keys' words. Where why has less room,
 * cli_advice_append_cfg cuts the scene's name in its middle ("…") until
 * the list fits, and the list's end (with "…") only when even that does
 * not: the advice is never dropped for want of room. */
#define CLI_ADVICE_LEN (PATH_MAX + 1024)
/* path into buf (len), whole when it has at most max bytes, else cut in
 * its middle to max bytes: "/home/…/runs/a.scene" (a third before "…",
 * the rest after it: the file's own name is kept). */
void cli_advice_path(const char *path, size_t max, char *buf, size_t len);
/* The key of one ADH_FIX_* bit in a sentence, with value (NULL: none), in
 * the voice of voice_bits: "--spacing=1.5nm", or "spacing = 1.5nm
 * (a.scene:4)" where the scene set it, "spacing = 1.5nm" where nobody did
 * and the voice is the scene's. */
void cli_advice_key(const adh_config *cfg, unsigned voice_bits, unsigned bit, const char *value, char *buf, size_t len);

#endif
