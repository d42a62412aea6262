#include "adhere/protocol.h"
#include "adhere/rings.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "adhere/models.h"
#include "adhere/status.h"
#include "adhere/units.h"

adh_protocol_settings adh_protocol_settings_default(void)
{
    adh_protocol_settings ps;
    memset(&ps, 0, sizeof ps);
    ps.start = NAN;
    ps.step = 0.05e-9;
    ps.nturns = 1;
    ps.turns[0] = -5e-9;
    ps.unload = 1;
    return ps;
}

double adh_protocol_auto_start(const adh_material *m, double step)
{
    /* |delta(h)| = 0.01 z0 from eq 23 */
    double hb = pow(m->A * sqrt(2.0 * m->R) / (8.0 * m->E * 0.01 * m->z0), 0.4);
    double h = fmax(hb, fmax(4.0 * adh_jump_separation(m), 5.0 * m->z0));
    return step * ceil(h / step - 1e-9);
}

double adh_protocol_reach(const adh_material *m)
{
    return 0.02 * m->R;
}

double adh_protocol_deepest_turn(const adh_protocol_settings *ps)
{
    double t = INFINITY;
    for (size_t i = 0; i < ps->nturns; i++)
        t = fmin(t, ps->turns[i]);
    return t;
}

static void set_fix(unsigned *fix, unsigned bits)
{
    if (fix)
        *fix = bits;
}

/* The drive settings alone (no grid): step, dwell, turns, R and the start. */
static int check_drive(const adh_protocol_settings *ps, const adh_material *m, char *why, size_t whylen,
                       unsigned *fix)
{
    if (!(isfinite(ps->step) && ps->step >= 1e-14 && ps->step <= 1e-8)) {
        snprintf(why, whylen, "step d = %s is not allowed: it must be from 0.01 pm to 10 nm", adh_qtext(ps->step, ADH_Q_LENGTH).s);
        return ADH_EINVAL;
    }
    if (adh_protocol_dwell_check(ps->dwell > ADH_PROTOCOL_MAX_DWELL ? LONG_MAX : (long)ps->dwell, why, whylen) != ADH_SUCCESS)
        return ADH_EINVAL;
    if (ps->nturns > ADH_MAX_TURNS) {
        snprintf(why, whylen, "%zu turning points given: at most %d are allowed", ps->nturns, ADH_MAX_TURNS);
        return ADH_EINVAL;
    }
    for (size_t i = 0; i < ps->nturns; i++) {
        double t = ps->turns[i];
        if (!isfinite(t) || t < -adh_protocol_reach(m)) {
            int dflt = ps->nturns == 1 && t == adh_protocol_settings_default().turns[0];
            snprintf(why, whylen, "turning point %s%s is too deep: the model (h0 << R) allows down to -R/50 = %s%s",
                     adh_qtext(t, ADH_Q_LENGTH).s, dflt ? " (the default turn)" : "", adh_qtext(-adh_protocol_reach(m), ADH_Q_LENGTH).s,
                     dflt ? "; give a shallower turn or a larger R" : "");
            set_fix(fix, dflt ? ADH_FIX_TURNS | ADH_FIX_RADIUS : 0);
            return ADH_EINVAL;
        }
    }
    double lowest = ps->nturns ? adh_protocol_deepest_turn(ps) : 0.0;
    /* The model needs h0 << R and a grid edge (at most 0.3 R out) where the
     * gap is many z0 wide: r^2/2R there is at most 0.045 R. */
    double need = (10.0 * m->z0 + fabs(lowest)) / 0.045;
    if (m->R < need) {
        snprintf(why, whylen, "R = %s is too small for this model: h0 << R and a negligible force at the grid edge need R >= %s here, 10 z0 plus the deepest |h0| over 0.045",
                 adh_qtext(m->R, ADH_Q_LENGTH).s, adh_qtext(need, ADH_Q_LENGTH).s);
        set_fix(fix, ADH_FIX_RADIUS);
        return ADH_EINVAL;
    }
    double start = isnan(ps->start) ? adh_protocol_auto_start(m, ps->step) : ps->start;
    if (!isfinite(start) || start <= 0 || start > adh_protocol_reach(m)) {
        if (isnan(ps->start))
            snprintf(why, whylen, "R = %s is too small for this material: the automatic start (where the force is negligible: the bulge of eq 23 below 0.01 z0 and 4 jump separations out) is %s, above R/50 = %s (the model needs h0 << R); use a larger R, or give a start up to %s",
                     adh_qtext(m->R, ADH_Q_LENGTH).s, adh_qtext(start, ADH_Q_LENGTH).s, adh_qtext(adh_protocol_reach(m), ADH_Q_LENGTH).s, adh_qtext(adh_protocol_reach(m), ADH_Q_LENGTH).s);
        else
            snprintf(why, whylen, "start = %s is not allowed: it must be above 0 and at most R/50 = %s (the model needs h0 << R)",
                     adh_qtext(start, ADH_Q_LENGTH).s, adh_qtext(adh_protocol_reach(m), ADH_Q_LENGTH).s);
        set_fix(fix, isnan(ps->start) ? ADH_FIX_RADIUS | ADH_FIX_START : 0);
        return ADH_EINVAL;
    }
    for (size_t i = 0; i < ps->nturns; i++) {
        if (ps->turns[i] >= start) {
            snprintf(why, whylen, "turning point %s is not allowed: it must lie below the start %s", adh_qtext(ps->turns[i], ADH_Q_LENGTH).s, adh_qtext(start, ADH_Q_LENGTH).s);
            return ADH_EINVAL;
        }
    }
    double steps = (start - lowest) / ps->step;
    if (steps > 2e6) {
        snprintf(why, whylen, "%.0f drive steps of %s from %s to %s: at most 2e6 are allowed; take a larger step", steps,
                 adh_qtext(ps->step, ADH_Q_LENGTH).s, adh_qtext(start, ADH_Q_LENGTH).s, adh_qtext(lowest, ADH_Q_LENGTH).s);
        set_fix(fix, ADH_FIX_STEP);
        return ADH_EINVAL;
    }
    return ADH_SUCCESS;
}

