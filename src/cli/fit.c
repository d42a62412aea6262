#include "cli/fit.h"
#include "plot/say.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/fit.h"
#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/status.h"
#include "adhere/units.h"
#include "cli/advice.h"
#include "cli/batch.h"
#include "cli/fitreport.h"
#include "cli/interrupt.h"
#include "cli/tables.h"
#include "util/ready.h"
#include "plot/outdir.h"
#include "scene/budget.h"
#include "scene/config.h"
#include "scene/fitdata.h"

/* A fit refits on a grid chosen for its optimum at most this often. */
#define MAX_REFITS 2

typedef struct fit_run {
    cli_options *cli;
    adh_fit_settings fs;
    adh_fitdata fd;
    adh_grid *g;
    adh_kernel *k;
    double dr;                /* the built grid's (finest) spacing */
    size_t nodes;
    size_t evals;             /* over every fit */
    double t0;
    char note[PATH_MAX + 1200]; /* the scene's keys the fit ignores, said as it starts; "" none */
} fit_run;

/* The free parameters each model takes, and its default set. */
#define FIT_ELASTIC_PARAMS "E, A, z0, R, offset and baseline"
#define FIT_TIME_FREE "E,A,Einf,tau"
#define FIT_TIME_PARAMS "E0 (or E), Einf, tau, A, z0, R, offset and baseline"

static int parse_free(const char *text, int time, unsigned *mask, char *why, size_t whylen)
{
    char buf[128], *save = NULL;
    snprintf(buf, sizeof buf, "%s", *text ? text : time ? FIT_TIME_FREE : "E,A");
    *mask = 0;
    for (char *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        adh_fit_param p;
        if (adh_fit_param_parse(t, &p) != 0) {
            snprintf(why, whylen, "--free: '%s' is not a parameter: use %s, separated by commas", t,
                     time ? FIT_TIME_PARAMS : FIT_ELASTIC_PARAMS);
            return -1;
        }
        if ((p == ADH_FIT_EINF || p == ADH_FIT_TAU) && !time) {
            snprintf(why, whylen, "--free: '%s' is the standard linear solid's, which only --model=time fits (with "
                     "--material=sls): this model's parameters are %s", t, FIT_ELASTIC_PARAMS);
            return -1;
        }
        if (*mask & 1u << p) {   /* a typo for another name, not a second wish for this one */
            snprintf(why, whylen, "--free: %s is named twice in '%s': name each parameter once",
                     p == ADH_FIT_E && time ? "E0 (E)" : adh_fit_param_name(p), text);
            return -1;
        }
        *mask |= 1u << p;
    }
    if (!*mask) {
        snprintf(why, whylen, "--free: name at least one of %s", time ? FIT_TIME_PARAMS : FIT_ELASTIC_PARAMS);
        return -1;
    }
    /* the force is gamma R times a function of h0/z0 and sigma alone: E, A
     * and R together have a direction that changes nothing, and the fit
     * reported whatever point it stopped at as a fit (R 7.96 um +- 3.6 %
     * on a curve made with 10 um) */
    unsigned ear = 1u << ADH_FIT_E | 1u << ADH_FIT_A | 1u << ADH_FIT_R;
    if ((*mask & ear) == ear) {
        snprintf(why, whylen, "--free: E, A and R together are not determined by a force curve (it is gamma R times "
                 "a function of h0/z0 and sigma, two combinations of the three): free at most two of them, and give "
                 "the third (R from the probe)");
        return -1;
    }
    return 0;
}

/* A drive flag the fit's model does not use would be dropped in silence:
 * the turn and the start are the fit's own in both models (the model's
 * curve runs from where the force is negligible to a step below the data),
 * the relaxation unloads at its turn without a dwell, and the static curve
 * has neither a dwell nor a relaxation for --eps to end. 0, or -1 with the
 * flag and why. The scene's keys stay (scene_ignored says them): they set
 * the runs the scene itself opens. */
