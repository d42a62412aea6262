/* A run in physical time, whichever rule steps it: the viscoelastic
 * integrator (adh_rule_visco, adhere/rule_visco.h) for a standard linear
 * solid, the static curve's path (adh_rule_path, adhere/rule_path.h) for
 * an elastic sphere. What a driver reads of either beyond the rows: the
 * summary, the events, the turns and profiles, the state. */
#ifndef ADHERE_RULE_TIME_H
#define ADHERE_RULE_TIME_H

#include "adhere/drive.h"
#include "adhere/run.h"
#include "adhere/visco.h"

/* Whether drive d steps a rule in physical time. */
int adh_rule_time_is(const adh_drive *d);
/* The summary so far (for the path: its integrator counts are 0, its
 * Newton and GMRES iterations and seconds the static curve's). 0, or -1
 * when d steps another rule (res untouched). */
int adh_rule_time_summary(const adh_drive *d, adh_visco_result *res);
/* The summary as the record's first `rows` rows saw it (a cursor walked
 * back over them: the TUI's b and u): the path's from its rows; the
 * integrator keeps no history, so its summary so far. 0, or -1 as above. */
int adh_rule_time_summary_at(const adh_drive *d, size_t rows, adh_visco_result *res);
/* The events so far (borrowed), 0 for another rule. */
size_t adh_rule_time_events(const adh_drive *d, const adh_visco_event **ev);
/* Moves the turns' summaries and the profiles the rule keeps into run,
 * the drive's own record, at the end of a run. */
void adh_rule_time_take(adh_drive *d, adh_run *run);

#endif
