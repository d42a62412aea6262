/* Numbers with units: every accepted form, and every rejection naming why. */
#include <string.h>

#include "adhere/units.h"
#include "tap.h"

static void accepts(const char *text, adh_quantity q, double want)
{
    double v = 0;
    char why[256] = "";
    int rc = adh_parse_quantity(text, q, &v, why, sizeof why);
    ok(rc == 0 && fabs(v - want) <= 1e-12 * fabs(want), "'%s' parses to %g (got %g) %s", text, want, v, why);
}

/* An underflow's message offers the least magnitude it allows ("at least
 * X m"): that X, written back with its unit, is accepted (2.2e-308 m, the
 * one it offered, was itself refused: DBL_MIN is 2.2251e-308). */
static void offered_is_accepted(const char *text, adh_quantity q, const char *unit)
{
    double v = 0;
    char why[256] = "", back[64] = "";
    adh_parse_quantity(text, q, &v, why, sizeof why);
    const char *at = strstr(why, "at least ");
    if (at) {
        size_t l = strcspn(at + 9, " ");
        l = l < 40 ? l : 40;
        memcpy(back, at + 9, l);
        strcpy(back + l, unit);
    }
    int rc = at ? adh_parse_quantity(back, q, &v, why, sizeof why) : -1;
    ok(rc == 0 && v > 0, "'%s': the least magnitude its message offers, '%s', is accepted %s", text, back,
       rc == 0 ? "" : why);
}

static void rejects(const char *text, adh_quantity q, const char *mentions)
{
    double v = 12345;
    char why[256] = "";
    int rc = adh_parse_quantity(text, q, &v, why, sizeof why);
    ok(rc != 0 && v == 12345 && strstr(why, mentions), "'%s' is rejected, message mentions '%s': %s", text, mentions, why);
}