/* The grid against the run: spacing, radius, the contact at the deepest
 * turn lowest, the force beyond the edge. */
static int check_grid(const adh_protocol_settings *ps, const adh_material *m, const adh_grid *g, double lowest,
                      char *why, size_t whylen, unsigned *fix)
{
    if (adh_grid_nodes_check(g->n > (size_t)LONG_MAX ? LONG_MAX : (long)g->n, why, whylen) != ADH_SUCCESS)
        return ADH_EINVAL;
    double lateral = sqrt(m->R * m->z0);
    if (g->dr > 0.25 * lateral) {
        snprintf(why, whylen, "grid spacing %s is too coarse: the contact edge needs at most 0.25 sqrt(R z0) = %s; use more nodes",
                 adh_qtext(g->dr, ADH_Q_LENGTH).s, adh_qtext(0.25 * lateral, ADH_Q_LENGTH).s);
        set_fix(fix, ADH_FIX_NODES);
        return ADH_EGRID;
    }
    /* the limit itself is allowed: N x spacing from values with units
     * (3nm is 3 x 1e-9) lands a few ulps past 0.3 R */
    if (g->rmax > 0.3 * m->R * (1 + 1e-12)) {
        /* a graded grid's last ring reaches past the radius it was asked for */
        snprintf(why, whylen, "grid radius Rmax = %s is not << R = %s: at most 0.3 R = %s is allowed%s",
                 adh_qtext(g->rmax, ADH_Q_LENGTH).s,
                 adh_qtext(m->R, ADH_Q_LENGTH).s, adh_qtext(0.3 * m->R, ADH_Q_LENGTH).s,
                 g->graded ? " (the graded rings' outer edge: the last ring, growing, ends past the radius asked; "
                             "ask for a radius one ring smaller)"
                           : " (N x spacing)");
        return ADH_EGRID;
    }
    /* The contact at the deepest position: the undeformed overlap radius,
     * enlarged by half again for adhesion (JKR contacts exceed Hertz's). */
    double gap_edge = lowest + g->rmax * g->rmax / (2.0 * m->R);
    double a_est = 1.5 * sqrt(2.0 * m->R * fmax(0.0, m->z0 - lowest));
    if (gap_edge < 10 * m->z0 || a_est > 0.8 * g->rmax) {
        /* a graded grid's radius is its own setting: more nodes or a larger
         * spacing (the advice it had) leave a radius given as it was */
        snprintf(why, whylen, "grid radius Rmax = %s is too short: the contact at h0 = %s may reach %s; %s",
                 adh_qtext(g->rmax, ADH_Q_LENGTH).s, adh_qtext(lowest, ADH_Q_LENGTH).s, adh_qtext(a_est, ADH_Q_LENGTH).s,
                 g->graded ? "use a larger grid radius" : "use more nodes or a larger spacing");
        set_fix(fix, g->graded ? ADH_FIX_GRID_RADIUS : ADH_FIX_NODES | ADH_FIX_SPACING);
        return ADH_EGRID;
    }
    /* Coarser than five edge zones, the contact line moves node by node and
     * the relaxation locks into oscillation between nodes (seen at sigma =
     * 100 on the N = 100 default grid: every step at the iteration cap). */
    double edge = adh_edge_zone(m);
    if (ps->nturns > 0 && g->dr > 5.0 * edge) {
        snprintf(why, whylen, "grid spacing %s is too coarse for this contact: its edge zone is about %s wide (sigma = %.3g), and a spacing above 5 times that (%s) locks the contact line to the nodes; use more nodes or a smaller spacing",
                 adh_qtext(g->dr, ADH_Q_LENGTH).s, adh_qtext(edge, ADH_Q_LENGTH).s, adh_material_sigma(m), adh_qtext(5.0 * edge, ADH_Q_LENGTH).s);
        set_fix(fix, ADH_FIX_NODES | ADH_FIX_SPACING);
        return ADH_EGRID;
    }
    if (adh_rings_check(g, m, lowest, why, whylen, fix) != ADH_SUCCESS)
        return ADH_EGRID;
    double tail = fabs(adh_rigid_force(m, gap_edge));
    double scale = fabs(adh_dmt_pulloff(m));
    if (tail > 1e-3 * scale) {
        snprintf(why, whylen, "grid radius Rmax = %s is too short: the force beyond it (%s) is not negligible against 2 pi gamma R = %s",
                 adh_qtext(g->rmax, ADH_Q_LENGTH).s, adh_qtext(tail, ADH_Q_FORCE).s, adh_qtext(scale, ADH_Q_FORCE).s);
        return ADH_EGRID;
    }
    return ADH_SUCCESS;
}

int adh_protocol_check(const adh_protocol_settings *ps, const adh_material *m, const adh_grid *g, char *why,
                       size_t whylen, unsigned *fix)
{
    set_fix(fix, 0);
    int rc = check_drive(ps, m, why, whylen, fix);
    if (rc != ADH_SUCCESS || !g)
        return rc;   /* g NULL: rigid spheres, no grid to check */
    return check_grid(ps, m, g, ps->nturns ? adh_protocol_deepest_turn(ps) : 0.0, why, whylen, fix);
}

int adh_protocol_dwell_check(long dwell, char *why, size_t whylen)
{
    if (dwell >= 0 && dwell <= ADH_PROTOCOL_MAX_DWELL)
        return ADH_SUCCESS;
    snprintf(why, whylen, "dwell = %ld iterations is not allowed: use 0 to %d", dwell, ADH_PROTOCOL_MAX_DWELL);
    return ADH_EINVAL;
}