static int fit_ignored(const cli_options *cli, adh_fit_model_kind kind, char *why, size_t whylen)
{
    int relax = kind == ADH_FIT_MODEL_RELAX;
    for (size_t i = 0; i < cli->nset; i++) {
        const cli_set *f = &cli->set[i];
        if (strcmp(f->key, "protocol.turns") == 0)
            snprintf(why, whylen, "adhere fit takes its turn from the data, %s the deepest position in "
                     "--data: --turn=%.40s would be ignored; leave it out",
                     kind == ADH_FIT_MODEL_TIME ? "at" : "a step below", f->value);
        else if (strcmp(f->key, "protocol.start") == 0 && strcmp(f->value, "auto") != 0)
            snprintf(why, whylen, "adhere fit starts its model's curve where the force is negligible, above the "
                     "highest position in --data: --start=%.40s would be ignored; leave it out", f->value);
        else if (strcmp(f->key, "protocol.dwell") == 0 && cli->cfg.spec.proto.dwell && kind == ADH_FIT_MODEL_TIME)
            snprintf(why, whylen, "adhere fit --model=time holds at its turn for a time in seconds (--dwell-time, "
                     "the data's), not a count of iterations: --dwell=%.40s would be ignored; leave it out", f->value);
        else if (strcmp(f->key, "protocol.dwell") == 0 && cli->cfg.spec.proto.dwell)
            snprintf(why, whylen, relax ? "adhere fit --model=relax unloads at its turn without a dwell: "
                     "--dwell=%.40s would be ignored; leave it out" : "adhere fit's static model is the static "
                     "curve, with no turn to dwell at: --dwell=%.40s would be ignored; leave it out", f->value);
        else if (strcmp(f->key, "solver.eps") == 0 && kind == ADH_FIT_MODEL_TIME)
            snprintf(why, whylen, "adhere fit --model=time integrates in physical time to the integrator's "
                     "tolerance, with no relaxation for --eps to end: --eps=%.40s would be ignored; leave it out",
                     f->value);
        else if (strcmp(f->key, "solver.time_tol") == 0 && kind == ADH_FIT_MODEL_TIME &&
                 adh_fit_model_time_tol(cli->cfg.spec.time.tol) != cli->cfg.spec.time.tol)   /* dropped */
            snprintf(why, whylen, "adhere fit --model=time integrates its model to a tolerance of %g or tighter "
                     "(its %g %% differences must stand above the model's own noise): --time-tol=%.40s would be "
                     "ignored; leave it out, or give one of %g or less", ADH_FIT_MODEL_TIME_TOL,
                     100 * ADH_FIT_MODEL_TIME_FD_STEP, f->value, ADH_FIT_MODEL_TIME_TOL);
        else if (strcmp(f->key, "solver.eps") == 0 && !relax)
            snprintf(why, whylen, "adhere fit's static model solves each point of the static curve to its own "
                     "tolerance, with no relaxation for --eps to end: --eps=%.40s would be ignored; leave it out, "
                     "or give --model=relax", f->value);
        else
            continue;
        return -1;
    }
    return 0;
}

/* The same settings from the scene are ignored too, but not refused: every
 * shipped figure scene sets its turns (fig1's, -2 nm), which its own runs
 * take, and a fit of the scene must still run. The fit says once, in
 * note, which of them it ignores, by key and line ("" when none). */
