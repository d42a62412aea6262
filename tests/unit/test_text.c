/* UTF-8 as RFC 3629 defines it: every class of well-formed sequence, at
 * the edges of its ranges, and every class of ill-formed one refused. */
#include <string.h>

#include "scene/text.h"
#include "tap.h"

static void len_is(const char *s, int want, const char *what)
{
    int got = adh_text_utf8_len(s);
    ok(got == want, "%s: length %d (got %d)", what, want, got);
}

int main(void)
{
    /* well-formed: each lead byte's range, at its edges */
    len_is("A", 1, "ASCII");
    len_is("", 1, "NUL (an ASCII byte)");
    len_is("\x7f", 1, "DEL, U+007F");
    len_is("\xc2\x80", 2, "U+0080, the least two-byte");
    len_is("\xc2\xb5", 2, "the micro sign U+00B5");
    len_is("\xdf\xbf", 2, "U+07FF, the largest two-byte");
    len_is("\xe0\xa0\x80", 3, "U+0800, the least three-byte");
    len_is("\xed\x9f\xbf", 3, "U+D7FF, just below the surrogates");
    len_is("\xee\x80\x80", 3, "U+E000, just above the surrogates");
    len_is("\xef\xbf\xbf", 3, "U+FFFF");
    len_is("\xf0\x90\x80\x80", 4, "U+10000, the least four-byte");
    len_is("\xf4\x8f\xbf\xbf", 4, "U+10FFFF, the largest code point");
    /* overlong forms */
    len_is("\xc0\x80", 0, "overlong U+0000 (C0 80)");
    len_is("\xc1\xbf", 0, "overlong U+007F (C1 BF)");
    len_is("\xe0\x80\x80", 0, "overlong U+0000 in three bytes (E0 80 80)");
    len_is("\xe0\x9f\xbf", 0, "overlong U+07FF in three bytes (E0 9F BF)");
    len_is("\xf0\x80\x80\x80", 0, "overlong U+0000 in four bytes (F0 80 80 80)");
    len_is("\xf0\x8f\xbf\xbf", 0, "overlong U+FFFF in four bytes (F0 8F BF BF)");
    /* UTF-16 surrogates */
    len_is("\xed\xa0\x80", 0, "surrogate U+D800 (ED A0 80)");
    len_is("\xed\xbf\xbf", 0, "surrogate U+DFFF (ED BF BF)");
    /* past U+10FFFF */
    len_is("\xf4\x90\x80\x80", 0, "U+110000 (F4 90 80 80)");
    len_is("\xf5\x80\x80\x80", 0, "lead byte F5");
    len_is("\xff", 0, "byte FF");
    /* truncated, lone continuation, Latin-1 */
    len_is("\x9b", 0, "a lone continuation byte (CSI 0x9b)");
    len_is("\xe9t\xe9", 0, "Latin-1 e-acute");
    len_is("\xe2\x82", 0, "a three-byte sequence cut short");
    len_is("\xf0\x90\x80", 0, "a four-byte sequence cut short");
    /* the first bad byte of a text */
    const char *t = "ok \xc2\xb5m \xed\xa0\x80 tail";
    ok(adh_text_not_utf8(t) == strstr(t, "\xed"), "not_utf8: the surrogate's first byte, after a good micro sign");
    ok(adh_text_not_utf8("5 \xc2\xb5m, \xf4\x8f\xbf\xbf") == NULL, "not_utf8: well-formed text passes");
    return tap_done();
}
