/* The static equilibrium curve's step rule, adh_rule_static (adhere/rule.h),
 * and what a driver reads of it beyond the rows. */
#ifndef ADHERE_RULE_STATIC_H
#define ADHERE_RULE_STATIC_H

#include "adhere/drive.h"
#include "adhere/protocol.h"
#include "adhere/rule.h"
#include "adhere/static.h"

/* The static solver behind drive d (folds, summary), NULL when d steps
 * another rule. */
const adh_static *adh_rule_static_solver(const adh_drive *d);
/* Where the static curve of protocol ps ends: its deepest turn, or the
 * static settings' default end without turns. */
double adh_rule_static_end(const adh_protocol_settings *ps);

#endif