static void scene_ignored(const adh_config *cfg, adh_fit_model_kind kind, char *note, size_t len)
{
    int relax = kind == ADH_FIT_MODEL_RELAX;
    const struct { const char *key; int ignored; } keys[] = {
        { "protocol.turns", 1 },
        { "protocol.start", !isnan(cfg->spec.proto.start) },
        { "protocol.dwell", cfg->spec.proto.dwell != 0 },
        { "protocol.unload", !cfg->spec.proto.unload },   /* fig1's 'unload = no': the fit unloads */
        { "solver.eps", !relax },
        /* a looser one is dropped for the model's own (adh_fit_model_time_tol) */
        { "solver.time_tol", kind == ADH_FIT_MODEL_TIME && adh_fit_model_time_tol(cfg->spec.time.tol) != cfg->spec.time.tol },
    };
    char list[200] = "";
    size_t n = 0, nkeys = sizeof keys / sizeof keys[0];
    int eps = 0, tol = 0;
    for (size_t i = 0; i < nkeys; i++) {
        int from = adh_config_origin(cfg, keys[i].key);
        if (keys[i].ignored && (from == -1 || from > 0)) {
            n += (size_t)snprintf(list + n, sizeof list - n, "%s%s", n ? ", " : "", keys[i].key);
            eps |= strcmp(keys[i].key, "solver.eps") == 0;
            tol |= strcmp(keys[i].key, "solver.time_tol") == 0;
        }
    }
    note[0] = '\0';
    if (!n)
        return;
    char sentence[800], tail[160] = "";
    if (tol)
        snprintf(tail, sizeof tail, "; the model integrates to a tolerance of %g or tighter, for its %g %% differences "
                 "to stand above its own noise", ADH_FIT_MODEL_TIME_TOL, 100 * ADH_FIT_MODEL_TIME_FD_STEP);
    snprintf(sentence, sizeof sentence, "the fit ignores the scene's %s: its model's curve runs from where the force "
             "is negligible, above the highest position in --data, to a turn %s%s%s%s (the "
             "scene's own runs take them)", list, kind == ADH_FIT_MODEL_TIME ? "at the deepest" : "a step below the deepest",
             relax ? " and back at once" : "",
             !eps ? "" : kind == ADH_FIT_MODEL_TIME ? "; physical time integrates to its tolerance, with no relaxation for eps to end"
             : "; the static curve solves each point to its own tolerance, with no relaxation for eps to end", tail);
    cli_options_words(cfg, sentence, note, len);
}

/* The fit's settings from the line and the scene: the start values, the
 * free parameters, the model and its solver. */
static int settings(fit_run *fr, char *why, size_t whylen)
{
    const cli_options *cli = fr->cli;
    const adh_config *cfg = &cli->cfg;
    fr->fs = adh_fit_settings_default();
    const char *model = cli->fit.model;   /* one of the three words: the line's parse refused any other */
    adh_fit_model_kind kind = strcmp(model, "relax") == 0 ? ADH_FIT_MODEL_RELAX
                            : strcmp(model, "time") == 0 ? ADH_FIT_MODEL_TIME : ADH_FIT_MODEL_STATIC;
    /* the physical-time model is the solid's, and only the solid's: an
     * elastic sphere is rate-independent (the static model fits it) */
    if (kind == ADH_FIT_MODEL_TIME && !cfg->spec.time.sls) {
        snprintf(why, whylen, "--model=time fits a standard linear solid in physical time: give --material=sls "
                 "(with start values --E0, --Einf, --tau and the data's --speed); an elastic sphere is "
                 "rate-independent, and --model=static fits it");
        return -1;
    }
    /* the data hold positions, not times: a curve measured at 10 nm/s fitted
     * at the default speed gave its E0 and tau for another curve */
    if (kind == ADH_FIT_MODEL_TIME && adh_config_origin(cfg, "protocol.speed") == -2) {
        snprintf(why, whylen, "--model=time runs its model at the speed the data were measured at, which --data does "
                 "not hold: give --speed (the approach's and retraction's, --speed=M/S or M/S,M/S); the default "
                 "would be taken for it in silence");
        return -1;
    }
    if (kind != ADH_FIT_MODEL_TIME && cfg->spec.time.sls) {
        snprintf(why, whylen, "--model=%s fits an elastic sphere, and the material is a standard linear solid "
                 "(material = sls): fit it with --model=time, or give --material=elastic", *model ? model : "static");
        return -1;
    }
    if (parse_free(cli->fit.free, kind == ADH_FIT_MODEL_TIME, &fr->fs.free, why, whylen) != 0)
        return -1;
    fr->fs.model.kind = kind;
    if (fit_ignored(cli, kind, why, whylen) != 0)
        return -1;
    scene_ignored(cfg, kind, fr->note, sizeof fr->note);
    if (kind == ADH_FIT_MODEL_TIME) {   /* the drive as given; the solid's start values */
        adh_config_visco(&cfg->spec, &fr->fs.model.visco);
        fr->fs.Einf = fr->fs.model.visco.sls.Einf;
        fr->fs.tau = fr->fs.model.visco.sls.tau;
    }
    fr->fs.model.relax = cfg->spec.relax;
    fr->fs.model.step = cfg->spec.proto.step;
    fr->fs.start = cfg->spec.mat;
    /* the start values are a material as a run's are (A = 0 has no
     * adhesion, nothing to compare the curve's pull-off with) */
    char msg[512];
    if (adh_material_validate(&fr->fs.start, msg, sizeof msg) != ADH_SUCCESS) {
        cli_options_core_words(cfg, &cfg->spec, CLI_ADVICE_FIT, msg, why, whylen);
        return -1;
    }
    fr->fs.offset = cli->fit.offset;
    fr->fs.baseline = cli->fit.baseline;
    fr->fs.cancel = cli_interrupt_flag();
    return 0;
}

