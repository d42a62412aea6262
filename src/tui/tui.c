/* The TUI's loop: reads keys (terminal or replay script), turns them into
 * actions on the session, solves steps in batches so a key can interrupt
 * them, and redraws. Handlers set the status line and return what must be
 * redone (redraw, repaint, resolve, replot), as htop's do; the loop does it,
 * draws when idle and the screen is behind, and, during a long solve, a few
 * times a second. */
#define NCURSES_WIDECHAR 1
#include "tui/tui.h"
#include "plot/say.h"
#include "adhere/clock.h"

#include <curses.h>
#include <errno.h>
#include <langinfo.h>
#include <locale.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "adhere/status.h"
#include "adhere/units.h"
#include "adhere/visco.h"
#include "tui/actions.h"
#include "tui/keysrc.h"
#include "tui/plotpath.h"
#include "tui/screen.h"
#include "tui/sim.h"
#include "plot/outdir.h"
#include "plot/rows.h"
#include "util/ready.h"   /* the test readiness signal, shared with the batch drivers */

static volatile sig_atomic_t got_signal;

/* Exit statuses, as the man page's EXIT STATUS gives them for every mode. */
enum { EXIT_OK = 0, EXIT_BAD_INPUT = 2 };

/* Only a flag here: curses is not async-signal-safe; the loop ends cleanly. */
static void on_signal(int sig)
{
    got_signal = sig;
}

enum { EDIT_NONE = 0, EDIT_PARAM, EDIT_COMMAND };

/* What a key's handler leaves to be redone, htop style: the handler
 * changes state and says what follows from it; the loop does it, once. */
enum {
    TODO_NONE = 0,
    TODO_REDRAW = 1,    /* the screen shows something new */
    TODO_REPAINT = 2,   /* repaint every cell (resize, ^L), then redraw */
    TODO_RESOLVE = 4,   /* a solve was asked for: the loop starts the step */
    TODO_REPLOT = 8     /* write the plots through gnuplot */
};

typedef struct tui {
    tui_sim sim;        /* and in it the session's one configuration */
    tui_keysrc keys;
    tui_view view;
    int headless;
    SCREEN *scr;
    FILE *fout, *fin;

    char status[768];
    int status_error;
    int editing;
    char text[1024];    /* a path of a deep directory fits */
    size_t textlen;
    int text_full;      /* a key was typed past text's end: the line is refused */
    char prompt[1200];
    long count;

    int pending;        /* steps still to start after the current one */
    int pending_dir;
    int pending_key;    /* the key that asked for them: held down, it repeats */
    int run_dir;        /* a continuous run (r) under way: 1, else 0 */
    int waiting;        /* replay: :wait until the run ends */
    size_t folds_seen;  /* static mode: folds already told on the status line */
    int help;
    int help_lines;
    int quit;
    int exit_code;
    char fatal[1024];   /* printed on stderr once the terminal is restored */
    double last_draw;
    int dirty;          /* the screen is behind the state: draw when idle */
} tui;

