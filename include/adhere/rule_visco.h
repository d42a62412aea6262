/* The viscoelastic step rule, adh_rule_visco (adhere/rule.h): a curve
 * rule, each step the next step of the integrator along the physical path
 * (adhere/visco.h): loading, the dwell and the retraction from every turn
 * in physical time, through the spring, the jumps crossed. Its settings
 * are adh_visco_rule_settings (NULL: elastic at the material's E, 1 um/s).
 * The material's E is E0. Started at the protocol's start, or, when that
 * is automatic and a spring would snap in from there, further out. */
#ifndef ADHERE_RULE_VISCO_H
#define ADHERE_RULE_VISCO_H

#include "adhere/drive.h"
#include "adhere/rule.h"
#include "adhere/run.h"
#include "adhere/visco.h"

/* The solver behind drive d (summary, events, energies), NULL when d
 * steps another rule. */
const adh_visco *adh_rule_visco_solver(const adh_drive *d);
/* The solver's own record of the run: the same rows, and what a curve
 * rule's drive does not keep: every turn's summary (pull-off, jump-out)
 * and the profiles at the protocol's positions of the base. */
const adh_run *adh_rule_visco_record(const adh_drive *d);
/* Moves what the record keeps beyond the rows (the turns' summaries and
 * the profiles) into run, the drive's own record, at the end of a run:
 * run then holds the whole run as a stepped rule's drive leaves it. */
void adh_rule_visco_take(adh_drive *d, adh_run *run);

#endif