/* The configuration as the fit runs it: the mode its model is, one turn a
 * step below the deepest point (the grid must hold the contact there), and
 * the grid chosen for the start values when none was given. */
static int configure(fit_run *fr, char *why, size_t whylen)
{
    adh_config *cfg = &fr->cli->cfg;
    double lo = INFINITY, step = cfg->spec.proto.step;
    for (size_t i = 0; i < fr->fd.d.n; i++)
        lo = fmin(lo, fr->fd.d.x[i] - fr->fs.offset);
    cfg->spec.mode = fr->fs.model.kind == ADH_FIT_MODEL_RELAX ? ADH_MODE_RELAX
                   : fr->fs.model.kind == ADH_FIT_MODEL_TIME ? ADH_MODE_TIME : ADH_MODE_STATIC;
    cfg->spec.proto.nturns = 1;
    cfg->spec.proto.turns[0] = step * floor(lo / step) - step;
    cfg->spec.proto.unload = 1;
    cfg->spec.proto.nprofiles = 0;
    unsigned fix = 0;
    if (adh_config_grid(cfg, why, whylen, &fix) != 0) {
        cli_advice_append_cfg(cfg, CLI_ADVICE_FIT, why, whylen, fix);
        return -1;
    }
    /* the checks every run meets, and memory for one static solver */
    if (cli_options_validate_for(cfg, CLI_ADVICE_FIT, why, whylen) != 0 ||
        adh_budget_check(&cfg->spec, cfg->spec.mode == ADH_MODE_STATIC, why, whylen) != 0)
        return -1;
    return 0;
}

static void release(fit_run *fr)
{
    adh_kernel_free(fr->k);
    adh_grid_free(fr->g);
    fr->k = NULL;
    fr->g = NULL;
}

static int build(fit_run *fr, char *why, size_t whylen)
{
    const adh_config *cfg = &fr->cli->cfg;
    int st = ADH_ENOMEM;
    release(fr);
    fr->g = adh_config_grid_alloc(&cfg->spec);
    fr->k = fr->g ? adh_config_kernel_alloc(&cfg->spec, fr->g, &st) : NULL;
    if (!fr->k) {
        snprintf(why, whylen, "the grid or kernel of %zu nodes could not be built: %s", cfg->spec.grid.use.nodes, adh_strerror(st));
        return -1;
    }
    fr->dr = adh_config_spacing(&cfg->spec);
    fr->nodes = cfg->spec.grid.use.nodes;
    return 0;
}

static int progress(const adh_fit_progress *p, void *ctx)
{
    const fit_run *fr = ctx;
    adh_ready_mark();   /* the first evaluation is in: a test may signal now */
    if (fr->cli->cfg.output.quiet)
        return 0;
    char line[512];
    int n = snprintf(line, sizeof line, "  eval %3zu%s iter %2zu ", fr->evals + p->evals, p->jacobian ? " (J)" : "    ",
                     p->iterations);
    for (int i = 0; i < ADH_FIT_NPARAM && n < (int)sizeof line - 64; i++)
        if (fr->fs.free & 1u << i)
            n += snprintf(line + n, sizeof line - (size_t)n, " %s %.6g", adh_fit_param_name((adh_fit_param)i),
                          p->value[i]);
    fprintf(stderr, "%s  chi2 %.4g N^2  best %.4g\n", line, p->chi2, p->best_chi2);
    return 0;
}

