/* An elastic sphere in physical time as a step rule, adh_rule_path
 * (adhere/rule.h): a curve rule that follows the static equilibrium curve
 * (adhere/static.h, the static mode's solver with the static mode's
 * settings) from the protocol's start to its deepest turn, then hands out
 * the physical path read off it (adhere/path.h) one row a step: loading,
 * each turn's dwell and unloading, the jumps at the folds of the base,
 * time from the base's travel. No time integration: an elastic solid
 * without inertia is rate-independent. Its settings are the viscoelastic
 * rule's, adh_visco_rule_settings (the drive, and the cancel flag; the
 * solid's moduli are not read: the material's E is the sphere's); NULL:
 * 1 um/s both ways, no dwell, no spring. The first step solves the whole
 * curve (the cancel flag stops it). */
#ifndef ADHERE_RULE_PATH_H
#define ADHERE_RULE_PATH_H

#include <signal.h>

#include "adhere/drive.h"
#include "adhere/path.h"
#include "adhere/rule.h"
#include "adhere/static.h"

/* The static curve's settings under spring k (INFINITY: none) with the
 * cancel flag, for the static mode and for this rule alike: under a
 * spring the points are at most 0.25 z0 apart, so that the snap points
 * read off between them hold (the base there moves < 1e-5 from 1 z0 to
 * 0.1 z0 apart). */
adh_static_settings adh_rule_path_static_settings(double k, const volatile sig_atomic_t *cancel);

/* The static curve behind drive d and its summary (NULL, and res
 * untouched, when d steps another rule or the curve is not solved yet);
 * from a start in contact its rows begin with the curve beyond the start,
 * from the automatic start down to it (adh_path_curve.start). */
const adh_run *adh_rule_path_curve(const adh_drive *d, adh_static_result *res);

/* The path behind drive d (summary, events: none before the first
 * step) and in *rows (may be NULL) how many of its rows the drive has
 * had; NULL when d steps another rule. */
const adh_path *adh_rule_path_walk(const adh_drive *d, size_t *rows);
/* Moves the turns' summaries and the profiles of the path into run, the
 * drive's own record, at the end of a run (as adh_rule_visco_take). */
void adh_rule_path_take(adh_drive *d, adh_run *run);

#endif
