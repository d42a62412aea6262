/* Numbers with optional SI unit suffix: "1GPa", "0.5nm", "10um", "1e-19J". */
#ifndef ADHERE_UNITS_H
#define ADHERE_UNITS_H

#include <stddef.h>

typedef enum adh_quantity {
    ADH_Q_NONE = 0,      /* a pure number: no unit allowed */
    ADH_Q_LENGTH,        /* m */
    ADH_Q_PRESSURE,      /* Pa */
    ADH_Q_ENERGY,        /* J */
    ADH_Q_SPEED,         /* m/s */
    ADH_Q_FORCE,         /* N */
    ADH_Q_TIME,          /* s */
    ADH_Q_STIFFNESS,     /* N/m */
    ADH_Q_WORK           /* J, written with a metric prefix (hysteresis,
                            dissipated energy: 6.579 fJ, 21.8 pJ), where an
                            ADH_Q_ENERGY (the Hamaker constant) is written
                            1e-19 J; parsed as an energy */
} adh_quantity;
#define ADH_Q_LAST ADH_Q_WORK

/* Parses text as a finite number in quantity q's SI unit, with an optional
 * metric prefix and unit ("nm", "um", "GPa", "zJ"...). Returns ADH_SUCCESS,
 * or ADH_EINVAL with a message in why (naming the text and what is allowed). */
int adh_parse_quantity(const char *text, adh_quantity q, double *value, char *why, size_t whylen);
/* A comma-separated list of q that reads as a decimal comma: a bare whole
 * number, then an element of digits with a unit ("-0,5nm": 0 m, or 0 nm on
 * the screen, and 5 nm; "1,5um/s"), whose joined form (-0.5nm) parses. ADH_EINVAL with a message
 * naming both readings; ADH_SUCCESS for any other list. */
int adh_list_decimal_comma(const char *text, adh_quantity q, char *why, size_t whylen);
/* A whole number in [lo, hi]: ADH_SUCCESS, or ADH_EINVAL with a message. */
int adh_parse_count(const char *text, long lo, long hi, long *value, char *why, size_t whylen);
/* The SI unit symbol of q ("m", "Pa", ...), "" for ADH_Q_NONE. */
const char *adh_quantity_unit(adh_quantity q);
/* Formats value with the best metric prefix, e.g. 3e8 Pa -> "300 MPa";
 * zero takes the prefix its quantity is usually read in ("0 nm", "0 nN"). */
void adh_format_quantity(double value, adh_quantity q, int digits, char *buf, size_t len);
/* value in the fewest significant digits that read back to the same double
 * (5.0000001e-05, not %.17g's 5.0000000999999998e-05): a number echoed to
 * the user as it was typed, and still exact. Returns buf. */
const char *adh_format_shortest(double value, char *buf, size_t len);

/* A quantity as text for a sentence, four significant digits with its
 * prefix (adh_format_quantity): the one way every message writes a value.
 * The text lives until the end of the full expression that made it:
 *     snprintf(why, n, "R = %s is too small", adh_qtext(R, ADH_Q_LENGTH).s); */
typedef struct adh_qtext_buf {
    char s[48];
} adh_qtext_buf;
adh_qtext_buf adh_qtext(double value, adh_quantity q);
/* The same as a value is typed, number and unit together in ASCII
 * ("1.58nm", "10um"): for the values a message tells the user to give. */
adh_qtext_buf adh_qtext_arg(double value, adh_quantity q);

/* Whether text (a number, or a comma-separated list of them) gives no unit
 * anywhere: a bare number, read in SI by flags and scenes. */
int adh_quantity_is_bare(const char *text);

#endif
