/* The CLI's words for what a core refusal asks to change: the core's
 * sentence names quantities and sets ADH_FIX_* bits (adhere/status.h); the
 * CLI names the flags. */
#ifndef ADH_CLI_ADVICE_H
#define ADH_CLI_ADVICE_H

#include <stddef.h>

/* Whose line the advice is for: a run's, or adhere fit's, whose turn is
 * no flag but a step below its measured curve's deepest position. */
typedef enum { CLI_ADVICE_RUN, CLI_ADVICE_FIT } cli_advice_for;

/* Appends the flags of the bits in fix to the sentence in why, as
 * " (--turn, -R)"; nothing for 0 (or when they do not fit). */
void cli_advice_append(char *why, size_t whylen, unsigned fix);
/* The same for who: a fit's turn is named as its data's
 * " (-R; the turn is the fit's, a step below the deepest position in --data)". */
void cli_advice_append_for(cli_advice_for who, char *why, size_t whylen, unsigned fix);

#endif