int main(void)
{
    accepts("1e9", ADH_Q_PRESSURE, 1e9);
    accepts("1GPa", ADH_Q_PRESSURE, 1e9);
    accepts("0.3 GPa", ADH_Q_PRESSURE, 3e8);
    accepts("300MPa", ADH_Q_PRESSURE, 3e8);
    accepts("0.5nm", ADH_Q_LENGTH, 0.5e-9);
    accepts("10um", ADH_Q_LENGTH, 10e-6);
    accepts("10\xc2\xb5m", ADH_Q_LENGTH, 10e-6);
    /* the Greek mu (U+03BC): what the man pages' \(*m renders as ("R in
     * \xce\xbcm", "Default: 1 \xce\xbcm/s"), copied from them, and what a
     * measured file's header may carry */
    accepts("10\xce\xbcm", ADH_Q_LENGTH, 10e-6);
    accepts("1\xce\xbcm/s", ADH_Q_SPEED, 1e-6);
    accepts("1.5cm", ADH_Q_LENGTH, 1.5e-2);
    accepts("2mm", ADH_Q_LENGTH, 2e-3);
    accepts("3m", ADH_Q_LENGTH, 3);
    accepts("1pm", ADH_Q_LENGTH, 1e-12);
    accepts("-5nm", ADH_Q_LENGTH, -5e-9);
    accepts("1e-19J", ADH_Q_ENERGY, 1e-19);
    accepts("100zJ", ADH_Q_ENERGY, 1e-19);
    accepts("1um/s", ADH_Q_SPEED, 1e-6);
    accepts(" 7 ", ADH_Q_NONE, 7);
    rejects("5nm", ADH_Q_PRESSURE, "a length");
    rejects("1GPa", ADH_Q_LENGTH, "a pressure");
    rejects("abc", ADH_Q_LENGTH, "not a number");
    rejects("nan", ADH_Q_LENGTH, "not a number");
    rejects("inf", ADH_Q_PRESSURE, "not a number");
    rejects("-inf", ADH_Q_PRESSURE, "not a number");
    rejects("0x10", ADH_Q_LENGTH, "not a number");
    rejects("1e999", ADH_Q_LENGTH, "range");
    /* below a double's normal range: an underflow, not "out of range" */
    rejects("1e-400m", ADH_Q_LENGTH, "underflows to zero (a double keeps no magnitude below 2.2e-308 m): write 0");
    rejects("1e-310", ADH_Q_NONE, "underflows (a double keeps no magnitude below 2.2e-308)");
    rejects("1e-300pm", ADH_Q_LENGTH, "underflows");
    /* a number past a double's range before its unit, inside it after:
     * the value it is (a key's range then judges it), not an underflow
     * naming a least magnitude the value is far above */
    accepts("1e-310GPa", ADH_Q_PRESSURE, 1e-301);
    accepts("-1e-310km", ADH_Q_LENGTH, -1e-307);
    accepts("1e309pm", ADH_Q_LENGTH, 1e297);
    rejects("1e-400GPa", ADH_Q_PRESSURE, "underflows to zero (a double keeps no magnitude below 2.2e-308 Pa)");
    rejects("1e310GPa", ADH_Q_PRESSURE, "range");
    accepts("0m", ADH_Q_LENGTH, 0);
    accepts("3e-308m", ADH_Q_LENGTH, 3e-308);
    offered_is_accepted("1e-400m", ADH_Q_LENGTH, "m");
    offered_is_accepted("1e-310", ADH_Q_NONE, "");
    accepts("2.23e-308m", ADH_Q_LENGTH, 2.23e-308);
    rejects("5 furlongs", ADH_Q_LENGTH, "unknown unit");
    rejects("", ADH_Q_LENGTH, "not a number");
    rejects("5nm", ADH_Q_NONE, "plain number");
    char longtext[300];
    memset(longtext, '1', sizeof longtext - 1);
    longtext[sizeof longtext - 1] = '\0';
    rejects(longtext, ADH_Q_LENGTH, "longer than");
    rejects("\x01\x02\xff", ADH_Q_LENGTH, "not a number");

    long n = -1;
    char why[256];
    ok(adh_parse_count("1000", 10, 20000, &n, why, sizeof why) == 0 && n == 1000, "count 1000 parses");
    ok(adh_parse_count("5", 10, 20000, &n, why, sizeof why) != 0 && strstr(why, "from 10 to 20000"), "count 5 below 10 is rejected: %s", why);
    ok(adh_parse_count("12.5", 10, 20000, &n, why, sizeof why) != 0, "count 12.5 is rejected");
    ok(adh_parse_count("99999999999999999999999", 10, 20000, &n, why, sizeof why) != 0, "an overflowing count is rejected");

    char buf[64];
    adh_format_quantity(3e8, ADH_Q_PRESSURE, 3, buf, sizeof buf);
    ok(strcmp(buf, "300 MPa") == 0, "3e8 Pa formats as '300 MPa' (got '%s')", buf);
    adh_format_quantity(-5e-9, ADH_Q_LENGTH, 3, buf, sizeof buf);
    ok(strcmp(buf, "-5 nm") == 0, "-5e-9 m formats as '-5 nm' (got '%s')", buf);

    /* a number said back in the fewest digits that read back exactly:
     * %.17g wrote 5.0000001e-5 as 5.0000000999999998e-05 */
    static const struct { double v; const char *want; } sh[] = {
        { 5.0000001e-5, "5.0000001e-05" }, { 0.1, "0.1" }, { 1e-3, "0.001" }, { 2.5e-5, "2.5e-05" },
        { -3, "-3" }, { 0, "0" }, { 0.1 + 0.2, "0.30000000000000004" },
    };
    for (size_t i = 0; i < sizeof sh / sizeof sh[0]; i++) {
        adh_format_shortest(sh[i].v, buf, sizeof buf);
        ok(strcmp(buf, sh[i].want) == 0 && strtod(buf, NULL) == sh[i].v, "%.17g is said back '%s' (got '%s')",
           sh[i].v, sh[i].want, buf);
    }

    /* every message writes a value through one formatter (issue 28, item 2):
     * an engineering prefix, zero in the prefix its quantity is read in,
     * values past the prefixes in SI with an exponent */
    static const struct { double v; adh_quantity q; const char *want; } eng[] = {
        { 1e-8, ADH_Q_LENGTH, "10 nm" }, { 1.5811e-9, ADH_Q_LENGTH, "1.581 nm" }, { 3.24e-11, ADH_Q_LENGTH, "32.4 pm" },
        { 1e-12, ADH_Q_LENGTH, "1 pm" }, { 0, ADH_Q_LENGTH, "0 nm" }, { 0, ADH_Q_FORCE, "0 nN" },
        { -2e-7, ADH_Q_LENGTH, "-200 nm" }, { 10, ADH_Q_LENGTH, "10 m" }, { 1e-30, ADH_Q_LENGTH, "1e-30 m" },
        { 1e13, ADH_Q_PRESSURE, "10 TPa" }, { 1e16, ADH_Q_PRESSURE, "1e+16 Pa" }, { 1e-6, ADH_Q_SPEED, "1 um/s" },
        { 0.5, ADH_Q_NONE, "0.5" }, { 1e-19, ADH_Q_ENERGY, "1e-19 J" },
        /* a work (hysteresis, dissipation) takes its prefix where the
         * Hamaker constant does not: not "2.18e+04 fJ" */
        { 2.18e-11, ADH_Q_WORK, "21.8 pJ" }, { 6.579e-15, ADH_Q_WORK, "6.579 fJ" },
        { 1.329e-16, ADH_Q_WORK, "132.9 aJ" }, { 0, ADH_Q_WORK, "0 fJ" }, { 3e-9, ADH_Q_WORK, "3 nJ" },
    };
    for (size_t i = 0; i < sizeof eng / sizeof eng[0]; i++) {
        const char *got = adh_qtext(eng[i].v, eng[i].q).s;
        ok(strcmp(got, eng[i].want) == 0, "%g %s is written '%s' (got '%s')", eng[i].v, adh_quantity_unit(eng[i].q),
           eng[i].want, got);
    }
    ok(strcmp(adh_qtext_arg(1.58e-9, ADH_Q_LENGTH).s, "1.58nm") == 0, "as typed: 1.58nm (got %s)",
       adh_qtext_arg(1.58e-9, ADH_Q_LENGTH).s);
    double back = 0;
    ok(adh_parse_quantity("5fJ", ADH_Q_WORK, &back, NULL, 0) == 0 && fabs(back - 5e-15) < 1e-27,
       "a work parses as an energy: 5fJ (%g)", back);
    back = 0;
    ok(adh_parse_quantity(adh_qtext_arg(3.3e-8, ADH_Q_LENGTH).s, ADH_Q_LENGTH, &back, NULL, 0) == 0 && fabs(back - 3.3e-8) < 1e-20,
       "a value as typed reads back (%g)", back);
    ok(adh_quantity_is_bare("10") && adh_quantity_is_bare(" -5, -2") && adh_quantity_is_bare("1e-19"),
       "bare numbers and lists of them are bare");
    ok(!adh_quantity_is_bare("10um") && !adh_quantity_is_bare("-5,-2nm") && !adh_quantity_is_bare("none") &&
       !adh_quantity_is_bare("auto"), "a unit anywhere, or a word, is not bare");

    /* a decimal comma in a list ("-0,5nm" was two turns, 0 m and 5 nm, taken
     * without a word): refused, naming both readings and the joined one */
    why[0] = '\0';
    ok(adh_list_decimal_comma("-0,5nm", ADH_Q_LENGTH, why, sizeof why) != 0 &&
       strstr(why, "'-0,5nm' reads as two values, -0 and 5nm: a decimal comma? write -0.5nm for one value"),
       "'-0,5nm' is refused as a decimal comma: %s", why);
    ok(adh_list_decimal_comma("2nm, 1,5nm", ADH_Q_LENGTH, why, sizeof why) != 0 && strstr(why, "write 1.5nm"),
       "... anywhere in a list, blanks around: %s", why);
    ok(adh_list_decimal_comma("1,5um/s", ADH_Q_SPEED, why, sizeof why) != 0 && strstr(why, "write 1.5um/s"),
       "... a speed's: %s", why);
    ok(adh_list_decimal_comma("1,5GPa", ADH_Q_LENGTH, why, sizeof why) == 0,
       "not when the joined form is no value of the quantity (a pressure for a length)");
    const char *fine[] = { "1nm,5nm", "0,-1nm", "2nm,0", "-1,-2", "1,5", "1.5,2nm", "1,5e-9m", "none", "-5nm" };
    int all = 1;
    for (size_t i = 0; i < sizeof fine / sizeof fine[0]; i++)
        all &= adh_list_decimal_comma(fine[i], ADH_Q_LENGTH, why, sizeof why) == 0;
    ok(all, "every other list passes: units on both, a signed second value, bare values alone, a decimal point");
    return tap_done();
}
