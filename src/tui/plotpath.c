/* The path on screen for the plot writer: the drive's run (its rows, turns
 * and pull-offs, as --batch's) with a few surface profiles from its undo
 * history; in static mode the curve computed so far. */
#include "tui/plotpath.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "adhere/cycle.h"
#include "adhere/history.h"
#include "adhere/protocol.h"
#include "plot/outdir.h"
#include "plot/setup.h"
#include "plot/plot.h"

static int write_into(const adh_plot_setup *ps, const adh_run *run, const char *dir, const char *sub,
                      int overwrite, char *msg, size_t msglen);

static void add_unique(size_t *idx, size_t *k, size_t cap, size_t i)
{
    for (size_t q = 0; q < *k; q++)
        if (idx[q] == i)
            return;
    if (*k < cap)
        idx[(*k)++] = i;
}

/* Which states to draw as profiles: into contact, each turn, each pull-off,
 * and where the path is now. Returns how many indices went into idx. */
static size_t pick_profiles(const adh_obs *rows, size_t n, const adh_turn_result *turns, size_t nt,
                            size_t *idx, size_t cap)
{
    size_t k = 0;
    for (size_t i = 0; i < n; i++)
        if (rows[i].branch > 0 && rows[i].a > 0) {
            add_unique(idx, &k, cap, i);
            break;
        }
    for (size_t t = 0; t < nt; t++)
        for (size_t i = 0; i < n; i++) {
            if (rows[i].branch > 0 && rows[i].h0 == turns[t].h0)
                add_unique(idx, &k, cap, i);
            if (rows[i].branch < 0 && rows[i].path == turns[t].path && rows[i].h0 == turns[t].pulloff_h0)
                add_unique(idx, &k, cap, i);
        }
    add_unique(idx, &k, cap, n - 1);
    return k;
}

/* Static mode: the whole curve computed so far (the cursor is only where
 * the screen looks), with profiles at the first point in contact, at the
 * pull-off and at the last point: the states the session keeps. */
static size_t curve_profiles(const tui_sim *s, const adh_obs *rows, adh_profile *prof)
{
    size_t np = 0;
    for (int which = 0; which < 3 && np < ADH_MAX_PROFILES; which++) {
        size_t at;
        const adh_state *st = tui_sim_curve_profile(s, which, &at);
        int dup = 0;
        for (size_t k = 0; st && k < np; k++)
            dup |= prof[k].h0 == st->h0;   /* (a pull-off past a start in contact is no row's) */
        if (!st || dup)
            continue;
        prof[np++] = (adh_profile){ .h0 = st->h0, .branch = rows[at].branch, .path = 0, .u = st->u, .h = st->h,
                                    .p = st->p };
    }
    return np;
}

/* Relaxation without profile positions asked: a few from the undo history
 * where the path did something worth seeing. */
static size_t path_profiles(const tui_sim *s, const adh_obs *rows, size_t n, const adh_run *run, adh_profile *prof)
{
    size_t idx[ADH_MAX_PROFILES];
    size_t np = pick_profiles(rows, n, run->turns, run->nturns, idx, ADH_MAX_PROFILES);
    for (size_t k = 0; k < np; k++) {
        const adh_state *st = adh_history_state_at(s->path.hist, idx[k]);
        prof[k] = (adh_profile){ .h0 = st->h0, .branch = rows[idx[k]].branch, .path = rows[idx[k]].path,
                                 .u = st->u, .h = st->h, .p = st->p };
    }
    return np;
}

int tui_plot_path(const tui_sim *s, const char *dir, const char *sub, const volatile sig_atomic_t *cancel, char *msg,
                  size_t msglen)
{
    size_t n;
    int stat = tui_sim_curve_mode(s);   /* static mode's curve, or physical time's path */
    const adh_obs *rows = stat ? tui_sim_curve(s, &n) : tui_sim_rows(s, &n);
    if (n == 0) {
        snprintf(msg, msglen, "nothing to plot yet");
        return -1;
    }
    /* The plots describe what is on screen: the configuration now, its
     * grid the mode's (the profiles' radii), drawn whatever --no-plot said
     * of --batch's. */
    adh_plot_setup ps;
    adh_plot_setup_fill(&s->cfg, &s->cfg.spec, stat ? s->sg : s->g, &ps);
    ps.draw = 1;
    ps.cancel = cancel;
    static adh_run run;   /* large (the turn table); arrays borrowed, never adh_run_free()d */
    static adh_profile prof[ADH_MAX_PROFILES];
    run = stat ? s->curve : *tui_sim_run(s);   /* the drive's record */
    /* the profiles the configuration asked for are the drive's, as --batch
     * draws them; else those the session picks */
    if (stat || !s->cfg.spec.proto.nprofiles) {
        size_t np = stat ? curve_profiles(s, rows, prof) : path_profiles(s, rows, n, &run, prof);
        run.profiles = prof;
        run.nprofiles = run.profiles_cap = np;
    }
    return write_into(&ps, &run, dir, sub, s->cfg.output.overwrite, msg, msglen);
}

static int write_into(const adh_plot_setup *ps, const adh_run *run, const char *dir, const char *sub,
                      int overwrite, char *msg, size_t msglen)
{
    /* the files of an earlier run or an earlier p go first: what is in dir
     * is this path's; sub, a name of adhere's own, is never a link's */
    unsigned flags = overwrite ? ADH_OUTDIR_OVERWRITE : 0;
    adh_outdir *od = sub ? adh_outdir_open_in(dir, sub, flags, msg, msglen) : adh_outdir_open(dir, flags, msg, msglen);
    if (!od)
        return -1;
    msg[0] = '\0';
    int rc = adh_plots_write(ps, run, NULL, od, msg, msglen, NULL, 0);
    adh_outdir_close(od);
    if (rc != 0 && !msg[0])
        snprintf(msg, msglen, "gnuplot failed");
    return rc == 0 ? 0 : -1;
}
