/* How adhere says what went wrong: one line on stderr, "adhere: " and the
 * message, whose file names, scene text and measured headers came from
 * outside (a name may hold an escape sequence, ESC [ 2 J or 0x9b alone:
 * it is written as \xNN, never sent to the terminal as it is). */
#ifndef ADH_PLOT_SAY_H
#define ADH_PLOT_SAY_H

#include <stddef.h>

/* The most of a message's bytes said: a message is written whole up to
 * this size (a long path, a long list), and a longer one cut there, ending
 * with an ellipsis and how many bytes were left out ("... (message cut:
 * 5000 bytes more)"); the same where memory for a long one runs out. */
#define ADH_SAY_MAX ((size_t)1 << 20)

/* Writes "adhere: MSG\n" to stderr, MSG's control bytes (but newlines and
 * tabs) and bytes that begin no UTF-8 character as \xNN. */
void adh_say(const char *msg);
/* The same for "WHO: MSG" ("adhere merge: ..."); who NULL: MSG alone (a
 * replay script's "FILE:LINE: ...", as compilers say it). */
void adh_say_as(const char *who, const char *msg);
/* adh_say of a printf-formatted message (no newline: the writer ends the
 * line); every "adhere: ..." line goes through one of these. */
void adh_sayf(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void adh_sayf_as(const char *who, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#endif