/* One fit on the grid built; then the resolution at its optimum. */
static int fit_once(fit_run *fr, adh_fit_result *res, adh_fit **out)
{
    int st;
    fr->fs.progress = progress;
    fr->fs.ctx = fr;
    adh_fit *f = adh_fit_alloc(fr->g, fr->k, &fr->fd.d, &fr->fs, &st);
    if (!f)
        return st;
    adh_fit_run(f, res);
    fr->evals += res->evals;
    *out = f;
    return res->status;
}

/* The physical-time model runs one cycle from rest: an approach, then its
 * retraction from a turn at the deepest point. A second cycle (its history
 * the first's, its turn elsewhere) was compared with the first's branches
 * in silence. 0, or -1 with FILE:LINE and why. */
static int one_cycle(const adh_fitdata *fd, char *why, size_t whylen)
{
    int prev = 0, nseg = 0;
    for (size_t i = 0; i < fd->d.n; i++) {
        if (i && fd->seg[i] == fd->seg[i - 1])
            continue;
        if (++nseg > 2 || (nseg == 2 && !(prev > 0 && fd->dir[i] < 0))) {
            /* a first segment that retracts: an approach after it is no
             * second one ("approach again" said so of data never approached) */
            int first_out = nseg == 2 && prev < 0 && fd->dir[i] > 0;
            snprintf(why, whylen, "%.1000s:%zu: --model=time runs one cycle from rest, an approach and then its "
                     "retraction, turned at the deepest point: the data %s here (segment %d); give one cycle%s",
                     fd->file[i]->path, fd->line[i],
                     first_out ? "approach after a retraction" : fd->dir[i] > 0 ? "approach again" : "retract again",
                     nseg, first_out ? ", its approach first" : "");
            return -1;
        }
        prev = fd->dir[i];
    }
    return 0;
}

static int refuse(const char *why)
{
    adh_say(why);
    return CLI_EXIT_USAGE;
}

