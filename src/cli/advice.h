/* The CLI's words for what a core refusal asks to change: the core's
 * sentence names quantities and sets ADH_FIX_* bits (adhere/status.h); the
 * CLI names the flags. */
#ifndef ADH_CLI_ADVICE_H
#define ADH_CLI_ADVICE_H

#include <stddef.h>

/* Appends the flags of the bits in fix to the sentence in why, as
 * " (--turn, -R)"; nothing for 0 (or when they do not fit). */
void cli_advice_append(char *why, size_t whylen, unsigned fix);

#endif
