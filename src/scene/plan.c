#include "scene/plan.h"
#include "adhere/grid.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "adhere/models.h"
#include "adhere/observe.h"
#include "adhere/protocol.h"
#include "adhere/rule_rigid.h"
#include "adhere/units.h"

static void note(adh_plan_note *list, size_t *n, const char *what, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

static void note(adh_plan_note *list, size_t *n, const char *what, const char *fmt, ...)
{
    if (*n == ADH_PLAN_MAX_NOTES)
        return;
    adh_plan_note *x = &list[(*n)++];
    snprintf(x->what, sizeof x->what, "%s", what);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(x->why, sizeof x->why, fmt, ap);
    va_end(ap);
}

int adh_plan_jobs(const adh_config *cfg)
{
    size_t runs = adh_config_nruns(cfg);
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    long jobs = cfg->sweep.jobs > 0 ? cfg->sweep.jobs : (cores > 0 ? cores : 1);
    if ((size_t)jobs > runs)
        jobs = (long)runs;
    return jobs < 1 ? 1 : (int)jobs;
}

/* Whether x is one of the positions base + k d (k >= 0) the core steps to:
 * it computes each afresh as base +- k d and matches profiles within 1e-6 d. */
static int on_drive(double x, double base, double dir, double step)
{
    double k = dir * (x - base) / step;
    return k > -1e-6 && fabs(k - nearbyint(k)) < 1e-6;
}

static size_t ceil_steps(double span, double step)
{
    return span > 0 ? (size_t)ceil(span / step - 1e-6) : 0;
}

/* Jump into contact on approach: eq 24 gives the central gap at the
 * instability; when that is inside the contact threshold (hard spheres), the
 * contact is reached first. Eq 23 turns that gap into a drive position. */
static double jump_position(const adh_material *m)
{
    double h = fmax(adh_jump_separation(m), ADH_CONTACT_FACTOR * m->z0);
    return adh_bulge_position(m, h);
}

/* Relaxation iterations a step in contact takes at eps = 1 pm against sigma,
 * measured (docs/performance.md): Figures 1, 5, 4 and 6, the sigma = 22.5
 * and 75 cycles of make bench (the mixing's beta follows the contact's
 * stiffness past sigma ~ 10, so the count falls again at 75); log-log
 * interpolation between them, the ends held beyond. */
static double contact_iterations(double sigma)
{
    static const double s[] = { 2.25, 4.36, 7.5, 17.4, 22.5, 75 }, it[] = { 109, 256, 540, 867, 909, 377 };
    size_t n = sizeof s / sizeof s[0], k = 1;
    if (!(sigma > s[0]))
        return it[0];
    if (sigma >= s[n - 1])
        return it[n - 1];
    while (sigma > s[k])
        k++;
    double t = log(sigma / s[k - 1]) / log(s[k] / s[k - 1]);
    return it[k - 1] * pow(it[k] / it[k - 1], t);
}

double adh_plan_iterations(const adh_run_spec *spec)
{
    const adh_protocol_settings *ps = &spec->proto;
    double step = ps->step, start = adh_config_start(spec);
    double jump = jump_position(&spec->mat);
    adh_derived d;
    adh_material_derive(&spec->mat, &d);
    double per_contact = contact_iterations(d.sigma) * pow(spec->relax.eps / 1e-12, -0.72), per_free = 17.0;
    double deepest = ps->nturns ? adh_protocol_deepest_turn(ps) : jump;
    double in = fmax(0.0, (jump - deepest) / step), out = fmax(0.0, (start - deepest) / step) - in;
    double contact = in, free = out;
    /* unloading: in contact from each turn to JKR's fold (where a
     * displacement-driven contact jumps apart), then free to the start */
    static adh_model_curve jkr;   /* large; plans are made one at a time */
    double fold = jump;
    if (adh_jkr_drive_curve(&spec->mat, deepest, &jkr) == 0 && jkr.n)
        fold = jkr.h0[jkr.n - 1];
    for (size_t i = 0; ps->unload && i < ps->nturns; i++) {
        double t = ps->turns[i];
        double c = fmax(0.0, (fmax(fold, t) - t) / step);
        contact += c;
        free += fmax(0.0, (start - t) / step - c);
    }
    /* each unloaded turn is held for the dwell's iterations, every one run */
    double dwell = ps->unload ? (double)ps->nturns * (double)ps->dwell : 0.0;
    return contact * per_contact + free * per_free + dwell;
}

static void plan_run(const adh_run_spec *rc, const adh_plan *p, adh_plan_run *r)
{
    adh_derived d;
    adh_material_derive(&rc->mat, &d);
    r->E = rc->mat.E;
    r->sigma = d.sigma;
    r->eps = rc->relax.eps;
    r->start = adh_config_start(rc);
    double step = rc->proto.step;
    if (!p->elastic) {
        r->end = adh_rule_rigid_end(&rc->mat, &rc->proto);
        r->loading_steps = 1 + (size_t)floor((r->start - r->end) / step + 1e-6);
        r->unloading_steps = 0;
        r->iterations = (double)r->loading_steps;
        return;
    }
    r->end = p->stop_at_contact ? jump_position(&rc->mat) : adh_protocol_deepest_turn(&rc->proto);
    r->loading_steps = 1 + ceil_steps(r->start - r->end, step);
    /* a turn off the step grid adds its own row */
    for (size_t i = 0; i < rc->proto.nturns; i++)
        if (!on_drive(rc->proto.turns[i], r->start, -1, step))
            r->loading_steps++;
    r->unloading_steps = 0;
    if (p->unloading_branches)
        for (size_t i = 0; i < rc->proto.nturns; i++)
            r->unloading_steps += 1 + (size_t)floor((r->start - rc->proto.turns[i]) / step + 1e-6);
    r->iterations = p->static_mode ? (double)(r->loading_steps + r->unloading_steps) : adh_plan_iterations(rc);
}

size_t adh_plan_steps(const adh_plan *p, const adh_run_spec *rc)
{
    adh_plan_run r;
    plan_run(rc, p, &r);
    return r.loading_steps + r.unloading_steps;
}

static void fmt_len(double v, char *buf, size_t len)
{
    adh_format_quantity(v, ADH_Q_LENGTH, 4, buf, len);
}

/* Which profile positions some branch passes through. */
static void plan_profiles(const adh_run_spec *run, adh_plan *p)
{
    const adh_plan_run *r0 = &p->runs[0];
    double step = run->proto.step;
    p->profiles_asked = run->proto.nprofiles;
    p->profiles_stored = 0;
    if (!run->proto.nprofiles) {
        note(p->skipped, &p->nskipped, "profiles", "no positions asked ([output] profiles): no u, h, p profile is kept");
        return;
    }
    if (!p->elastic) {
        note(p->skipped, &p->nskipped, "profiles", "rigid spheres do not deform: no profile is kept");
        return;
    }
    if (p->static_mode) {   /* cli/static.c stores none: its points are not drive positions */
        note(p->skipped, &p->nskipped, "profiles", "mode = static: the curve's points fall where continuation puts "
             "them, not on drive positions; no u, h, p profile is kept");
        return;
    }
    for (size_t i = 0; i < run->proto.nprofiles; i++) {
        double x = run->proto.profiles[i];
        size_t hits = 0;
        if (x <= r0->start + 1e-6 * step && (p->stop_at_contact ? x >= r0->end : x >= r0->end - 1e-6 * step) &&
            on_drive(x, r0->start, -1, step))
            hits++;
        /* unloading may go past the start, while the surfaces touch, up to the reach */
        for (size_t t = 0; p->unloading_branches && t < run->proto.nturns; t++)
            if (on_drive(x, run->proto.turns[t], +1, step) && x <= adh_protocol_reach(&run->mat) + 1e-6 * step)
                hits++;
        p->profiles_stored += hits;
        p->profiles_reached += hits > 0;
        if (!hits) {
            char b[64];
            fmt_len(x, b, sizeof b);
            char what[80];   /* "profile at " and b: never cut */
            snprintf(what, sizeof what, "profile at %s", b);
            note(p->skipped, &p->nskipped, what, "no branch steps there (drive positions are start - k d on loading, turn + k d on unloading, up to the model's reach 0.02 R)%s",
                 p->stop_at_contact ? " or it lies past the jump into contact" : "");
        }
    }
}

/* A study's own files: the table, its figure, the shard's records. */
static void plan_study_files(const adh_config *cfg, adh_plan *p)
{
    if (p->time_mode)
        note(p->stored, &p->nstored, "sweep.tsv", "one row per run: the swept values, every summary number (the solid "
             "and the drive, jumps, pull-off and their times and bases, hysteresis, dissipated, time, ...) and its status");
    else
        note(p->stored, &p->nstored, "sweep.tsv", "one row per run: the swept values, every summary number (E, sigma, eps, "
             "jump_in_h0, h_before, h_star, max_load, pulloff_F, jump_out_h0, iterations, seconds, jumped, hysteresis, ...%s) "
             "and its status", p->static_mode && adh_sweep_axis_of(&cfg->sweep, "protocol.spring") ? ", the snap points" : "");
    note(p->stored, &p->nstored, "study.tsv, runs.tsv", "the study's fingerprint and each run's row as it ends: a rerun "
         "skips the runs done, adhere merge joins shards");
    int plot = cfg->output.plot ? adh_sweep_plot_kind(&cfg->sweep) : ADH_SWEEP_PLOT_NONE;
    if (plot == ADH_SWEEP_PLOT_JUMP)
        note(p->stored, &p->nstored, "jump.png", "jump separation vs sigma against eq 24 (Figure 3)");
    if (plot == ADH_SWEEP_PLOT_FORCE)
        note(p->stored, &p->nstored, "force.png", adh_sweep_fig7_panel(cfg)
             ? "every run's force curve with the JKR prediction, and the hysteresis against eps with the static "
               "curve's (its own resolved grid) as its line (Figure 7)"
             : "every run's force curve with the JKR prediction (Figure 7)");
    if (plot == ADH_SWEEP_PLOT_MAP)
        note(p->stored, &p->nstored, "map.png", "a heat map of %s over %s and %s", cfg->sweep.map[0] ? cfg->sweep.map : "pulloff_F",
             cfg->sweep.axis[0].name, cfg->sweep.axis[1].name);
    if (plot == ADH_SWEEP_PLOT_CURVES)
        note(p->stored, &p->nstored, "curves.png", "%s against %s, a curve for each value of the other keys",
             cfg->sweep.map[0] ? cfg->sweep.map : "pulloff_F", cfg->sweep.axis[cfg->sweep.naxes - 1].name);
    if (plot == ADH_SWEEP_PLOT_SPEED)
        note(p->stored, &p->nstored, "speed.png", "pull-off and hysteresis against the speed, log axis; the static "
             "pull-offs at E0 and Einf as lines (two static curves more)");
    if (plot == ADH_SWEEP_PLOT_SNAP)
        note(p->stored, &p->nstored, "snap.png", "the snap-in distance (base and sphere) against the spring, log "
             "axes, with rigid spheres' (eq 22)");
}

/* About how much the study writes: each run's row twice (runs.tsv and
 * sweep.tsv: ~50 numbers, 550 bytes measured, counted 800), and with run-K directories their tables (a
 * force row per step) and figures. */
static void plan_bytes(const adh_config *cfg, adh_plan *p)
{
    p->run_dirs = cfg->sweep.naxes ? adh_sweep_run_dirs(&cfg->sweep) : 1;
    double steps = (double)(p->loading_steps + p->unloading_steps);
    double runs = (double)p->nruns;
    p->bytes = cfg->sweep.naxes ? 2 * ADH_PLAN_ROW_BYTES * runs + 4096 : 0;
    if (p->run_dirs) {
        int figs = 0;
        for (unsigned b = 1; b <= ADH_PLOT_BULGE; b <<= 1)
            figs += cfg->output.plot && (cfg->output.plots & b) ? 1 : 0;
        /* a row of force.tsv is 13 numbers; summary.tsv ~3 kB; a figure ~60 kB */
        p->bytes += steps * (double)p->nruns / (double)(p->drives ? p->drives : 1) * 260.0 + runs * (3072.0 + 60e3 * figs);
    }
}

/* The first runs one by one; the totals over every drive (runs that
 * differ only in their turn share one loading branch) and the distinct
 * grids, each a kernel. */
static void plan_totals(const adh_config *cfg, adh_plan *p)
{
    p->iterations = 0;
    for (size_t i = 0; i < p->nruns; i++) {
        adh_run_spec rc;
        adh_plan_run more;
        adh_config_sweep_run(cfg, i, &rc);
        plan_run(&rc, p, i < ADH_PLAN_MAX_RUNS ? &p->runs[i] : &more);
        p->iterations += i < ADH_PLAN_MAX_RUNS ? p->runs[i].iterations : more.iterations;
    }
    p->drives = adh_sweep_drives(cfg);
    /* the distinct grids, each a kernel (one serves the runs that share it) */
    adh_run_spec *grids = malloc(ADH_PLAN_MAX_KERNELS * sizeof *grids);
    p->kernels = 0;
    for (size_t u = 0; u < p->drives; u++) {
        adh_run_spec rc;
        adh_plan_run r;
        adh_sweep_drive_spec(cfg, u, &rc);
        size_t g = 0, known = !grids ? 0 : p->kernels < ADH_PLAN_MAX_KERNELS ? p->kernels : ADH_PLAN_MAX_KERNELS;
        while (g < known && !adh_config_same_grid(&grids[g], &rc))
            g++;
        if (p->elastic && g == known) {
            if (grids && g < ADH_PLAN_MAX_KERNELS)
                grids[g] = rc;
            p->kernels++;
        }
        plan_run(&rc, p, &r);
        p->loading_steps += r.loading_steps;
        p->unloading_steps += r.unloading_steps;
        /* each unloaded turn of a relaxation held for the dwell (static
         * and physical time have none in iterations) */
        if (p->elastic && !p->static_mode && !p->time_mode && rc.proto.unload)
            p->dwell_iterations += (double)rc.proto.nturns * (double)rc.proto.dwell;
    }
    free(grids);
    p->shared_kernel = p->elastic && p->kernels == 1;
    plan_bytes(cfg, p);
}

/* What the plan skips, and why. */
static void plan_skipped(const adh_config *cfg, const adh_run_spec *s0, adh_plan *p)
{
    if (!p->elastic)
        note(p->skipped, &p->nskipped, "elastic solve", "mode = rigid: the force is eq 22 at each drive position; no kernel, no relaxation");
    if (p->stop_at_contact)
        note(p->skipped, &p->nskipped, "loading past contact", "no turning point (turns = none): loading stops at the jump into contact");
    if (p->elastic && !p->unloading_branches)
        note(p->skipped, &p->nskipped, "unloading", "%s",
             s0->proto.nturns ? "unload = no: the turns end the loading branch only" : "no turning point asked (turns = none)");
    if (p->elastic && s0->proto.nturns > 1 && p->unloading_branches && !p->static_mode)
        note(p->skipped, &p->nskipped, "reloading per turn", "the %zu turns share one loading branch: a state snapshot at each turn starts its unloading",
             s0->proto.nturns);
    if (s0->proto.dwell && p->static_mode)
        note(p->skipped, &p->nskipped, "dwell", "mode = static: the equilibrium curve has no time to hold at a turn; "
             "dwell = %zu iterations is not used", s0->proto.dwell);
    else if (s0->proto.dwell && !p->unloading_branches)
        note(p->skipped, &p->nskipped, "dwell", "no unloading branch to dwell before");
    plan_profiles(s0, p);
    if (p->static_mode && p->elastic)
        note(p->skipped, &p->nskipped, "contact-line speeds", "mode = static: a curve of equilibria has no speed");
    else if (!p->contact_speeds)
        note(p->skipped, &p->nskipped, "contact-line speeds", "contact is not in [output] plots (the contact radius of each row is kept: one pass over the gap per step)");
    if (!cfg->output.plot)
        note(p->skipped, &p->nskipped, "plots", "--no-plot: no PNG is drawn");
    else if (!(cfg->output.plots & (ADH_PLOT_ALL | ADH_PLOT_PRECONTACT | ADH_PLOT_BULGE)))
        note(p->skipped, &p->nskipped, "plots of each run", "plots = none");
    if (cfg->sweep.plot > 0 && !cfg->sweep.naxes)
        note(p->skipped, &p->nskipped, "sweep plot", "no swept parameter in [sweep]");
    if (p->drives < p->nruns && p->static_mode)
        note(p->skipped, &p->nskipped, "a curve per k", "the %zu runs that differ only in their spring share %zu static "
             "curve%s (the spring does not change the curve), from the softest spring's start; each k's snap points are "
             "read off it", p->nruns, p->drives, p->drives == 1 ? "" : "s");
    else if (p->drives < p->nruns)
        note(p->skipped, &p->nskipped, "loading per turn", "the %zu runs that differ only in their turn share %zu loading branches: "
             "each drive unloads from every turn of its runs (up to %d)", p->nruns, p->drives, ADH_MAX_TURNS);
    if (cfg->sweep.naxes && !p->run_dirs)
        note(p->skipped, &p->nskipped, "run-K directories", "%zu runs: each run's row is in sweep.tsv, its own tables and plots "
             "are not written (run_dirs = yes, --run-dirs=yes writes them)", p->nruns);
    if (p->static_mode)
        note(p->skipped, &p->nskipped, "relaxation", "mode = static: the equilibrium curve is followed by continuation, no eps steps");
    if (p->time_path)
        note(p->skipped, &p->nskipped, "time integration", "an elastic material is rate-independent: the path is the "
             "static curve's, its jumps where the base turns on it, t from the base's travel; no integrator, no eps "
             "steps; rows fall on the curve's points, not on the drive step d");
    else if (p->time_mode)
        note(p->skipped, &p->nskipped, "relaxation", "mode = time: the path is integrated in physical time, no eps steps; "
             "rows fall where the integrator's tolerance puts them, not on the drive step d");
}

/* What the run stores, file by file. */
static void plan_stored(const adh_config *cfg, const adh_run_spec *s0, adh_plan *p)
{
    const char *prefix = cfg->sweep.naxes ? "run-K/" : "";
    char what[64];
    snprintf(what, sizeof what, "%sforce.tsv", prefix);
    if (p->time_path)
        note(p->stored, &p->nstored, what, "one row per point of the path: the static curve's points the base passes, "
             "each jump's fold and landing, each turn: t, base, h0, F, delta, hc, a, angle, Newton iterations, F_rigid (eq 22)");
    else if (p->time_mode)
        note(p->stored, &p->nstored, what, "one row per integrator step: t, base, h0, F, delta, hc, a, angle, Newton iterations, F_rigid (eq 22)");
    else if (p->static_mode)
        note(p->stored, &p->nstored, what, "one row per point of the curve: h0, F, delta, hc, a, angle, Newton "
             "iterations, stable (0 on its unstable stretches), F_rigid (eq 22)");
    else
        note(p->stored, &p->nstored, what, "one row per drive step: h0, F, delta, hc, a, angle, iterations, F_rigid (eq 22)");
    if (p->time_mode) {
        snprintf(what, sizeof what, "%sevents.tsv", prefix);
        note(p->stored, &p->nstored, what, "jumps, contact, pull-off, turns located in time: t, base, h0, F, a before and after");
    }
    snprintf(what, sizeof what, "%ssummary.tsv", prefix);
    if (p->time_path)   /* cli/timerun.c's keys besides the run's */
        note(p->stored, &p->nstored, what, "jump_in_h0, pull-off, jump_out_h0, the drive, hysteresis (the jumps' losses), dissipated (0), jump_loss, the times and bases of the jumps and the pull-off, time, the static curve's iterations (time_steps 0)");
    else if (p->time_mode)
        note(p->stored, &p->nstored, what, "sigma, gamma, JKR/DMT, h_star (eq 24's gap), jump_in_h0, pull-off, jump_out_h0, the solid and the drive, hysteresis, dissipated, jump_loss, stored_change, energy_residual (what the balance leaves), the times and bases of the jumps and the pull-off, time, the integrator's steps and iterations");
    else if (p->static_mode)
        note(p->stored, &p->nstored, what, "sigma, gamma, JKR/DMT, h_star (eq 24's gap), jump_in_h0 and jump_out_h0 "
             "(the curve's folds), pull-off (load- and displacement-controlled), folds, points, Newton iterations, "
             "hysteresis (the equilibrium loop)%s", isfinite(s0->time.spring) ? ", the spring's snap points" : "");
    else
        note(p->stored, &p->nstored, what, "sigma, gamma, JKR/DMT, h_star (eq 24's gap), jump_in_h0, pull-off, jump_out_h0, hysteresis, total iterations and seconds");
    /* the static curve has no turns of its own: cli/static.c writes none */
    if (!p->static_mode && (p->unloading_branches || (p->elastic && s0->proto.nturns))) {
        snprintf(what, sizeof what, "%sturns.tsv", prefix);
        note(p->stored, &p->nstored, what, "one row per turning point: maximum load, contact radius, pull-off, jump-out, hysteresis (adhesion vs load)");
    }
    if (p->profiles_stored) {
        snprintf(what, sizeof what, "%sprofiles.tsv", prefix);
        note(p->stored, &p->nstored, what, "u, h, p at %zu of the %zu positions asked (at most %zu profiles over the branches)",
             p->profiles_reached, p->profiles_asked, p->profiles_stored);
    }
    if (cfg->output.plot) {
        static const struct { unsigned bit; const char *file, *what; } figs[] = {
            { ADH_PLOT_FORCE, "force.png", "force vs position, rigid eq 22, JKR and DMT; adhesion vs maximum load with 2+ turns" },
            { ADH_PLOT_PROFILE, "profile.png", "surface profiles at the stored positions" },
            { ADH_PLOT_CONTACT, "contact.png", "contact-line speed and contact radius (contact.tsv)" },
            { ADH_PLOT_PRECONTACT, "precontact.png", "force before contact vs eq 22 at h0 and at h from eq 23 (Figure 1 inset)" },
            { ADH_PLOT_BULGE, "bulge.png", "central bulge before contact vs eq 23 (Figure 2)" },
        };
        for (size_t i = 0; i < sizeof figs / sizeof figs[0]; i++)
            if (cfg->output.plots & figs[i].bit) {
                snprintf(what, sizeof what, "%s%s", prefix, figs[i].file);
                /* the plot module skips a profile figure with no profile in it */
                if (figs[i].bit == ADH_PLOT_PROFILE && !p->profiles_stored)
                    note(p->skipped, &p->nskipped, what, "profile is in plots but no profile is stored");
                else if (figs[i].bit == ADH_PLOT_CONTACT && p->static_mode)
                    note(p->stored, &p->nstored, what, "the contact radius (contact.tsv), its stable stretches solid "
                         "and the unstable ones dashed");
                else
                    note(p->stored, &p->nstored, what, "%s", figs[i].what);
            }
        /* the plot module's adh_forcebase_wanted: a base apart from h0 */
        if ((cfg->output.plots & ADH_PLOT_FORCE) && (p->static_mode || p->time_mode) && isfinite(s0->time.spring)) {
            snprintf(what, sizeof what, "%sforce-base.png", prefix);
            note(p->stored, &p->nstored, what, "force vs the base (piezo) position through the spring, the snaps "
                 "vertical at fixed base");
        }
    }
}

void adh_plan_make(const adh_config *cfg, adh_plan *p)
{
    memset(p, 0, sizeof *p);
    /* what every run shares (the protocol, the mode) is run 0's */
    adh_run_spec run0;
    adh_config_sweep_run(cfg, 0, &run0);
    const adh_run_spec *s0 = &run0;
    p->nruns = adh_config_nruns(cfg);
    p->jobs = adh_plan_jobs(cfg);
    p->elastic = s0->mode != ADH_MODE_RIGID;
    p->static_mode = s0->mode == ADH_MODE_STATIC;
    p->time_mode = s0->mode == ADH_MODE_TIME;
    p->time_path = p->time_mode && !s0->time.sls;
    p->loading_branches = 1;
    p->stop_at_contact = p->elastic && s0->proto.nturns == 0;
    p->snapshots = p->elastic && s0->proto.unload ? s0->proto.nturns : 0;
    p->unloading_branches = p->elastic && s0->proto.unload ? s0->proto.nturns : 0;
    p->shared_kernel = p->elastic;
    p->contact_speeds = cfg->output.plot && (cfg->output.plots & ADH_PLOT_CONTACT);

    plan_totals(cfg, p);
    plan_skipped(cfg, s0, p);
    plan_stored(cfg, s0, p);
    if (cfg->sweep.naxes)
        plan_study_files(cfg, p);
}

static void list_lengths(FILE *f, const double *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        fprintf(f, "%s%g", i ? ", " : "", v[i] * 1e9);
    fputs(" nm", f);
}

/* "sweep: E = 1 GPa, 2 GPa (each an independent run)", or a range's ends
 * and spacing. */
static void print_axis(FILE *f, const adh_sweep_axis *x, int alone)
{
    char a[64], b[64];
    fprintf(f, "sweep: %s =", x->name);
    if (x->spacing != ADH_SWEEP_LIST) {
        adh_format_quantity(x->lo, (adh_quantity)x->quantity, 4, a, sizeof a);
        adh_format_quantity(x->hi, (adh_quantity)x->quantity, 4, b, sizeof b);
        fprintf(f, " %s .. %s, %zu values, %s spacing", a, b, x->n, x->spacing == ADH_SWEEP_LOG ? "logarithmic" : "linear");
    }
    for (size_t j = 0; x->spacing == ADH_SWEEP_LIST && j < x->n; j++) {
        if (isnan(x->num[j]) || x->quantity == ADH_Q_NONE)
            snprintf(a, sizeof a, "%s", x->text[j]);
        else
            adh_format_quantity(x->num[j], (adh_quantity)x->quantity, 4, a, sizeof a);
        fprintf(f, "%s %s", j ? "," : "", a);
    }
    fprintf(f, "%s\n", alone ? " (each an independent run)" : "");
}

static void print_study(FILE *f, const adh_config *cfg, const adh_plan *p)
{
    const adh_sweep *s = &cfg->sweep;
    for (size_t k = 0; k < s->naxes; k++)
        print_axis(f, &s->axis[k], s->naxes == 1);
    if (s->naxes > 1) {
        fprintf(f, "study: %zu runs, every combination of the %zu keys (", p->nruns, s->naxes);
        for (size_t k = 0; k < s->naxes; k++)
            fprintf(f, "%s%zu", k ? " x " : "", s->axis[k].n);
        fprintf(f, "; %s varies slowest), each an independent run\n", s->axis[0].name);
    }
    if (p->drives < p->nruns)
        fprintf(f, "drives: %zu (runs that differ only in their turn share a loading branch)\n", p->drives);
    fprintf(f, "parallel: %d run%s at once%s\n", p->jobs, p->jobs == 1 ? "" : "s",
            p->jobs > 1 ? " (one thread each; BLAS single-threaded)" : "");
    fprintf(f, "run directories: %s\n", p->run_dirs ? "run-1 ... run-N, each run's tables and plots"
            : "none (each run is a row of sweep.tsv)");
}

/* Snapshots, the unloading branches, the dwell and the drive speed: a
 * relaxation's, or time's; the static curve is one curve, the same both
 * ways (cli/static.c unloads nothing, holds no dwell, draws no speed). */
static void print_unloading(FILE *f, const adh_config *cfg, const adh_plan *p)
{
    if (p->static_mode) {
        fprintf(f, "snapshots: 0\nunloading branches: 0%s\n", p->unloading_branches
                ? " (the static curve is the same both ways: its folds are the jumps)" : "");
        return;
    }
    fprintf(f, "snapshots: %zu%s\n", p->snapshots, p->snapshots ? " (the state at each turn, where its unloading starts)" : "");
    fprintf(f, "unloading branches: %zu%s", p->unloading_branches, p->nruns > 1 && p->unloading_branches ? " per run" : "");
    if (p->unloading_branches && p->time_mode)
        fprintf(f, " (each from its turn, after the dwell, until the base is back at the start and the surfaces are apart, up to the model's reach 0.02 R)");
    else if (p->unloading_branches)
        fprintf(f, " (each from its turn until the surfaces jump apart: %zu steps in all back to the start, more if they still touch there, up to the model's reach 0.02 R)", p->runs[0].unloading_steps);
    fputc('\n', f);
    if (p->unloading_branches && !p->time_mode)
        fprintf(f, "dwell: %zu iterations at each turn before unloading\n", cfg->spec.proto.dwell);
    if (p->elastic && !p->time_mode) {
        char a[64];
        adh_format_quantity(cfg->output.drive_speed, ADH_Q_SPEED, 3, a, sizeof a);
        fprintf(f, "drive speed: %s (turns d a / d h0 into contact-line speeds)\n", a);
    }
}

void adh_plan_print(FILE *f, const adh_config *cfg, const adh_plan *p)
{
    char a[64], b[64];
    fprintf(f, "plan: %s\n", cfg->output.title[0] ? cfg->output.title : "(untitled)");
    fprintf(f, "scene: %s\n", cfg->scene[0] ? cfg->scene : "(built-in default)");
    fprintf(f, "runs: %zu\n", p->nruns);
    if (cfg->sweep.naxes)
        print_study(f, cfg, p);
    if (!p->elastic)
        fprintf(f, "mode: rigid (eq 22 only)\n");
    else if (p->static_mode)
        fprintf(f, "mode: static (equilibrium continuation)\n");
    else if (p->time_mode)
        adh_plan_time_print(f, cfg);
    else {
        adh_format_quantity(cfg->spec.relax.eps, ADH_Q_LENGTH, 3, a, sizeof a);
        fprintf(f, "mode: relax (the paper's relaxation, eps = %s%s)\n", a,
                adh_sweep_axis_of(&cfg->sweep, "solver.eps") ? " unless swept" : "");
        adh_mix_rule_describe(&cfg->spec.relax, a, sizeof a);
        if (cfg->spec.relax.rule == ADH_MIX_MOMENTUM)
            fprintf(f, "mixing: %s (heavy ball, ratio from the measured stiffness)\n", a);
        else
            fprintf(f, "mixing: %s (one adaptive ratio, at most %g)\n", a, cfg->spec.relax.mix_max);
    }
    if (p->elastic) {
        double dr = adh_config_spacing(&cfg->spec);
        fmt_len(dr, a, sizeof a);
        fmt_len(dr * (double)cfg->spec.grid.use.nodes, b, sizeof b);
        if (cfg->spec.grid.use.graded) {
            /* the graded grid's own line: its N follows from the spec */
            adh_rings_spec rs = adh_config_rings(&cfg->spec);
            char c[64];
            fmt_len(rs.fine, c, sizeof c);
            fmt_len(rs.rmax, b, sizeof b);
            fprintf(f, "kernel: %s, %s, graded grid of %zu rings: spacing %s to %s, then growing x%g to Rmax %s; %zu built%s\n",
                    adh_kernel_name(cfg->spec.grid.use.kernel), adh_kernel_storage_name(cfg->spec.grid.use.storage), adh_rings_count(&rs), a, c,
                    rs.ratio, b, p->kernels, p->nruns > 1 && p->shared_kernel ? ", shared read-only by every run" : "");
        } else {
            fprintf(f, "kernel: %s, N = %zu, spacing %s, Rmax %s; %zu built%s%s\n", adh_kernel_name(cfg->spec.grid.use.kernel),
                    cfg->spec.grid.use.nodes, a, b, p->kernels, p->nruns > 1 && p->shared_kernel ? ", shared read-only by every run" : "",
                    cfg->spec.grid.use.storage == ADH_STORAGE_HMAT ? ", hierarchical (hmat)" : cfg->spec.grid.use.storage == ADH_STORAGE_H2 ? ", hierarchical (h2)" : "");
        }
        adh_grid_report gr;
        adh_grid_check(&cfg->spec.mat, adh_config_grid_use(&cfg->spec), cfg->spec.grid.use.nodes, dr, &gr);
        fprintf(f, "resolution: %.3g nodes across the contact's edge zone (l/spacing), %s (the limit is %g l)\n",
                gr.edge_nodes, gr.resolved ? "resolved" : "NOT resolved, runs only with --force", gr.limit);
    } else {
        fprintf(f, "kernel: none (no elastic solve)\n");
    }
    const adh_plan_run *r0 = &p->runs[0];
    fmt_len(r0->start, a, sizeof a);
    fmt_len(r0->end, b, sizeof b);
    if (p->time_mode && isfinite(cfg->spec.time.spring))   /* the start is the sphere's, outside the snap-in */
        fprintf(f, "loading branches: %zu%s (the sphere from %s, the base F/k further out, to %s%s)\n",
                p->loading_branches, p->nruns > 1 ? " per run" : "", a,
                p->stop_at_contact ? "the jump into contact, about " : "the base at ", b);
    else if (p->time_mode)   /* the integrator's steps, not the drive's */
        fprintf(f, "loading branches: %zu%s (the base from %s to %s%s)\n", p->loading_branches,
                p->nruns > 1 ? " per run" : "", a, p->stop_at_contact ? "the jump into contact, about " : "", b);
    else if (p->static_mode)   /* the continuation's points, not the drive's */
        fprintf(f, "loading branches: %zu%s (the static curve from %s to %s%s, its points where continuation puts "
                "them)\n", p->loading_branches, p->nruns > 1 ? " per run" : "", a,
                p->stop_at_contact ? "about " : "", b);
    else
        fprintf(f, "loading branches: %zu%s (from %s to %s%s, %s%zu steps)\n", p->loading_branches,
                p->nruns > 1 ? " per run" : "", a, p->stop_at_contact ? "about " : "", b,
                p->stop_at_contact ? "ends at the jump into contact, about " : "", r0->loading_steps);
    if (p->elastic && cfg->spec.proto.nturns) {
        fprintf(f, "turning points: %zu (", cfg->spec.proto.nturns);
        list_lengths(f, cfg->spec.proto.turns, cfg->spec.proto.nturns);
        fprintf(f, ")\n");
    } else {
        fprintf(f, "turning points: none\n");
    }
    print_unloading(f, cfg, p);
    for (size_t i = 0; p->nruns > 1 && i < p->nruns && i < ADH_PLAN_MAX_RUNS; i++) {
        const adh_plan_run *r = &p->runs[i];
        fmt_len(r->start, a, sizeof a);
        fmt_len(r->end, b, sizeof b);
        if (p->time_mode || p->static_mode)   /* no eps, no drive steps: the integrator's, the curve's */
            fprintf(f, "run %zu: E = %s, sigma = %.4g: %s from %s to %s%s\n", i + 1, adh_qtext(r->E, ADH_Q_PRESSURE).s,
                    r->sigma, p->time_mode ? "the base" : "the static curve", a, p->stop_at_contact ? "about " : "", b);
        else
            fprintf(f, "run %zu: E = %s, sigma = %.4g, eps = %s: from %s to %s%s, %zu loading + at most %zu unloading steps to the start\n",
                    i + 1, adh_qtext(r->E, ADH_Q_PRESSURE).s, r->sigma, adh_qtext(r->eps, ADH_Q_LENGTH).s, a,
                    p->stop_at_contact ? "about " : "", b, r->loading_steps, r->unloading_steps);
    }
    if (p->nruns > ADH_PLAN_MAX_RUNS)
        fprintf(f, "runs %d ... %zu: as the sweep lines say (their steps are in the total)\n", ADH_PLAN_MAX_RUNS + 1, p->nruns);
    if (p->time_path)
        fprintf(f, "steps: the static curve's points, no time steps (the path's rows are its points the base passes)\n");
    else if (p->time_mode)
        fprintf(f, "steps: as many as the integrator's tolerance needs (short ones at every fold, jump and turn)\n");
    else if (p->static_mode)
        fprintf(f, "steps: the curve's points, as many as continuation's step control takes (short ones at every fold)\n");
    else
        fprintf(f, "steps: %s%zu loading + at most %zu unloading to the start%s\n", p->stop_at_contact ? "about " : "",
                p->loading_steps, p->unloading_steps,
                p->unloading_branches ? " (more if the surfaces still touch there)" : "");
    if (p->elastic && !p->static_mode && !p->time_mode)   /* every run's: runs[] holds the first few */
        fprintf(f, "iterations: about %.2g (some 17 a step out of contact; in contact %.0f a step at sigma = %.3g "
                   "and eps = 1 pm, more as eps^-0.72 for smaller eps%s)\n", p->iterations,
                contact_iterations(p->runs[0].sigma), p->runs[0].sigma,
                p->unloading_branches && cfg->spec.proto.dwell ? "; the dwell's at each turn" : "");
    for (size_t i = 0; i < p->nstored; i++)
        fprintf(f, "stored: %s: %s\n", p->stored[i].what, p->stored[i].why);
    for (size_t i = 0; i < p->nskipped; i++)
        fprintf(f, "skip: %s: %s\n", p->skipped[i].what, p->skipped[i].why);
}

double adh_plan_time_left(const adh_plan_progress *runs, size_t n, int jobs, double now, double pace)
{
    double cost = 0, secs = 0;
    for (size_t i = 0; i < n; i++)
        if (runs[i].state == 2) {
            cost += runs[i].cost;
            secs += runs[i].seconds;
        }
    if (cost > 0 && secs > 0)
        pace = cost / secs;
    if (!(pace > 0) || jobs < 1 || n == 0)
        return NAN;
    /* when each job comes free: the runs under way end at their expected
     * time; then the waiting ones, in order, on the first job free */
    double *free_at = calloc((size_t)jobs, sizeof *free_at);
    if (!free_at)
        return NAN;
    int busy = 0;
    for (size_t i = 0; i < n; i++)
        if (runs[i].state == 1) {
            double need = runs[i].cost / pace, ran = now - runs[i].started;
            double end = now + fmax(need - ran, 0.1 * need);
            if (busy < jobs)
                free_at[busy++] = end;
        }
    for (int j = busy; j < jobs; j++)
        free_at[j] = now;
    for (size_t i = 0; i < n; i++) {
        if (runs[i].state != 0)
            continue;
        int j0 = 0;
        for (int j = 1; j < jobs; j++)
            if (free_at[j] < free_at[j0])
                j0 = j;
        free_at[j0] += runs[i].cost / pace;
    }
    double end = now;
    for (int j = 0; j < jobs; j++)
        end = fmax(end, free_at[j]);
    free(free_at);
    return end - now;
}
