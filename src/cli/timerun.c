/* Physical time for the CLI: a run of the viscoelastic step rule, and what
 * the tables say of it. */
#include "cli/timerun.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/drive.h"
#include "adhere/rule_time.h"
#include "adhere/status.h"
#include "adhere/units.h"
#include "scene/text.h"

/* A run in time that ran through, marked unconverged where its numbers
 * are not promised to 0.5 %, with the sentence why in run->why and the
 * tolerance's setting in run->fix (the drivers name it as it was given):
 * a tolerance looser than the one the promise was measured at, or an
 * energy balance open past what a converged integration closes to (an
 * elastic path integrates nothing: its residual is its loop's quadrature
 * against its chords, the static curve's, and it has no time tolerance).
 * Where the residual is the integration's error it falls with the
 * tolerance (Einf = 1.1 E0 on 5 nm rings: 1.0 %, 0.74 % and 0.49 % at
 * 5e-5, 2.5e-5 and 1.25e-5), so the sentence says a tighter one closes it
 * there; where it does not fall (1 mm/s near elastic at R = 1 um: 0.41 %,
 * 0.53 %, 0.63 % at 5e-5, 1.25e-5, 1e-6) the error is another's, which
 * halving it tells. */
static void time_mark(int sls, const adh_visco_settings *s, const adh_visco_result *res, adh_run *run)
{
    double open = adh_visco_balance_open(res);
    char tol[32];
    int loose = sls && adh_visco_tol_loose(s->tol);
    int unclosed = res->steps > 0 && fabs(open) > ADH_VISCO_BALANCE_MAX;
    if (!loose && !unclosed)
        return;
    run->unconverged = 1;
    run->fix |= sls ? ADH_FIX_TIME_TOL : 0;
    if (loose) {
        snprintf(run->why, sizeof run->why, "the time tolerance %s is looser than %g, up to which halving it moves "
                 "the pull-off, the jumps and the hysteresis by under 0.5 %%: these numbers are not promised to 0.5 %%",
                 adh_format_shortest(s->tol, tol, sizeof tol), ADH_VISCO_TOL_DEFAULT);
    } else {
        snprintf(run->why, sizeof run->why, "the energy balance is open by %.2g %% of the hysteresis (over %g %%: "
                 "hysteresis - dissipated - jump_loss - stored_change): the integration did not converge, its numbers "
                 "are not to its tolerance", 100 * fabs(open), 100 * ADH_VISCO_BALANCE_MAX);
        if (sls)   /* an elastic path has no tolerance of time to tighten: the static curve's */
            adh_text_catf(run->why, sizeof run->why, ", %g; where the residual is the integration's error, falling "
                          "with the tolerance, a tighter one closes it", s->tol);
    }
    if (loose && unclosed)
        adh_text_catf(run->why, sizeof run->why, "; the energy balance is open by %.2g %% of the hysteresis (over %g %%)",
                      100 * fabs(open), 100 * ADH_VISCO_BALANCE_MAX);
}

int cli_time_run(const adh_run_spec *spec, const adh_grid *g, const adh_kernel *k, adh_step_cb cb, void *ctx,
                 adh_run *run, cli_time_out *out)
{
    memset(out, 0, sizeof *out);
    adh_config_visco(spec, &out->vs);
    adh_drive *d = adh_drive_alloc(adh_config_time_rule(spec), g, k);
    if (!d) {
        run->status = ADH_ENOMEM;
        return run->status;
    }
    int rc = adh_drive_set(d, &spec->mat, &out->vs, &spec->proto, run);
    if (rc == ADH_SUCCESS)
        rc = adh_runner_drive(d, cb, ctx);
    if (adh_rule_time_summary(d, &out->res) == 0) {
        const adh_visco_event *ev;
        size_t n = adh_rule_time_events(d, &ev);
        out->ev = n ? malloc(n * sizeof *ev) : NULL;
        if (out->ev) {
            memcpy(out->ev, ev, n * sizeof *ev);
            out->nev = n;
        }
    }
    adh_rule_time_take(d, run);
    adh_drive_free(d);
    run->status = rc;
    if (rc == ADH_SUCCESS)
        time_mark(spec->time.sls, &out->vs.s, &out->res, run);
    return rc;
}

void cli_time_out_free(cli_time_out *out)
{
    free(out->ev);
    out->ev = NULL;
    out->nev = 0;
}