int cli_fit_main(cli_options *cli)
{
    fit_run fr = { .cli = cli };
    char why[2048];
    adh_config *cfg = &cli->cfg;
    if (settings(&fr, why, sizeof why) != 0)
        return refuse(why);
    if (adh_fitdata_make(cfg->output.measured, (size_t)__builtin_popcount(fr.fs.free), &fr.fs.start, fr.fs.offset,
                         fr.fs.baseline, &fr.fd, why, sizeof why) != 0)
        return refuse(why);
    if (fr.fs.model.kind == ADH_FIT_MODEL_TIME && one_cycle(&fr.fd, why, sizeof why) != 0) {
        adh_fitdata_free(&fr.fd);
        return refuse(why);
    }
    if (configure(&fr, why, sizeof why) != 0 || build(&fr, why, sizeof why) != 0) {
        adh_fitdata_free(&fr.fd);
        release(&fr);
        return refuse(why);
    }
    /* the output directory opened (and locked) before the work */
    const char *out = cfg->output.dir[0] ? cfg->output.dir : NULL;
    adh_outdir *od = NULL;
    if (out && !(od = adh_outdir_open(out, cfg->output.overwrite ? ADH_OUTDIR_OVERWRITE : 0, why, sizeof why))) {
        adh_fitdata_free(&fr.fd);
        release(&fr);
        return refuse(why);
    }
    if (fr.note[0] && !cfg->output.quiet)   /* a note: the fit is what it would be without them */
        adh_say(fr.note);
    cli_interrupt_catch();
    adh_ready_phase("fit");
    adh_fit_result res;
    adh_fit *f = NULL;
    adh_grid_report gr;
    int refits = 0, st;
    adh_grid_use use = fr.fs.model.kind == ADH_FIT_MODEL_RELAX ? ADH_GRID_RELAX : ADH_GRID_STATIC;
    for (;;) {
        st = fit_once(&fr, &res, &f);
        if (!f) {
            cli_interrupt_release();
            adh_outdir_close(od);
            adh_fitdata_free(&fr.fd);
            release(&fr);
            snprintf(why, sizeof why, "the fit could not start: %s", adh_strerror(st));
            return refuse(why);
        }
        adh_grid_check(&res.best, use, fr.nodes, fr.dr, &gr);
        /* a grid chosen for the start may not resolve the optimum (E and A
         * set sigma, hence the edge zone): choose again there, refit from it */
        if (gr.resolved || !adh_config_grid_auto(&cfg->spec) || refits == MAX_REFITS || st == ADH_EINTR ||
            !isfinite(res.chi2))
            break;
        if (!cfg->output.quiet)
            adh_sayf("the grid chosen for the start has %.2f nodes across the edge zone at the optimum "
                     "(%.2f needed): choosing it again there and fitting from the optimum", gr.edge_nodes,
                     1.0 / gr.limit);
        cfg->spec.mat = res.best;
        fr.fs.start = res.best;
        fr.fs.offset = res.value[ADH_FIT_OFFSET];
        fr.fs.baseline = res.value[ADH_FIT_BASELINE];
        if (fr.fs.model.kind == ADH_FIT_MODEL_TIME) {   /* the solid's: an elastic fit's are its unused starts */
            fr.fs.Einf = cfg->spec.time.Einf = res.value[ADH_FIT_EINF];
            fr.fs.tau = cfg->spec.time.tau = res.value[ADH_FIT_TAU];
        }
        if (adh_config_grid(cfg, why, sizeof why, NULL) != 0 || build(&fr, why, sizeof why) != 0)
            break;
        adh_fit_free(f);
        f = NULL;
        refits++;
    }
    cli_fit_report r = { .cfg = cfg, .fd = &fr.fd, .res = &res, .fs = &fr.fs, .model = adh_fit_model_forces(f),
                         .resid = adh_fit_residuals(f), .grid_edge_nodes = gr.edge_nodes,
                         .grid_resolved = gr.resolved, .refits = refits, .evals = fr.evals,
                         .partial = st == ADH_EINTR };
    /* the best model's whole curve, for the figure (one more evaluation) */
    r.ncurve = isfinite(res.chi2) ? adh_fit_best_curve(f, &r.ch0, &r.cF, &r.cstable) : 0;
    r.seconds = res.seconds;
    cli_fit_print(stdout, &r);
    int rc = CLI_EXIT_OK;
    if (out && isfinite(res.chi2)) {
        int wr = cli_fit_write(&r, od, cfg->output.plot, why, sizeof why);
        if (wr != 0) {
            adh_say(why);
            rc = wr == 3 ? CLI_EXIT_PLOT : CLI_EXIT_USAGE;
        }
    }
    const char *word;
    int verdict = cli_fit_verdict(&r, &word);
    if (!cfg->output.quiet && out && !isfinite(res.chi2))   /* it said "wrote fit.tsv, ..." of files not written */
        adh_sayf("%s after %zu model evaluations in %.1f s; no evaluation succeeded: nothing written "
                 "in %s", word, fr.evals, res.seconds, adh_outdir_path(od));
    else if (!cfg->output.quiet && out && rc == CLI_EXIT_OK)
        adh_sayf("%s after %zu model evaluations in %.1f s; wrote fit.tsv, fit-points.tsv, best.scene%s "
                 "in %s (open it: adhere %s/best.scene)", word, fr.evals, res.seconds, cfg->output.plot ? ", fit.png" : "",
                 adh_outdir_path(od), adh_outdir_path(od));
    else if (!cfg->output.quiet)
        adh_sayf("%s after %zu model evaluations in %.1f s", word, fr.evals, res.seconds);
    char stop[CLI_TABLES_STOPPED_LEN];
    if (!isfinite(res.chi2) && *cli_fit_model_stop(cfg, &res, fr.fs.model.kind != ADH_FIT_MODEL_STATIC, stop, sizeof stop))   /* not hidden by -q: no fit */
        adh_sayf("the model stopped: %s", stop);
    adh_outdir_close(od);
    adh_fit_free(f);
    adh_fitdata_free(&fr.fd);
    release(&fr);
    /* the handlers stay through the files and the figure: a signal there
     * stops gnuplot's wait and leaves no temporary, as in --batch */
    cli_interrupt_release();
    if (!r.partial && cli_interrupt_signal())
        adh_sayf("interrupted by signal %d after the fit had ended", cli_interrupt_signal());
    if (r.partial || cli_interrupt_signal())
        return cli_interrupt_exit();
    if (rc != CLI_EXIT_OK)
        return rc;
    return verdict ? CLI_EXIT_SOLVER : CLI_EXIT_OK;
}