static void say(tui *t, int error, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static void say(tui *t, int error, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(t->status, sizeof t->status, fmt, ap);
    va_end(ap);
    t->status_error = error;
    t->dirty = 1;
}

static void fmtq(double v, adh_quantity q, char *buf, size_t len)
{
    adh_format_quantity(v, q, 4, buf, len);
}

/* The screen steps a curve: the static one, or physical time's path
 * (points computed once, walked back and forth). */
static int is_curve(const tui *t)
{
    return tui_sim_curve_mode(&t->sim);
}

static int is_timed(const tui *t)
{
    return tui_sim_mode(&t->sim) == ADH_MODE_TIME;
}

static const adh_config *config(const tui *t)
{
    return &t->sim.cfg;
}

/* How many turning points the protocol has. */
static size_t nturns(const tui *t)
{
    size_t n;
    tui_sim_turns(&t->sim, &n);
    return n;
}

static const char *activity(const tui *t)
{
    if (is_curve(t)) {
        if (t->run_dir)
            return is_timed(t) ? "running in time" : "following the curve";
        if (t->sim.busy)
            return t->sim.walk ? "walking the curve" : t->pending ? "stepping" : "solving a point";
        return "idle";
    }
    static char buf[128];   /* which turn of several the run is on */
    if (t->run_dir) {
        size_t k;
        int unloading = tui_sim_next(&t->sim, &k) < 0;
        if (nturns(t) > 1) {
            snprintf(buf, sizeof buf, "%s, turn %zu of %zu", unloading ? "running to the jump-out" : "running to the turn",
                     t->sim.tcur + 1, nturns(t));
            return buf;
        }
        return unloading ? "running to the jump-out" : "running to the turn";
    }
    if (t->sim.busy)
        return t->pending ? "stepping" : "solving a step";
    return "idle";
}

static void select_move(tui *t, long n);

static void draw(tui *t)
{
    tui_view *v = &t->view;
    if (!tui_sim_param_shown(&t->sim, (tui_param)v->sel))
        select_move(t, 1);   /* a field the mode does not show (an edit changed the mode) */
    v->status = t->status;
    v->status_error = t->status_error;
    v->count = t->count;
    v->activity = activity(t);
    v->prompt = NULL;
    if (t->editing) {
        if (t->editing == EDIT_PARAM) {
            double f;
            const char *unit = tui_sim_param_unit(&t->sim, (tui_param)v->sel, v->utf8, &f);
            if (unit[0])
                snprintf(t->prompt, sizeof t->prompt, " %s = %s_   (in %s, or with a unit: 2GPa 0.4nm; Enter sets, Esc cancels)",
                         tui_params[v->sel].name, t->text, unit);
            else
                snprintf(t->prompt, sizeof t->prompt, " %s = %s_   (Enter sets, Esc cancels)", tui_params[v->sel].name,
                         t->text);
        }
        else if (t->textlen + 2 > (size_t)COLS && COLS > 8) {   /* its end in view, where the typing is */
            const char *tail = t->text + t->textlen - (size_t)(COLS - 6);
            while (((unsigned char)*tail & 0xc0) == 0x80)   /* from a character's first byte */
                tail++;
            snprintf(t->prompt, sizeof t->prompt, ":...%s_", tail);
        }
        else
            snprintf(t->prompt, sizeof t->prompt, ":%s_", t->text);
        v->prompt = t->prompt;
    }
    if (t->help)
        t->help_lines = tui_draw_help(v);
    else
        tui_draw(&t->sim, v);
    refresh();
    t->last_draw = adh_clock_seconds();
    t->dirty = 0;
}

static void stop_all(tui *t)
{
    t->pending = 0;
    t->run_dir = 0;
    t->waiting = 0;
}

/* dir: +1 or -1 a step by hand (static mode: the next or previous
 * point), 0 the protocol's next step (r). */
static void start_step(tui *t, int dir)
{
    char why[512];
    if (tui_sim_will_build(&t->sim) && !t->headless) {
        /* The kernel is built on the first step; at large N that takes a
         * moment, so say so before the screen goes quiet. */
        say(t, 0, "building the kernel for N = %zu nodes...", tui_sim_grid(&t->sim)->nodes);
        draw(t);
    }
    if (tui_sim_begin(&t->sim, dir, why, sizeof why) != 0) {
        stop_all(t);
        say(t, 1, "%s", why);
    }
}

/* Physical time: the point just reached, its time, base and speed,
 * naming a jump when the last step crossed one. */
static void describe_time(tui *t)
{
    const tui_sim *s = &t->sim;
    const adh_obs *o = tui_sim_row(s);
    char h0[64], F[64], a[64], tt[64], v[64], b[64];
    fmtq(o->base, ADH_Q_LENGTH, b, sizeof b);
    fmtq(o->h0, ADH_Q_LENGTH, h0, sizeof h0);
    fmtq(o->F, ADH_Q_FORCE, F, sizeof F);
    fmtq(o->a, ADH_Q_LENGTH, a, sizeof a);
    fmtq(o->t, ADH_Q_TIME, tt, sizeof tt);
    const adh_time_settings *ts = &config(t)->spec.time;
    fmtq(o->branch > 0 ? ts->speed_in : ts->speed_out, ADH_Q_SPEED, v, sizeof v);
    const adh_obs *prev = s->ccur > 0 ? &tui_sim_curve(s, &(size_t){ 0 })[s->ccur - 1] : NULL;
    if (!s->walked && prev && (prev->a > 0) != (o->a > 0))
        say(t, 0, "t = %s: jumped %s at h0 = %s (base at %s): F %s%s%s", tt, o->a > 0 ? "into contact" : "out of contact",
            h0, b, F, o->a > 0 ? ", contact radius " : "", o->a > 0 ? a : "");
    else
        say(t, 0, "t = %s%s: h0 %s, F %s, %s%s (base %s at %s)", tt, s->walked ? " (kept, not solved again)" : "",
            h0, F, o->a > 0 ? "a " : "not in contact", o->a > 0 ? a : "", o->branch > 0 ? "approaching" : "retracting", v);
}

/* Static mode: the point just reached, naming a fold when one was passed. */
static void describe_point(tui *t)
{
    if (is_timed(t)) {
        describe_time(t);
        return;
    }
    const tui_sim *s = &t->sim;
    const adh_obs *o = tui_sim_row(s);
    char h0[64], F[64], a[64];
    fmtq(o->h0, ADH_Q_LENGTH, h0, sizeof h0);
    fmtq(o->F, ADH_Q_FORCE, F, sizeof F);
    fmtq(o->a, ADH_Q_LENGTH, a, sizeof a);
    const char *stab = o->stable ? "stable" : "unstable (det J < 0)";
    adh_static_fold last;
    size_t kept = tui_sim_curve_fold(s, &last);
    if (t->folds_seen > s->sres.folds)
        t->folds_seen = s->sres.folds;
    if (!s->walked && s->sres.folds > t->folds_seen && kept == s->sres.folds) {
        char fh[64], fF[64];
        fmtq(last.h0, ADH_Q_LENGTH, fh, sizeof fh);
        fmtq(last.F, ADH_Q_FORCE, fF, sizeof fF);
        say(t, 0, "fold %zu at h0 = %s (F %s): %s; now %s", s->sres.folds, fh, fF,
            last.kind < 0 ? "approaching, the surfaces jump in here" : "retracting, they jump out here",
            o->stable ? "stable" : "unstable");
    } else {
        say(t, 0, "point %zu%s%s: h0 %s, F %s, %s%s, %s", s->ccur + 1, s->walked ? " (kept, not solved again)" : "",
            "", h0, F, o->a > 0 ? "a " : "not in contact", o->a > 0 ? a : "", stab);
    }
    t->folds_seen = s->sres.folds;
}

/* The pull-off of the path's unloading branch, its force minimum, "-850 nN
 * (3.4 πγR) at 3.75 nm" (where, when `where`: the panel says it too, and a
 * status line that goes on to the next turn has no room for it): the
 * number the user came for, not the force after the jump, and not where
 * the surfaces jumped apart (the jump-out). */
typedef struct { char s[160]; } text96;
static text96 pulloff_text(const tui *t, int where)
{
    text96 r;
    adh_cycle c;
    char F[64], h0[64];
    tui_sim_cycle(&t->sim, &c);
    fmtq(c.pulloff_F, ADH_Q_FORCE, F, sizeof F);
    fmtq(c.pulloff_h0, ADH_Q_LENGTH, h0, sizeof h0);
    snprintf(r.s, sizeof r.s, "%s (%.3g %s)%s%s", F, c.pulloff_F / (-M_PI * t->sim.der.gamma * config(t)->spec.mat.R),
             t->view.utf8 ? "\xcf\x80\xce\xb3R" : "pi gamma R", where ? " at " : "", where ? h0 : "");
    return r;
}

/* Plain words about the step just done, naming jumps in and out. */
static void describe_step(tui *t)
{
    if (is_curve(t)) {
        describe_point(t);
        return;
    }
    size_t n;
    const adh_obs *rows = tui_sim_rows(&t->sim, &n);
    const adh_obs *o = &rows[n - 1];
    char h0[64], F[64], a[64];
    fmtq(o->h0, ADH_Q_LENGTH, h0, sizeof h0);
    fmtq(o->F, ADH_Q_FORCE, F, sizeof F);
    fmtq(o->a, ADH_Q_LENGTH, a, sizeof a);
    int was = n >= 2 && rows[n - 2].a > 0;
    if (o->a > 0 && !was && n >= 2)
        say(t, 0, "jumped into contact at h0 = %s: contact radius %s, force %s", h0, a, F);
    else if (o->a == 0 && was)
        say(t, 0, "jumped out at h0 = %s: pull-off %s; F after the jump %s", h0,
            pulloff_text(t, 1).s, F);
    else
        say(t, 0, "%s to h0 = %s: force %s%s%s", o->branch > 0 ? "approached" : "retracted", h0, F,
            o->a > 0 ? ", contact radius " : ", not in contact", o->a > 0 ? a : "");
}

/* The jumps a complete static curve made, in words: "jump-in, jump-out
 * and 3 lattice folds", "jump-out", "no jumps" (a stiff sphere's curve
 * has no fold at all; it said "jump-in, jump-out and 0 lattice folds"). */
static void curve_jumps(const adh_static_result *r, char *buf, size_t len)
{
    size_t physical = !isnan(r->jump_in_h0) + !isnan(r->jump_out_h0);
    size_t lattice = r->folds > physical ? r->folds - physical : 0;
    const char *part[3];
    char lat[48];
    size_t n = 0;
    if (!isnan(r->jump_in_h0))
        part[n++] = "jump-in";
    if (!isnan(r->jump_out_h0))
        part[n++] = "jump-out";
    if (lattice) {
        snprintf(lat, sizeof lat, "%zu lattice fold%s", lattice, lattice == 1 ? "" : "s");
        part[n++] = lat;
    }
    if (n == 0)
        snprintf(buf, len, "no jumps");
    else if (n == 1)
        snprintf(buf, len, "%s", part[0]);
    else if (n == 2)
        snprintf(buf, len, "%s and %s", part[0], part[1]);
    else
        snprintf(buf, len, "%s, %s and %s", part[0], part[1], part[2]);
}

/* Whether a continuous run has reached its goal after the step just done. */
static int run_done(tui *t)
{
    const adh_obs *o = tui_sim_row(&t->sim);
    char h0[64], F[64];
    if (is_curve(t) && is_timed(t)) {
        const adh_visco_result *r = &t->sim.vres;
        if (t->sim.cstatus != ADH_SUCCESS || tui_sim_redoable(&t->sim))
            return 0;
        char pl[64], tt[64], hy[64];
        fmtq(r->pulloff_F, ADH_Q_FORCE, pl, sizeof pl);
        if (isnan(r->pulloff_F))   /* (a start in contact whose unloading could not go on past it) */
            snprintf(pl, sizeof pl, "not reached");
        fmtq(r->time, ADH_Q_TIME, tt, sizeof tt);
        fmtq(r->hysteresis, ADH_Q_WORK, hy, sizeof hy);
        /* an elastic sphere walks its static curve: its rows are the
         * curve's points, no integrator steps */
        /* marked as --batch marks the run: its numbers are not promised */
        char loose[160] = "", tol[32];
        if (config(t)->spec.time.sls && adh_visco_tol_loose(config(t)->spec.time.tol))
            snprintf(loose, sizeof loose, "; unconverged: the time tolerance %s is looser than %g "
                     "(:set solver.time_tol)", adh_format_shortest(config(t)->spec.time.tol, tol, sizeof tol),
                     ADH_VISCO_TOL_DEFAULT);
        say(t, 0, "cycle complete after %s (%zu %s, %zu jumps): pull-off %s, hysteresis %s%s", tt,
            t->sim.curve.nrows, config(t)->spec.time.sls ? "steps" : "points", r->jumps, pl, hy, loose);
        return 1;
    }
    if (is_curve(t)) {
        const adh_static_result *r = &t->sim.sres;
        if (t->sim.cstatus != ADH_SUCCESS || tui_sim_redoable(&t->sim))
            return 0;
        char pl[64], pd[64], jumps[96], tail[128] = "";
        fmtq(o->h0, ADH_Q_LENGTH, h0, sizeof h0);
        fmtq(r->pulloff_F, ADH_Q_FORCE, pl, sizeof pl);
        curve_jumps(r, jumps, sizeof jumps);
        if (!isnan(r->jump_out_h0)) {
            fmtq(r->pulloff_F_disp, ADH_Q_FORCE, pd, sizeof pd);
            snprintf(tail, sizeof tail, ", F at jump-out %s", pd);
        }
        say(t, 0, "curve complete at h0 = %s (%zu points; %s): %s%s%s", h0, t->sim.curve.nrows, jumps,
            isnan(r->pulloff_F) ? "no pull-off (the curve past the start was not followed)" : "pull-off ",
            isnan(r->pulloff_F) ? "" : pl, tail);
        return 1;
    }
    /* the drive says what the row meant; the run pauses where a branch
     * reaches its goal */
    unsigned ev = tui_sim_events(&t->sim);
    const adh_run *run = tui_sim_run(&t->sim);
    size_t nt = nturns(t);
    fmtq(o->h0, ADH_Q_LENGTH, h0, sizeof h0);
    fmtq(o->F, ADH_Q_FORCE, F, sizeof F);
    /* turns are named by the protocol's numbers ("turn 3 of 8"); a turn
     * made by hand by its position */
    size_t nk;
    int next = tui_sim_next(&t->sim, &nk);
    char this_turn[96], next_turn[128];
    if (next < 0)
        tui_sim_turn_name(&t->sim, nk - 1, next_turn, sizeof next_turn);
    else if (next > 0 && nk > 0)
        snprintf(next_turn, sizeof next_turn, "turn %zu of %zu", nk, nt);
    else
        snprintf(next_turn, sizeof next_turn, "the next turn");
    if (ev & ADH_DRIVE_TURN) {
        tui_sim_turn_name(&t->sim, run->nturns - 1, this_turn, sizeof this_turn);
        if (next == 0)   /* unload = no: the protocol loads only */
            say(t, 0, "at %s h0 = %s (force %s): the protocol ends here (protocol.unload = no)",
                nt <= 1 ? "the turning point" : this_turn, h0, F);
        else if (nt <= 1 && next < 0)
            say(t, 0, "at the turning point h0 = %s (force %s): press r to unload until the jump-out", h0, F);
        else if (next > 0)
            say(t, 0, "at %s, h0 = %s (force %s): press r to load on to %s", this_turn, h0, F, next_turn);
        else
            say(t, 0, "at %s, h0 = %s (force %s): press r to unload %s until the jump-out (from its state on the way in)",
                this_turn, h0, F, next_turn);
        return 1;
    }
    if (!(ev & ADH_DRIVE_END))
        return 0;
    if (o->branch > 0) {
        say(t, 0, "in contact at h0 = %s (no turning point set: :set turn VALUE)", h0);
        return 1;
    }
    int k = o->path;
    tui_sim_turn_name(&t->sim, (size_t)(k - 1), this_turn, sizeof this_turn);
    char then[192] = "";
    if (next < 0)
        snprintf(then, sizeof then, "; r unloads %s", next_turn);
    else if (next > 0)
        snprintf(then, sizeof then, "; r loads on to %s", next_turn);
    if (ev & ADH_DRIVE_PULLOFF) {
        if (next != 0)
            say(t, 0, "jumped out at h0 = %s (%s): pull-off %s%s", h0, this_turn, pulloff_text(t, 0).s, then);
        else if (nt > 1)
            say(t, 0, "jumped out at h0 = %s (%s): pull-off %s; F after the jump %s", h0, this_turn,
                pulloff_text(t, 0).s, F);
        else
            say(t, 0, "jumped out at h0 = %s: pull-off %s; F after the jump %s", h0, pulloff_text(t, 1).s, F);
        return 1;
    }
    int touched = 0;
    for (size_t i = 0; i < run->nrows; i++)
        touched |= run->rows[i].branch < 0 && run->rows[i].path == k && run->rows[i].a > 0;
    /* unloading goes past the start while the surfaces touch, so a branch
     * still in contact ended at the reach */
    if (touched)
        say(t, 0, "unloaded to h0 = %s, the model's reach (0.02 R), still in contact: no jump-out%s", h0, then);
    else
        say(t, 0, "back at the start h0 = %s without having been in contact%s", h0, then);
    return 1;
}

static void after_step(tui *t, tui_work rc, const char *why)
{
    if (rc == TUI_WORK_COMPLETE) {
        char done[256];
        stop_all(t);
        tui_sim_why_done(&t->sim, done, sizeof done);
        say(t, 0, "%s", done);
        return;
    }
    if (rc == TUI_WORK_FAILED) {
        stop_all(t);
        say(t, 1, "%s", why);
        return;
    }
    describe_step(t);
    if (t->pending > 0) {
        t->pending--;
        start_step(t, t->pending_dir);
    } else if (t->run_dir && run_done(t)) {
        stop_all(t);
    }
    /* a run that goes on starts its next step from the loop, after a look
     * at the keys (any key pauses) */
}

static int resize_to(tui *t, int cols, int rows, char *why, size_t whylen)
{
    if (!t->headless) {
        snprintf(why, whylen, "resize the terminal window instead: :resize is for replay scripts");
        return -1;
    }
    resizeterm(rows, cols);
    return 0;
}

static void write_plots(tui *t)
{
    size_t n;
    tui_sim_rows(&t->sim, &n);
    if (n == 0) {
        say(t, 1, "nothing to plot yet: step first (f, or r to run)");
        return;
    }
    /* the static curve's plots (and physical time's) beside the
     * relaxation's, not over them */
    const char *base = config(t)->output.dir[0] ? config(t)->output.dir : NULL;
    const char *kind = is_timed(t) ? "time" : is_curve(t) ? "static" : NULL;
    /* ./adhere-plots is a name adhere gives, as static/ and time/ are:
     * never entered through a link */
    char own[32];
    snprintf(own, sizeof own, "adhere-plots%s%s", kind ? "/" : "", kind ? kind : "");
    const char *sub = base ? kind : own;
    char dir[PATH_MAX + 48];
    snprintf(dir, sizeof dir, "%s%s%s", base ? base : "", base && sub ? "/" : "", sub ? sub : "");
    if (!t->headless) {
        say(t, 0, "writing plots to %s/ through gnuplot...", dir);
        draw(t);
    }
    char msg[600];
    if (tui_plot_path(&t->sim, base, sub, &got_signal, msg, sizeof msg) == 0)
        say(t, 0, "plots: %s", msg);   /* the writer names the files and the directory */
    else
        say(t, 1, "plots not written to %s/: %s", dir, msg);
}

/* val, a key's value as the configuration writes it (every number at
 * %.17g), with each element of it that is a number in its shortest exact
 * digits: ":set solver.time_tol 5.0000001e-5" said 5.0000000999999998e-05. */
static void shortest_numbers(char *val, size_t len)
{
    char in[256], one[40];
    snprintf(in, sizeof in, "%s", val);
    size_t o = 0;
    for (const char *p = in;;) {
        size_t n = strcspn(p, ",");
        char *end;
        double v = strtod(p, &end);
        if (end == p + n && n > 0 && !strchr(" \t", *p)) {
            adh_format_shortest(v, one, sizeof one);
            o += (size_t)snprintf(val + o, o < len ? len - o : 0, "%s", one);
        } else {
            o += (size_t)snprintf(val + o, o < len ? len - o : 0, "%.*s", (int)n, p);
        }
        if (!p[n])
            break;
        o += (size_t)snprintf(val + o, o < len ? len - o : 0, ",");
        p += n + 1;
    }
}

/* A key as the screen names it, and its value: a field's name and the text
 * the panel shows ("R", "20 µm"), else the key and its value (a quantity
 * with its unit, a number in its shortest exact digits). Returns the name. */
static const char *key_value(const tui *t, const char *key, char *val, size_t len)
{
    int p = tui_sim_field(key);
    if (p == P_TURN) {   /* a list is said whole */
        tui_sim_turns_text(&t->sim, val, len);
        return tui_params[p].name;
    }
    if (p >= 0) {
        tui_sim_param_text(&t->sim, (tui_param)p, t->view.utf8, val, len);
        return tui_params[p].name;
    }
    const adh_config_key *k = adh_config_key_find(key);
    double v;
    adh_config_get(config(t), key, val, len);
    if (k && k->q != ADH_Q_NONE && adh_parse_quantity(val, ADH_Q_NONE, &v, NULL, 0) == 0)
        fmtq(v, k->q, val, len);
    else
        shortest_numbers(val, len);
    return key;
}

/* The status line after an edit of key: what it is now, and what follows
 * (sigma and gamma at once; a new path, or the path kept for a turn). */
static void key_changed(tui *t, const char *key)
{
    char val[256];
    const char *name = key_value(t, key, val, sizeof val);
    int u = t->view.utf8, turn = !strcmp(key, "protocol.turns"), eps = !strcmp(key, "solver.eps");
    size_t ncurve;
    tui_sim_curve(&t->sim, &ncurve);
    if (is_curve(t) && turn)
        say(t, 0, "turn = %s: the curve now ends there%s", val, ncurve ? "" : "; f or r follows it from the start");
    else if (turn && t->sim.edit_kept_path)
        say(t, 0, "turn = %s: r now loads to there (the path is kept)", val);
    else if (turn)
        say(t, 0, "turn = %s: the grid follows it (N = %zu, as --batch would choose); a new path starts from the "
            "start", val, tui_sim_grid(&t->sim)->nodes);
    else if (is_curve(t) && (ncurve || eps))
        say(t, 0, "%s = %s: the equilibrium curve does not depend on it%s (the relaxation path restarts)",
            name, val, ncurve ? " and is kept" : "");
    else if (is_curve(t))
        say(t, 0, "%s = %s: %s = %.4g, %s = %.4g mJ/m%s; the curve starts again from the start (f, or r to "
            "its end)", name, val, u ? "\xcf\x83" : "sigma", t->sim.der.sigma,
            u ? "\xce\xb3" : "gamma", t->sim.der.gamma * 1e3, u ? "\xc2\xb2" : "^2");
    else
        say(t, 0, "%s = %s: %s = %.4g, %s = %.4g mJ/m%s; a new path starts from the start", name,
            val, u ? "\xcf\x83" : "sigma", t->sim.der.sigma, u ? "\xce\xb3" : "gamma", t->sim.der.gamma * 1e3,
            u ? "\xc2\xb2" : "^2");
}

typedef struct rows_out {
    const adh_obs *rows;
    size_t n;
    int timed;   /* physical time: t and base first, as --batch's */
} rows_out;

static int rows_table(FILE *f, const void *ctx)
{
    const rows_out *r = ctx;
    (r->timed ? adh_rows_header_timed : adh_rows_header)(f);
    for (size_t i = 0; i < r->n; i++)
        (r->timed ? adh_rows_write_timed : adh_rows_write)(f, &r->rows[i]);
    return 0;
}

/* The path's rows (static mode: the curve's points so far) as force.tsv's
 * columns, through a new temporary renamed into place (a link at path is
 * replaced, never written through): a script can hold them against
 * --batch's. */
static int write_rows(tui *t, const char *path, char *why, size_t whylen)
{
    rows_out r;
    r.rows = is_curve(t) ? tui_sim_curve(&t->sim, &r.n) : tui_sim_rows(&t->sim, &r.n);
    r.timed = is_timed(t);
    int e = adh_outfile_write(path, rows_table, &r);
    char reason[1024];
    if (e)
        snprintf(why, whylen, "cannot write the rows to %s: %s", path, adh_outfile_reason(path, e, reason, sizeof reason));
    return e ? -1 : 0;
}

/* A file :dump or :rows names that is one the session reads (its scene,
 * its replay script: adh_outdir_inputs): the screen was put over the
 * script, the rows over the scene. -1 with why; 0 for any other. */
static int reads_it(const char *path, const char *what, char *why, size_t whylen)
{
    const char *input, *option;
    if (!adh_outdir_input_named(path, &input, &option))
        return 0;
    snprintf(why, whylen, "not writing the %s to %s: it is %s this session reads; name another file", what, path,
             input);
    return -1;
}

/* A :set / :dump / :rows / :wait / :resize, from a script or the ':' prompt.
 * 0, or -1 with a sentence in why. */
static int run_command(tui *t, const tui_replay_item *it, char *why, size_t whylen)
{
    switch (it->kind) {
    case TUI_REPLAY_SET: {
        /* a field by its name, or any key of the run by its own */
        int p = tui_sim_param_lookup(it->name);
        const char *key = p >= 0 ? tui_params[p].key : it->name;
        if (p < 0 && !adh_config_key_find(key)) {
            snprintf(why, whylen, "unknown parameter '%s' for set: a key of the run as a scene writes it, "
                     "section.name (protocol.dwell, grid.fine_band), or a field; the names are E A z0 R eps d N "
                     "spacing turn", it->name);
            return -1;
        }
        if (strcmp(key, "protocol.turns") != 0) {   /* a new turn leaves a run going */
            tui_sim_cancel(&t->sim);
            stop_all(t);
        }
        if ((p >= 0 ? tui_sim_set(&t->sim, (tui_param)p, it->value, why, whylen)
                    : tui_sim_set_key(&t->sim, key, it->value, why, whylen)) != 0)
            return -1;
        key_changed(t, key);
        return 0;
    }
    case TUI_REPLAY_DUMP:
        if (reads_it(it->value, "screen", why, whylen) != 0)
            return -1;
        draw(t);
        return tui_dump_screen(it->value, why, whylen);
    case TUI_REPLAY_ROWS:
        if (reads_it(it->value, "rows", why, whylen) != 0)
            return -1;
        return write_rows(t, it->value, why, whylen);
    case TUI_REPLAY_WAIT:
        t->waiting = t->run_dir != 0;
        return 0;
    case TUI_REPLAY_RESIZE:
        return resize_to(t, it->cols, it->rows, why, whylen);
    default:
        snprintf(why, whylen, "not a command: the commands are set NAME VALUE, dump FILE, rows FILE");
        return -1;
    }
}

static int edit_key(tui *t, int key)
{
    char why[512];
    if (key == 27) {
        t->editing = EDIT_NONE;
        say(t, 0, "edit cancelled; nothing changed");
        return TODO_REDRAW;
    }
    if (key == KEY_BACKSPACE || key == KEY_DC) {
        /* a whole character: its UTF-8 continuation bytes, then its first */
        while (t->textlen && ((unsigned char)t->text[t->textlen - 1] & 0xc0) == 0x80)
            t->textlen--;
        if (t->textlen)
            t->textlen--;
        t->text[t->textlen] = '\0';
        return TODO_REDRAW;
    }
    if (key != '\n') {
        /* printable ASCII, and the bytes of a UTF-8 character as the
         * terminal sends them: the micro sign the panel shows beside R was
         * dropped, so 5, micro sign, m set R = 5 m, and a file name lost
         * its accented letters */
        int typed = (key >= ' ' && key < 127) || (key >= 0x80 && key <= 0xff);
        if (typed && t->textlen + 1 < sizeof t->text) {
            t->text[t->textlen++] = (char)key;
            t->text[t->textlen] = '\0';
        } else if (typed && !t->text_full) {
            t->text_full = 1;
            say(t, 1, "the line holds %zu characters: what is typed past them is not taken, and Enter will refuse "
                "the line; Esc cancels", sizeof t->text - 1);
        }
        return TODO_REDRAW;
    }
    int mode = t->editing;
    t->editing = EDIT_NONE;
    /* a line cut short would set another value, or write another file
     * (a path's prefix, perhaps one of the user's): never run */
    if (t->text_full) {
        say(t, 1, "not %s: the line was longer than %zu characters and its end was not taken; nothing changed",
            mode == EDIT_PARAM ? "set" : "run", sizeof t->text - 1);
        return TODO_REDRAW;
    }
    if (mode == EDIT_PARAM) {
        tui_param p = (tui_param)t->view.sel;
        if (p != P_TURN) {
            tui_sim_cancel(&t->sim);
            stop_all(t);
        }
        if (tui_sim_set(&t->sim, p, t->text, why, sizeof why) != 0)
            say(t, 1, "%s; nothing changed", why);
        else
            key_changed(t, tui_params[p].key);
        return TODO_REDRAW;
    }
    /* The ':' prompt takes what a script's command line takes. */
    char line[sizeof t->text + 2];
    snprintf(line, sizeof line, ":%s", t->text);
    tui_replay_script sc;
    int errline;
    if (t->textlen == 0)
        return TODO_REDRAW;
    if (tui_replay_parse(line, strlen(line), &sc, &errline, why, sizeof why) != 0) {
        say(t, 1, "%s", why);
        return TODO_REDRAW;
    }
    int bad = 0;
    for (size_t i = 0; i < sc.n && !bad; i++) {
        if (sc.items[i].kind == TUI_REPLAY_WAIT)
            continue;
        bad = run_command(t, &sc.items[i], why, sizeof why) != 0;
    }
    if (bad)
        say(t, 1, "%s", why);
    else if (sc.n && sc.items[0].kind == TUI_REPLAY_DUMP)
        say(t, 0, "screen written to %s", sc.items[0].value);
    else if (sc.n && sc.items[0].kind == TUI_REPLAY_ROWS)
        say(t, 0, "rows written to %s", sc.items[0].value);
    tui_replay_free(&sc);
    return TODO_REDRAW;
}

static void move_history(tui *t, int redo, long n)
{
    long done = 0;
    stop_all(t);
    const char *edit = NULL;
    while (done < n && (redo ? tui_sim_redo(&t->sim) : tui_sim_undo(&t->sim)) == ADH_SUCCESS) {
        done++;
        if (t->sim.edit_moved)
            edit = t->sim.edit_moved;
    }
    const adh_obs *o = tui_sim_row(&t->sim);
    char h0[64];
    if (edit) {
        /* an edit taken back or done again: say what the parameter is now
         * and what came back with it */
        char val[256];
        size_t np;
        tui_sim_rows(&t->sim, &np);
        const char *name = key_value(t, edit, val, sizeof val);
        if (is_curve(t))
            say(t, 0, "%s the edit: %s = %s again (the relaxation path came back with it; f solves the curve)",
                redo ? "redid" : "undid", name, val);
        else
            say(t, 0, "%s the edit: %s = %s again, with its path (%zu state%s)", redo ? "redid" : "undid",
                name, val, np, np == 1 ? "" : "s");
        return;
    }
    if (!done) {
        if (is_curve(t))
            say(t, 1, "nothing to %s", redo ? "redo: this is the last point computed (f computes more)"
                                         : o ? "undo: this is the first point of the curve" : "undo: no point yet");
        else
            say(t, 1, "nothing to %s", redo ? "redo" : o ? "undo: this is the first state of the path"
                                                         : "undo: no step taken yet");
        return;
    }
    fmtq(o->h0, ADH_Q_LENGTH, h0, sizeof h0);
    if (is_curve(t))
        say(t, 0, "%s %ld point%s: at point %zu of %zu of the curve, h0 = %s (nothing solved again)",
            redo ? "forward" : "back", done, done == 1 ? "" : "s", t->sim.ccur + 1, t->sim.curve.nrows, h0);
    else
        say(t, 0, "%s %ld step%s: back at h0 = %s, exactly as it was", redo ? "redid" : "undid", done,
            done == 1 ? "" : "s", h0);
}

/* m: relaxation <-> static. Nothing is solved here; each mode finds what
 * it had, and the first step in static mode builds its solver. */
static void toggle_mode(tui *t)
{
    if (is_timed(t)) {
        /* an elastic sphere stays in time for its drive: the advice to set
         * elastic again changed nothing, and said the same */
        const adh_time_settings *ts = &config(t)->spec.time;
        unsigned g = ts->given;
        if (ts->sls)
            say(t, 1, "m does nothing in physical time: :set material.material elastic leaves it");
        else
            say(t, 1, "m does nothing in physical time: this elastic sphere is in it for its %s; start adhere "
                "without %s for the relaxation and the static curve", g & ADH_TIME_MODE ? "scene.mode = time"
                : g & ADH_TIME_SPEED ? "speed" : g & ADH_TIME_DWELL ? "dwell_time" : "spring",
                g & ADH_TIME_MODE ? "it" : "its drive (speed, dwell_time, spring)");
        return;
    }
    stop_all(t);
    tui_sim_set_mode(&t->sim, is_curve(t) ? ADH_MODE_RELAX : ADH_MODE_STATIC);
    size_t n;
    tui_sim_rows(&t->sim, &n);
    t->folds_seen = t->sim.sres.folds;
    const adh_obs *o = tui_sim_row(&t->sim);
    char h0[64] = "";
    if (o)
        fmtq(o->h0, ADH_Q_LENGTH, h0, sizeof h0);
    if (is_curve(t) && o)
        say(t, 0, "static equilibrium: back at point %zu of %zu of the curve, h0 = %s (nothing solved again)",
            t->sim.ccur + 1, t->sim.curve.nrows, h0);
    else if (is_curve(t))
        say(t, 0, "static equilibrium: f solves the next point, r follows the curve through its folds, b walks back");
    else if (o)
        say(t, 0, "relaxation: back on the path at h0 = %s (%zu state%s, kept); m returns to the curve",
            h0, n, n == 1 ? "" : "s");
    else
        say(t, 0, "relaxation: f steps the spheres together and relaxes, r runs to the turn; m: static");
}

/* Up/Down n fields, over those on the panel (physical time's only in it). */
static void select_move(tui *t, long n)
{
    int step = n < 0 ? P_COUNT - 1 : 1;
    for (long k = labs(n); k > 0; k--)
        do
            t->view.sel = (t->view.sel + step) % P_COUNT;
        while (!tui_sim_param_shown(&t->sim, (tui_param)t->view.sel));
}

/* A key on the help screen: PgUp/PgDn scroll, any other returns. */
static int help_key(tui *t, int key)
{
    if (key == KEY_NPAGE || key == KEY_PPAGE) {
        int page = LINES - 2 > 1 ? LINES - 2 : 1;
        t->view.help_top += key == KEY_NPAGE ? page : -page;
        if (t->view.help_top > t->help_lines - page)
            t->view.help_top = t->help_lines - page;
        if (t->view.help_top < 0)
            t->view.help_top = 0;
    } else {
        t->help = 0;
    }
    return TODO_REDRAW;
}

/* r: static mode follows the curve to its end; relaxation takes the
 * protocol's next step, from wherever the path is (the drive knows whether
 * it loads or unloads). What must be redone: a solve, or nothing. */
static int run_key(tui *t)
{
    char why[512];
    t->pending = 0;
    if (is_curve(t)) {
        char end[64];
        fmtq(tui_sim_curve_end(&t->sim), ADH_Q_LENGTH, end, sizeof end);
        t->run_dir = 1;
        if (is_timed(t))
            say(t, 0, "running the cycle in physical time, the base back to h0 = %s; any key pauses", end);
        else
            say(t, 0, "following the equilibrium curve through its folds to h0 = %s; any key pauses", end);
        return TODO_RESOLVE;
    }
    size_t k;
    int next = tui_sim_next(&t->sim, &k);
    if (next == 0) {
        tui_sim_why_done(&t->sim, why, sizeof why);
        say(t, 0, "%s", why);
        return TODO_NONE;
    }
    t->run_dir = 1;
    char tname[128];
    if (next < 0)
        tui_sim_turn_name(&t->sim, k - 1, tname, sizeof tname);
    if (next < 0 && strcmp(tname, "the turn") != 0)
        say(t, 0, "unloading %s until the jump-out; any key pauses", tname);
    else if (next > 0 && nturns(t) > 1 && k > 0)
        say(t, 0, "loading to turn %zu of %zu; any key pauses", k, nturns(t));
    else
        say(t, 0, "%s", next < 0 ? "unloading until the jump-out; any key pauses"
                                 : "loading to the turning point; any key pauses");
    return TODO_RESOLVE;
}

/* + and -: the selected field times f (a new turn leaves a run going). */
static void scale_key(tui *t, double f)
{
    char why[512];
    tui_param p = (tui_param)t->view.sel;
    if (p != P_TURN) {
        tui_sim_cancel(&t->sim);
        stop_all(t);
    }
    if (tui_sim_scale(&t->sim, p, f, why, sizeof why) != 0)
        say(t, 1, "%s; nothing changed", why);
    else
        key_changed(t, tui_params[p].key);
}

static int handle_key(tui *t, int key)
{
    char name[32];
    if (key == KEY_RESIZE)
        return TODO_REPAINT | TODO_REDRAW;
    if (t->help)
        return help_key(t, key);
    if (t->editing)
        return edit_key(t, key);
    if (key >= '0' && key <= '9' && (key != '0' || t->count > 0)) {
        t->count = t->count * 10 + (key - '0');
        if (t->count > 99999)
            t->count = 99999;
        return TODO_REDRAW;
    }
    int todo = TODO_REDRAW;
    long n = t->count ? t->count : 1;
    t->count = 0;
    tui_action a = tui_action_for_key(key);
    if (a != ACT_NONE && a != ACT_HELP && a != ACT_REDRAW && a != ACT_CANCEL)
        t->view.params_first = a == ACT_SELECT_UP || a == ACT_SELECT_DOWN || a == ACT_EDIT ||
                               a == ACT_SCALE_UP || a == ACT_SCALE_DOWN || a == ACT_COMMAND;
    switch (a) {
    case ACT_FORWARD:
    case ACT_BACK:
        t->pending = (int)n - 1;
        t->pending_dir = a == ACT_FORWARD ? +1 : -1;
        t->pending_key = key;
        t->run_dir = 0;
        todo |= TODO_RESOLVE;
        break;
    case ACT_RUN: todo |= run_key(t); break;
    case ACT_UNDO: move_history(t, 0, n); break;
    case ACT_REDO: move_history(t, 1, n); break;
    case ACT_RESET: {
        char st[64];
        stop_all(t);
        tui_sim_reset(&t->sim);
        fmtq(t->sim.start, ADH_Q_LENGTH, st, sizeof st);
        if (is_curve(t))
            say(t, 0, "reset: the curve is forgotten (the relaxation path is kept); f solves it again from h0 = %s", st);
        else
            say(t, 0, "reset: the path is forgotten; the next step starts at h0 = %s", st);
        break;
    }
    case ACT_MODE: toggle_mode(t); break;
    case ACT_SELECT_UP: select_move(t, -n); break;
    case ACT_SELECT_DOWN: select_move(t, n); break;
    case ACT_EDIT:
    case ACT_COMMAND:
        t->editing = a == ACT_EDIT ? EDIT_PARAM : EDIT_COMMAND;
        t->text[0] = '\0';
        t->textlen = 0;
        t->text_full = 0;
        break;
    case ACT_SCALE_UP:
    case ACT_SCALE_DOWN: scale_key(t, pow(a == ACT_SCALE_UP ? 2.0 : 0.5, (double)n)); break;
    case ACT_PLOTS: todo |= TODO_REPLOT; break;
    case ACT_HELP:
        t->help = 1;
        t->view.help_top = 0;
        break;
    case ACT_REDRAW: todo |= TODO_REPAINT; break;
    case ACT_CANCEL: say(t, 0, "%s", ""); break;
    case ACT_QUIT: t->quit = 1; break;
    case ACT_NONE:
        tui_replay_key_name(key, name, sizeof name);
        say(t, 1, "the key %s does nothing here; ? lists the keys", name);
        break;
    }
    return todo;
}

/* Does what a handler left to be redone. The direction of a solve is the
 * one the handler chose: a run's, else the pending steps'. */
static void redo_todo(tui *t, int todo)
{
    if (todo & TODO_REPAINT)
        clearok(curscr, TRUE);
    if (todo & TODO_RESOLVE)
        start_step(t, t->run_dir ? (is_curve(t) ? +1 : 0) : t->pending_dir);
    if (todo & TODO_REPLOT)
        write_plots(t);
    if (todo & (TODO_REDRAW | TODO_REPAINT))
        t->dirty = 1;
}


/* What the key that paused a run does besides: q quits; p draws the path
 * so far (the run stays paused: r goes on from there). */
static void paused_by(tui *t, int key, const char *h0)
{
    tui_action a = tui_action_for_key(key);
    if (a == ACT_QUIT)
        t->quit = 1;
    if (a != ACT_PLOTS)
        return;
    write_plots(t);
    char was[sizeof t->status];
    snprintf(was, sizeof was, "%s", t->status);
    say(t, t->status_error, "paused at h0 = %s, %s; r goes on", h0, was);
}

/* A key while a step is being solved (terminal only): the key that started
 * the steps, held down, asks for one more; any other key pauses. */
static void busy_key(tui *t, int key)
{
    if (key == KEY_RESIZE) {
        clearok(curscr, TRUE);
        return;
    }
    if (!t->run_dir && key == t->pending_key) {
        if (t->pending < 1)
            t->pending = 1;
        return;
    }
    tui_sim_cancel(&t->sim);
    stop_all(t);
    const adh_obs *o = tui_sim_row(&t->sim);
    char h0[64] = "the start";
    if (o)
        fmtq(o->h0, ADH_Q_LENGTH, h0, sizeof h0);
    say(t, 0, "paused at h0 = %s (the unfinished step was dropped); r goes on", h0);
    paused_by(t, key, h0);
}

static void handle_item(tui *t, const tui_replay_item *it)
{
    char why[512];
    if (it->kind == TUI_REPLAY_KEY) {
        redo_todo(t, handle_key(t, it->key));
        return;
    }
    t->dirty = 1;
    if (run_command(t, it, why, sizeof why) != 0) {
        /* A script that asks for the impossible is a broken script. */
        snprintf(t->fatal, sizeof t->fatal, "%s:%d: %s", t->keys.file, it->line, why);
        t->exit_code = EXIT_BAD_INPUT;
        t->quit = 1;
    }
}

/* A run between two steps: a replay reads its next item here (a key pauses,
 * a command runs, :wait lets the run finish); a terminal checks for a key. */
static void run_next(tui *t)
{
    tui_replay_item it;
    if (!t->waiting) {
        int got = tui_keysrc_next(&t->keys, 0, &it);
        if (got == KEYSRC_END) {
            stop_all(t);
            t->quit = 1;
            return;
        }
        if (got == KEYSRC_ITEM) {
            if (it.kind == TUI_REPLAY_KEY && it.key == KEY_RESIZE) {
                /* the window changed, not the user's mind: redrawn at the
                 * new size, the run goes on (it paused, as a key does) */
                clearok(curscr, TRUE);
                t->dirty = 1;
            } else if (it.kind == TUI_REPLAY_KEY) {
                stop_all(t);
                const adh_obs *o = tui_sim_row(&t->sim);
                char h0[64];
                fmtq(o->h0, ADH_Q_LENGTH, h0, sizeof h0);
                say(t, 0, "paused at h0 = %s; r goes on", h0);
                paused_by(t, it.key, h0);
                return;
            }
            handle_item(t, &it);
            if (!t->run_dir || t->quit)
                return;
        }
    }
    start_step(t, is_curve(t) ? +1 : 0);
}

static void progress(tui *t)
{
    if (is_curve(t)) {
        char h0[64];
        fmtq(tui_sim_target(&t->sim), ADH_Q_LENGTH, h0, sizeof h0);
        say(t, 0, "solving the %s past h0 = %s (point %zu); any key stops", is_timed(t) ? "path in time"
            : "equilibrium curve", h0, t->sim.curve.nrows + 1);
        draw(t);
        return;
    }
    double change;
    size_t it = tui_sim_progress(&t->sim, &change);
    char h0[64], c[64], e[64];
    fmtq(tui_sim_target(&t->sim), ADH_Q_LENGTH, h0, sizeof h0);
    fmtq(change, ADH_Q_LENGTH, c, sizeof c);
    fmtq(config(t)->spec.relax.eps, ADH_Q_LENGTH, e, sizeof e);
    say(t, 0, "relaxing at h0 = %s: iteration %zu, change %s (done below %s); any key stops", h0, it, c, e);
    draw(t);
}

static void loop(tui *t)
{
    tui_replay_item it;
    while (!t->quit) {
        if (got_signal) {
            /* 128 + the signal, as --batch: SIGINT 130, SIGTERM 143, SIGHUP
             * (terminal gone) 129, SIGQUIT (C-\) 131 */
            t->exit_code = 128 + got_signal;
            snprintf(t->fatal, sizeof t->fatal, "adhere: stopped by signal %d", (int)got_signal);
            break;
        }
        if (t->sim.busy) {
            if (!t->headless) {
                if (tui_keysrc_next(&t->keys, 0, &it) == KEYSRC_ITEM)
                    busy_key(t, it.key);
                if (!t->sim.busy)
                    continue;
                if (adh_clock_seconds() - t->last_draw > 0.15)
                    progress(t);
            }
            char why[512];
            /* Batches keep a terminal responsive; a replay never reads keys
             * inside a step, so its batch size changes nothing it shows. */
            tui_work rc = tui_sim_work(&t->sim, t->headless ? 5000 : 200, why, sizeof why);
            adh_ready_mark();   /* a solve is under way, signals are caught */
            if (rc != TUI_WORK_BUSY)
                after_step(t, rc, why);
            continue;
        }
        if (t->run_dir) {
            /* a static point can take well under a millisecond: drawing
             * each would cost more than solving it */
            if (!t->headless && (!is_curve(t) || adh_clock_seconds() - t->last_draw > 0.05))
                draw(t);
            run_next(t);
            continue;
        }
        if (t->dirty)
            draw(t);
        int got = tui_keysrc_next(&t->keys, 250, &it);  /* wakes up to see signals */
        if (got == KEYSRC_END)
            break;
        if (got == KEYSRC_ITEM)
            handle_item(t, &it);
    }
    tui_sim_cancel(&t->sim);
}

static int screen_open(tui *t, char *why, size_t whylen)
{
    if (t->headless) {
        t->fout = fopen("/dev/null", "w");
        t->fin = fopen("/dev/null", "r");
        if (!t->fout || !t->fin) {
            snprintf(why, whylen, "cannot open /dev/null for the headless screen: %s", strerror(errno));
            return -1;
        }
        /* A fixed terminal type and size, whatever TERM, LINES and COLUMNS
         * say: the same script must give the same screen anywhere. */
        use_env(FALSE);
        /* vt100 first (ncurses-base always has it); the screen text does
         * not depend on which, only on curses having some entry. */
        static const char *const types[] = { "vt100", "ansi", "xterm", "dumb" };
        for (size_t i = 0; i < sizeof types / sizeof types[0] && !t->scr; i++)
            t->scr = newterm(types[i], t->fout, t->fin);
        if (!t->scr) {
            snprintf(why, whylen, "cannot start curses headless: no vt100, ansi, xterm or dumb terminfo entry");
            return -1;
        }
        set_term(t->scr);
        resizeterm(config(t)->tui.rows, config(t)->tui.cols);
    } else {
        if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO)) {
            snprintf(why, whylen, "the TUI needs a terminal; use --batch, or --replay=FILE for a keystroke script");
            return -1;
        }
        const char *term = getenv("TERM");
        t->scr = newterm(NULL, stdout, stdin);
        if (!t->scr) {
            snprintf(why, whylen, "cannot use the terminal type TERM=%s; set TERM, or use --batch",
                     term ? term : "(unset)");
            return -1;
        }
        set_term(t->scr);
        curs_set(0);
    }
    cbreak();   /* not raw(): C-c must stay SIGINT */
    noecho();
    nonl();
    keypad(stdscr, TRUE);
    set_escdelay(25);
    return 0;
}