size_t cli_time_keys(const cli_time_out *o, cli_tables_extra *x)
{
    const adh_visco_result *r = &o->res;
    const adh_visco_energy *c = &r->cycle;
    /* the cycle's accounts exist once it closed: a run stopped before
     * says nan, not the zeros they start from */
    int closed = !isnan(r->hysteresis);
    const cli_tables_extra v[] = {
        { "E0", o->vs.sls.E0 },
        { "Einf", o->vs.sls.Einf },
        { "tau", o->vs.sls.tau },
        { "speed_in", o->vs.drive.speed_in },
        { "speed_out", o->vs.drive.speed_out },
        { "dwell_time", o->vs.drive.dwell },
        { "spring", o->vs.drive.spring },
        { "jump_in_t", r->jump_in_t },
        { "jump_in_base", r->jump_in_base },
        { "pulloff_t", r->pulloff_t },
        { "pulloff_base", r->pulloff_base },
        { "jump_out_t", r->jump_out_t },
        { "jump_out_base", r->jump_out_base },
        { "hysteresis", r->hysteresis },
        { "dissipated", closed ? c->dissipated : NAN },
        { "jump_loss", closed ? c->jumps : NAN },
        { "stored_change", closed ? c->stored - c->stored0 : NAN },
        /* what the balance leaves: the work less the three, the
         * integration's error (no term is missing: docs/viscoelastic.md);
         * an elastic path's, its loop's quadrature against its chords */
        { "energy_residual", closed ? adh_visco_balance_residual(r) : NAN },
        { "time", r->time },
        { "time_steps", (double)r->steps },
        { "jumps", (double)r->jumps },
        { "lattice_jumps", (double)r->lattice_jumps },
        { "jumps_relaxed", (double)r->jumps_relaxed },
        { "folds_resumed", (double)r->folds_resumed },
        { "newton_iterations", (double)r->newton },
        { "krylov_iterations", (double)r->krylov },
        { "tolerance", o->vs.s.tol },
    };
    size_t n = sizeof v / sizeof v[0];
    memcpy(x, v, n * sizeof *v);
    return n;
}

size_t cli_time_snap_keys(const adh_run *curve, double k, double *store, cli_tables_extra *x)
{
    double at[64], base[64];
    size_t nf = adh_visco_spring_folds(curve, k, at, base, 64);
    if (nf > 64)
        nf = 64;
    store[0] = k;
    store[1] = nf ? at[0] : NAN;
    store[2] = nf ? base[0] : NAN;
    store[3] = nf >= 2 ? adh_visco_spring_snap_out(curve, k, &store[4]) : NAN;
    if (nf < 2)
        store[4] = NAN;
    static const char *const names[CLI_TIME_SNAP_KEYS] = { "spring", "snap_in_h0", "snap_in_base", "snap_out_h0",
                                                           "snap_out_base" };
    for (size_t i = 0; i < CLI_TIME_SNAP_KEYS; i++) {
        x[i].key = names[i];
        x[i].value = store[i];
    }
    return CLI_TIME_SNAP_KEYS;
}

static const char *event_word(int kind)
{
    switch (kind) {
    case ADH_VISCO_JUMP: return "jump";
    case ADH_VISCO_CONTACT: return "contact";
    case ADH_VISCO_PULLOFF: return "pulloff";
    case ADH_VISCO_TURN: return "turn";
    case ADH_VISCO_UNLOAD: return "unload";
    case ADH_VISCO_END: return "end";
    }
    return "?";
}

int cli_time_events(FILE *f, const void *vo)
{
    const cli_time_out *o = vo;
    fputs("# adhere " ADH_VERSION "\n# events in physical time, SI units (s, m, N, J): jump (a fold of the "
          "instantaneous problem or the spring's instability, before and after), contact formed or lost without "
          "a jump, pulloff (a force minimum on unloading), turn, unload (retraction begins), end\n", f);
    if (o->scene && o->scene[0])
        cli_tables_comment(f, "scene", o->scene);
    if (o->partial)   /* the events of a run cut short, as its force.tsv says */
        fprintf(f, "# PARTIAL: %s\n", o->partial);
    fputs("event\tpath\tt\tbase\th0\tF\ta\th0_after\tF_after\ta_after\tloss\n", f);
    for (size_t i = 0; i < o->nev; i++) {
        const adh_visco_event *e = &o->ev[i];
        fprintf(f, "%s\t%d\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\n", event_word(e->kind),
                e->path, e->t, e->base, e->h0, e->F, e->a, e->h0_after, e->F_after, e->a_after, e->loss);
    }
    return 0;
}
