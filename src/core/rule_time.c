/* A run in physical time, whichever rule steps it (adhere/rule_time.h). */
#include "adhere/rule_time.h"

#include <string.h>

#include "adhere/rule_path.h"
#include "adhere/rule_visco.h"

int adh_rule_time_is(const adh_drive *d)
{
    return adh_drive_workspace(d, &adh_rule_visco) || adh_drive_workspace(d, &adh_rule_path);
}

int adh_rule_time_summary(const adh_drive *d, adh_visco_result *res)
{
    const adh_visco *w = adh_rule_visco_solver(d);
    if (w) {
        adh_visco_summary(w, res);
        return 0;
    }
    size_t rows;
    const adh_path *p = adh_rule_path_walk(d, &rows);
    if (!p)
        return -1;
    adh_static_result sr;
    memset(&sr, 0, sizeof sr);
    adh_rule_path_curve(d, &sr);
    adh_path_summary(p, rows, res);
    /* no integrator: the static curve's work */
    res->newton = sr.newton_iterations;
    res->krylov = sr.krylov_iterations;
    res->setups = sr.factorizations;
    res->seconds = sr.seconds;
    return 0;
}

int adh_rule_time_summary_at(const adh_drive *d, size_t rows, adh_visco_result *res)
{
    if (adh_rule_time_summary(d, res) != 0)
        return -1;
    size_t handed;
    const adh_path *p = adh_rule_path_walk(d, &handed);
    if (p && rows < handed) {
        adh_visco_result all = *res;
        adh_path_summary(p, rows, res);
        res->newton = all.newton, res->krylov = all.krylov, res->setups = all.setups, res->seconds = all.seconds;
    }
    return 0;
}

size_t adh_rule_time_events(const adh_drive *d, const adh_visco_event **ev)
{
    const adh_visco *w = adh_rule_visco_solver(d);
    size_t rows;
    const adh_path *p = adh_rule_path_walk(d, &rows);
    *ev = NULL;
    return w ? adh_visco_events(w, ev) : p ? adh_path_events(p, rows, ev) : 0;
}

void adh_rule_time_take(adh_drive *d, adh_run *run)
{
    adh_rule_visco_take(d, run);
    adh_rule_path_take(d, run);
}