static void screen_close(tui *t)
{
    if (t->scr) {
        endwin();
        delscreen(t->scr);
        t->scr = NULL;
    }
    if (t->fout)
        fclose(t->fout);
    if (t->fin)
        fclose(t->fin);
    t->fout = t->fin = NULL;
}

static int locale_utf8(int headless)
{
    setlocale(LC_ALL, "");
    /* One numeric locale, C's, wherever numbers are read or written (the
     * tables, gnuplot's commands and data, :set E 0.5GPa): a decimal comma
     * would break all three. The terminal keeps its LC_CTYPE. */
    setlocale(LC_NUMERIC, "C");
    if (strcmp(nl_langinfo(CODESET), "UTF-8") == 0)
        return 1;
    /* A replay's screen is written as UTF-8 text whatever the caller's
     * locale; a real terminal keeps its own and gets ASCII labels. */
    if (headless && setlocale(LC_CTYPE, "C.UTF-8"))
        return strcmp(nl_langinfo(CODESET), "UTF-8") == 0;
    return 0;
}

int tui_main(const adh_config *cfg)
{
    static tui t;   /* large; and the signal handler's flag lives beside it */
    char why[1024];
    memset(&t, 0, sizeof t);
    t.dirty = 1;
    t.headless = cfg->tui.replay[0] != '\0';
    if (t.headless) {
        if (tui_keysrc_replay(&t.keys, cfg->tui.replay, why, sizeof why) != 0) {
            adh_say_as(NULL, why);   /* FILE:LINE: first, as compilers do */
            return EXIT_BAD_INPUT;
        }
    } else {
        tui_keysrc_terminal(&t.keys);
    }
    if (tui_sim_init(&t.sim, cfg, why, sizeof why) != 0) {
        adh_say(why);
        tui_keysrc_free(&t.keys);
        return EXIT_BAD_INPUT;
    }
    adh_tui_options *size = &t.sim.cfg.tui;
    if (size->cols < 40 || size->rows < 12) {
        size->cols = 100;
        size->rows = 32;
    }
    t.view.utf8 = locale_utf8(t.headless);
    t.view.no_clock = cfg->tui.no_clock;
    t.view.measured = cfg->output.measured;

    struct sigaction sa, old_int, old_term, old_hup, old_quit;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    got_signal = 0;
    /* Before newterm: curses then leaves these handlers alone. */
    sigaction(SIGINT, &sa, &old_int);
    sigaction(SIGTERM, &sa, &old_term);
    sigaction(SIGHUP, &sa, &old_hup);   /* a closed terminal: restore and go */
    sigaction(SIGQUIT, &sa, &old_quit); /* C-\ (cbreak keeps it a signal): restore, not a broken terminal */

    if (screen_open(&t, why, sizeof why) != 0) {
        screen_close(&t);
        sigaction(SIGINT, &old_int, NULL);
        sigaction(SIGTERM, &old_term, NULL);
        sigaction(SIGHUP, &old_hup, NULL);
        sigaction(SIGQUIT, &old_quit, NULL);
        adh_say(why);
        tui_sim_free(&t.sim);
        tui_keysrc_free(&t.keys);
        return EXIT_BAD_INPUT;   /* no terminal to run on: a usage error */
    }
    /* the screen runs one: say where the rest are, in every mode */
    char swept[160] = "";
    if (adh_sweep_runs(&cfg->sweep) > 1)
        snprintf(swept, sizeof swept, " (this scene's sweep of %zu runs is for --batch; here one run, the values at "
                 "the left)", adh_sweep_runs(&cfg->sweep));
    if (cfg->spec.mode == ADH_MODE_RIGID)
        say(&t, 0, "The screen relaxes step by step as the paper does; --mode=rigid is for --batch%s. ? lists every "
            "key.", swept);
    else if (cfg->spec.mode == ADH_MODE_STATIC)
        say(&t, 0, "Static equilibrium%s: f solves the curve point by point, r follows it to the end, ? lists every "
            "key.", swept);
    else if (cfg->spec.mode == ADH_MODE_TIME)
        say(&t, 0, "Physical time%s: f takes the next step in time, r runs the cycle, b walks back, ? lists every "
            "key.", swept);
    else if (adh_sweep_runs(&cfg->sweep) > 1)
        say(&t, 0, "%s%sits sweep of %zu runs is for --batch; here one run, the values at the left. f steps in, "
            "r runs, ? lists every key.", cfg->output.title, cfg->output.title[0] ? ": " : "This scene: ",
            adh_sweep_runs(&cfg->sweep));
    else if (cfg->output.title[0])
        say(&t, 0, "%s. f steps in, r runs, ? lists every key.", cfg->output.title);
    else
        say(&t, 0, "Welcome. f steps the spheres together, r runs to the turning point, ? lists every key.");
    loop(&t);
    if (cfg->tui.screen[0] && t.exit_code == 0) {
        draw(&t);
        if (tui_dump_screen(cfg->tui.screen, why, sizeof why) != 0) {
            snprintf(t.fatal, sizeof t.fatal, "adhere: %.1000s", why);
            t.exit_code = EXIT_BAD_INPUT;   /* an unwritable output */
        }
    }
    screen_close(&t);
    sigaction(SIGINT, &old_int, NULL);
    sigaction(SIGTERM, &old_term, NULL);
    sigaction(SIGHUP, &old_hup, NULL);
    sigaction(SIGQUIT, &old_quit, NULL);
    if (t.fatal[0])
        adh_say_as(NULL, t.fatal);   /* escaped: it may quote a file's name or a script's text */
    tui_sim_free(&t.sim);
    tui_keysrc_free(&t.keys);
    return t.exit_code;
}
