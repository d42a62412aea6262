/* How adhere says what went wrong: one line on stderr, "adhere: " and the
 * message, whose file names, scene text and measured headers came from
 * outside (a name may hold an escape sequence, ESC [ 2 J or 0x9b alone:
 * it is written as \xNN, never sent to the terminal as it is). */
#ifndef ADH_PLOT_SAY_H
#define ADH_PLOT_SAY_H

/* Writes "adhere: MSG\n" to stderr, MSG's control bytes (but newlines and
 * tabs) and bytes that begin no UTF-8 character as \xNN. */
void adh_say(const char *msg);

#endif
