/* Text read from a user's file (a scene, a measured curve) that a message
 * may quote back to the terminal, and the bounded appends every layer's
 * messages are built with. */
#ifndef ADH_SCENE_TEXT_H
#define ADH_SCENE_TEXT_H

#include <stddef.h>

/* The first byte of s that does not begin or continue a UTF-8 character,
 * or NULL: no lone byte 0x80-0x9f (C1 controls, CSI 0x9b among them, to
 * some terminals) or Latin-1 text is quoted as it is, nor an overlong
 * form, a surrogate or a code point past U+10FFFF (not UTF-8, RFC 3629,
 * and an overlong form may hide an ASCII control from a check). */
const char *adh_text_not_utf8(const char *s);

/* The bytes of the UTF-8 character s begins with (1 to 4; an ASCII byte,
 * the NUL too, is 1), or 0 when s does not begin a well-formed one
 * (RFC 3629: no overlong form, surrogate, or code point past U+10FFFF). */
int adh_text_utf8_len(const char *s);

/* Appends text to the string in buf (len), as much as fits (never past
 * len, always terminated): whole, however long, where one printf
 * conversion may portably write only 4095 bytes (a sentence with a scene's
 * name whole in it, PATH_MAX). */
void adh_text_cat(char *buf, size_t len, const char *text);
/* Appends printf-formatted text to the string in buf (len), cut at its
 * end. */
void adh_text_catf(char *buf, size_t len, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

#endif
