#include "cli/fitreport.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/kernel.h"
#include "adhere/models.h"
#include "adhere/params.h"
#include "adhere/status.h"
#include "adhere/units.h"
#include "cli/tables.h"
#include "plot/fitplot.h"
#include "plot/outdir.h"
#include "scene/text.h"

static const char *const units[ADH_FIT_NPARAM] = { "Pa", "J", "m", "m", "m", "N", "Pa", "s" };
static const adh_quantity quantities[ADH_FIT_NPARAM] = { ADH_Q_PRESSURE, ADH_Q_ENERGY, ADH_Q_LENGTH, ADH_Q_LENGTH,
                                                         ADH_Q_LENGTH, ADH_Q_FORCE, ADH_Q_PRESSURE, ADH_Q_TIME };

static int time_model(const cli_fit_report *r)
{
    return r->fs->model.kind == ADH_FIT_MODEL_TIME;
}

/* The parameters the report lists: the solid's only with its model. */
static int listed(const cli_fit_report *r, int p)
{
    return time_model(r) || p < ADH_FIT_EINF;
}

/* A parameter's name as the model calls it: the solid's E is E0. */
static const char *pname(const cli_fit_report *r, int p)
{
    return p == ADH_FIT_E && time_model(r) ? "E0" : adh_fit_param_name((adh_fit_param)p);
}

static const char *model_word(const cli_fit_report *r, int noun)
{
    adh_fit_model_kind k = r->fs->model.kind;
    return k == ADH_FIT_MODEL_RELAX ? (noun ? "relaxation" : "relax")
         : k == ADH_FIT_MODEL_TIME ? (noun ? "physical-time" : "time") : "static";
}

static int is_free(const cli_fit_report *r, int p)
{
    return (r->res->free & 1u << p) != 0;
}

int cli_fit_verdict(const cli_fit_report *r, const char **word)
{
    const adh_fit_result *res = r->res;
    unsigned flags = 0;
    for (int i = 0; i < ADH_FIT_NPARAM; i++)
        flags |= res->flags[i];
    *word = r->partial ? "partial (interrupted: the best point so far)"
          : !isfinite(res->chi2) ? "failed (the model could not be evaluated)"
          : flags ? "unidentifiable (a parameter is not determined by these data: not a fit)"
          : res->status == ADH_EMAXITER ? "not converged (iteration cap)"
          : res->status != ADH_SUCCESS ? "failed"
          /* the model's numbers at the optimum are not converged in the
           * grid: its values can sit several standard errors off (-N 251
           * --spacing=4nm: E 1.2 % from the resolved fit's, SE 0.19 %) */
          : !r->grid_resolved && !r->cfg->spec.grid.force
              ? "not resolved (the grid does not resolve the contact's edge zone at the optimum: give a finer one, "
                "or --force to take it)"
          : res->chi2_red > CLI_FIT_POOR_CHI2 ? "poor fit (the residuals are well above the data's own scatter)"
          : "fit";
    return strcmp(*word, "fit") != 0;
}

const char *cli_fit_model_stop(const adh_config *cfg, const adh_fit_result *res, int relax_model, char *buf,
                               size_t len)
{
    buf[0] = '\0';
    if (!res->failed || res->model_status == ADH_SUCCESS)
        return buf;
    /* fit's own words: the drive (turns, start, step) follows the data, not
     * a flag; the relaxation is --model's, not --mode's */
    unsigned grid = ADH_FIX_NODES | ADH_FIX_SPACING | ADH_FIX_GRID_RADIUS | ADH_FIX_FINE_BAND | ADH_FIX_FORCE;
    char reason[CLI_TABLES_REASON_LEN];
    cli_tables_reason(cfg, res->model_why, res->model_fix & grid, reason, sizeof reason);
    snprintf(buf, len, "%s%s", adh_strerror(res->model_status), *reason ? ": " : "");
    adh_text_cat(buf, len, reason);
    adh_text_cat(buf, len, *reason && res->model_fix & ADH_FIX_MODE && !relax_model ? " (--model=relax)" : "");
    return buf;
}

static void value_text(int p, double v, char *buf, size_t len)
{
    if (p == ADH_FIT_OFFSET || p == ADH_FIT_BASELINE) {   /* may be 0 or negative */
        if (p == ADH_FIT_OFFSET)
            snprintf(buf, len, "%.5g nm", v * 1e9);
        else
            snprintf(buf, len, "%.5g nN", v * 1e9);
        return;
    }
    adh_format_quantity(v, quantities[p], 5, buf, len);
}

static void print_params(FILE *out, const cli_fit_report *r)
{
    const adh_fit_result *res = r->res;
    fprintf(out, "%-9s %-14s %-24s %s\n", "parameter", "best", "standard error", "start");
    for (int i = 0; i < ADH_FIT_NPARAM; i++) {
        char v[64], s[64], st[64], se[80];
        if (!listed(r, i))
            continue;
        double start[ADH_FIT_NPARAM] = { r->fs->start.E, r->fs->start.A, r->fs->start.z0, r->fs->start.R,
                                         r->fs->offset, r->fs->baseline, r->fs->Einf, r->fs->tau };
        value_text(i, res->value[i], v, sizeof v);
        value_text(i, start[i], st, sizeof st);
        if (!is_free(r, i)) {
            fprintf(out, "%-9s %-14s %-24s (fixed)\n", pname(r, i), v, "-");
            continue;
        }
        value_text(i, res->se[i], s, sizeof s);
        if (!isfinite(res->se[i]))   /* none to give: "nan Pa (nan %)" said nothing of why */
            snprintf(se, sizeof se, "%s", r->partial ? "- (interrupted)" : "-");
        else if (i <= ADH_FIT_R || i >= ADH_FIT_EINF)
            snprintf(se, sizeof se, "%s (%.2g %%)", s, 100 * res->se[i] / res->value[i]);
        else
            snprintf(se, sizeof se, "%s", s);
        fprintf(out, "%-9s %-14s %-24s %s\n", pname(r, i), v, se, st);
    }
    adh_derived d;
    adh_material_derive(&res->best, &d);
    fprintf(out, "derived: gamma = A/(16 pi z0^2) = %.4g mJ/m^2, sigma = %.4g, JKR pull-off %.4g nN\n",
            d.gamma * 1e3, d.sigma, d.F_jkr * 1e9);
    if (time_model(r))   /* what a curve much shorter than tau determines (ADH_FIT_SLOW) */
        fprintf(out, "derived: creep rate (1/E0 - 1/Einf)/tau = %.4g 1/(GPa s); the data %.4g s in contact\n",
                1e9 * res->creep_rate, res->contact_time);
}

static void print_warnings(FILE *out, const cli_fit_report *r)
{
    const adh_fit_result *res = r->res;
    for (int i = 0; i < ADH_FIT_NPARAM; i++)
        for (int j = i + 1; j < ADH_FIT_NPARAM; j++) {
            double c = res->corr[i][j];
            if (!is_free(r, i) || !is_free(r, j) || !(fabs(c) > CLI_FIT_CORR_WARN))
                continue;
            int az = (i == ADH_FIT_A && j == ADH_FIT_Z0);
            fprintf(out, "warning: %s and %s are correlated at %.4f: the data fix a combination of them, not each "
                    "alone%s; fix one (leave it out of --free)\n", pname(r, i), pname(r, j), c,
                    az ? " (A and z0 trade off: the surface energy A/(16 pi z0^2) and the range z0 act together, "
                         "and a force curve fixes mainly the energy)" : "");
        }
    if (res->flags[ADH_FIT_TAU] & ADH_FIT_SLOW)
        fprintf(out, "warning: E0 and tau are not determined apart: tau = %.4g s is longer than the %.4g s the data "
                "spend in contact, over which the solid creeps as at its start, 1/Einf + (1/E0 - 1/Einf) t/tau: the "
                "curve fixes Einf and the creep rate (1/E0 - 1/Einf)/tau, and chi2 is flat along E0 and tau together "
                "whatever their standard errors say; fix one of them (leave it out of --free), or fit a curve "
                "driven slower\n", res->value[ADH_FIT_TAU], res->contact_time);
    for (int i = 0; i < ADH_FIT_NPARAM; i++) {
        if (res->flags[i] & ADH_FIT_AT_LIMIT)
            fprintf(out, "warning: %s ran to the limit of its search range: unidentifiable from these data, not a "
                    "fit value\n", pname(r, i));
        else if (res->flags[i] & ADH_FIT_UNDETERMINED)
            fprintf(out, "warning: %s is not determined: its standard error is as large as the value itself (or "
                    "the Jacobian is singular): unidentifiable from these data\n", pname(r, i));
    }
    if (r->fs->model.kind == ADH_FIT_MODEL_RELAX)
        fprintf(out, "warning: with the relaxation model the standard errors are not to be trusted: its jumps move by "
                "whole drive steps as the parameters change, so chi2 is piecewise and the Jacobian's differences "
                "can span a jump (the values are good to about a step's worth)\n");
    if (time_model(r))
        fprintf(out, "warning: with the physical-time model the standard errors may be too small by about 1.2 "
                "(measured over 24 synthetic curves: the errors over the standard errors had an rms of 1.18 to 1.25, "
                "1 +- 0.14 expected of honest ones, the largest 2.9)\n");
    if (!r->grid_resolved)
        fprintf(out, "warning: the grid does not resolve the contact's edge zone at the optimum (%.2f nodes across "
                "it): the model's numbers may be off by more than 1 %%\n", r->grid_edge_nodes);
}

/* None where the fit has no Jacobian at its best point (interrupted
 * before one): a matrix of nan said nothing of why. */
static void print_corr(FILE *out, const cli_fit_report *r)
{
    for (int i = 0; i < ADH_FIT_NPARAM; i++)
        if (is_free(r, i) && !isfinite(r->res->corr[i][i])) {
            fprintf(out, "correlation: -%s\n", r->partial ? " (interrupted)" : "");
            return;
        }
    fprintf(out, "correlation:");
    for (int j = 0; j < ADH_FIT_NPARAM; j++)
        if (is_free(r, j))
            fprintf(out, " %9s", pname(r, j));
    fprintf(out, "\n");
    for (int i = 0; i < ADH_FIT_NPARAM; i++) {
        if (!is_free(r, i))
            continue;
        fprintf(out, "  %-9s  ", pname(r, i));
        for (int j = 0; j < ADH_FIT_NPARAM; j++)
            if (is_free(r, j))
                fprintf(out, " %9.4f", r->res->corr[i][j]);
        fprintf(out, "\n");
    }
}

void cli_fit_print(FILE *out, const cli_fit_report *r)
{
    const adh_fit_result *res = r->res;
    const adh_config *cfg = r->cfg;
    const char *word;
    cli_fit_verdict(r, &word);
    if (r->partial)
        fprintf(out, "# PARTIAL: interrupted, the best point so far\n");
    size_t napp = 0;
    for (size_t i = 0; i < r->fd->d.n; i++)
        napp += r->fd->d.dir[i] > 0;
    fprintf(out, "fit: %zu free parameter%s, %s model, %zu points (%zu approach, %zu retract; %zu in contact)\n",
            res->nfree, res->nfree == 1 ? "" : "s", model_word(r, 1),
            res->n, napp, res->n - napp, r->fd->ncontact);
    fprintf(out, "grid: %s, N = %zu, spacing %.3g nm%s; at the optimum %.2f nodes across the contact's edge zone (%s)%s\n",
            cfg->spec.grid.use.graded ? "graded" : "uniform", cfg->spec.grid.use.nodes, adh_config_spacing(&cfg->spec) * 1e9,
            adh_config_grid_auto(&cfg->spec) ? ", chosen for the start values" : ", as given",
            r->grid_edge_nodes, r->grid_resolved ? "resolved" : "NOT resolved",
            r->refits ? ", chosen again at the optimum" : "");
    print_params(out, r);
    print_corr(out, r);
    fprintf(out, "chi2 per point: %.4g N^2 (rms residual %.4g nN); the data's own scatter %.4g nN: chi2 per degree "
            "of freedom against it %.3g (about 1 when the model fits)\n", res->chi2 / (double)res->n, res->rms * 1e9,
            res->noise * 1e9, res->chi2_red);
    fprintf(out, "model evaluations: %zu (%zu failed), %zu iterations, %.2f s\n", r->evals, res->failed,
            res->iterations, r->seconds);
    char stop[CLI_TABLES_STOPPED_LEN];
    if (*cli_fit_model_stop(r->cfg, res, r->fs->model.kind != ADH_FIT_MODEL_STATIC, stop, sizeof stop))
        fprintf(out, "the last model evaluation that failed stopped: %s\n", stop);
    print_warnings(out, r);
    fprintf(out, "result: %s\n", word);
}

static int write_fit_tsv(FILE *f, const void *ctx)
{
    const cli_fit_report *r = ctx;
    const adh_fit_result *res = r->res;
    const char *word;
    cli_fit_verdict(r, &word);
    fprintf(f, "# adhere %s fit\n", ADH_VERSION);
    if (r->partial)
        fprintf(f, "# PARTIAL: interrupted, the best point so far\n");
    fprintf(f, "# result: %s\n", word);
    if (r->missing && r->missing[0])
        fprintf(f, "# not written: %s\n", r->missing);
    for (const adh_measured *m = r->cfg->output.measured; m; m = m->next)
        fprintf(f, "# data: %s (%zu points)\n", m->name, m->n);
    fprintf(f, "# model: %s; grid N = %zu, spacing %.6g m; %zu model evaluations, %.3f s\n",
            model_word(r, 0), r->cfg->spec.grid.use.nodes,
            adh_config_spacing(&r->cfg->spec), r->evals, r->seconds);
    char stop[CLI_TABLES_STOPPED_LEN];
    if (*cli_fit_model_stop(r->cfg, res, r->fs->model.kind != ADH_FIT_MODEL_STATIC, stop, sizeof stop))
        fprintf(f, "# the last model evaluation that failed stopped: %s\n", stop);
    fprintf(f, "# chi2 %.9g N^2, %zu points, chi2/point %.9g N^2, scatter %.9g N, chi2/dof against it %.6g\n",
            res->chi2, res->n, res->chi2 / (double)res->n, res->noise, res->chi2_red);
    fprintf(f, "parameter\tvalue\tstd_error\tunit\tfree\tflag");
    for (int j = 0; j < ADH_FIT_NPARAM; j++)
        if (is_free(r, j))
            fprintf(f, "\tcorr_%s", pname(r, j));
    fprintf(f, "\n");
    for (int i = 0; i < ADH_FIT_NPARAM; i++) {
        if (!listed(r, i))
            continue;
        const char *flag = res->flags[i] & ADH_FIT_AT_LIMIT ? "at_limit"
                         : res->flags[i] & ADH_FIT_UNDETERMINED ? "undetermined"
                         : res->flags[i] & ADH_FIT_SLOW ? "creep_rate_only" : "-";
        fprintf(f, "%s\t%.10g\t%.6g\t%s\t%d\t%s", pname(r, i), res->value[i], res->se[i],
                units[i], is_free(r, i), flag);
        for (int j = 0; j < ADH_FIT_NPARAM; j++)
            if (is_free(r, j))
                fprintf(f, "\t%.6g", res->corr[i][j]);
        fprintf(f, "\n");
    }
    return 0;
}

static int write_points_tsv(FILE *f, const void *ctx)
{
    const cli_fit_report *r = ctx;
    const adh_fitdata *fd = r->fd;
    fprintf(f, "# adhere %s fit: each measured point, the best model there and the residual (SI units)\n",
            ADH_VERSION);
    if (r->partial)
        fprintf(f, "# PARTIAL: interrupted, the best point so far\n");
    fprintf(f, "file\tline\tposition\tF\tdirection\tcontact\tF_model\tresidual\n");
    for (size_t i = 0; i < fd->d.n; i++)
        fprintf(f, "%s\t%zu\t%.10g\t%.10g\t%s\t%d\t%.10g\t%.6g\n", fd->file[i]->name, fd->line[i], fd->x[i],
                fd->F[i], adh_measured_dir_name(fd->dir[i]), fd->contact[i],
                r->model[i] + r->res->value[ADH_FIT_BASELINE], r->resid[i]);
    return 0;
}

/* The physical-time model's drive (in [protocol]). */
static void write_scene_drive(FILE *f, const cli_fit_report *r)
{
    const adh_visco_drive *dr = &r->fs->model.visco.drive;
    fprintf(f, "speed = %.10gm/s, %.10gm/s\ndwell_time = %.10gs\n", dr->speed_in, dr->speed_out, dr->dwell);
    if (isfinite(dr->spring))
        fprintf(f, "spring = %.10gN/m\n", dr->spring);
}

/* A scene the TUI and --batch open: the best material, the fit's grid
 * and its deepest turn. */
static int write_scene(FILE *f, const void *ctx)
{
    const cli_fit_report *r = ctx;
    const adh_config *cfg = r->cfg;
    const adh_material *m = &r->res->best;
    const char *word;
    cli_fit_verdict(r, &word);
    fprintf(f, "# adhere fit's best model (%s)%s\n", word, r->partial ? " # PARTIAL" : "");
    for (const adh_measured *d = cfg->output.measured; d; d = d->next)
        fprintf(f, "# fitted to %s\n", d->name);
    fprintf(f, "# position offset %.6g nm, force baseline %.6g nN: model h0 = measured - offset\n",
            r->res->value[ADH_FIT_OFFSET] * 1e9, r->res->value[ADH_FIT_BASELINE] * 1e9);
    fprintf(f, "\n[scene]\ntitle = best fit: %s = %.4g GPa, A = %.4g J\nmode = %s\n", pname(r, ADH_FIT_E),
            m->E * 1e-9, m->A, model_word(r, 0));
    if (time_model(r))   /* the solid */
        fprintf(f, "\n[material]\nmaterial = sls\nE0 = %.10gPa\nEinf = %.10gPa\ntau = %.10gs\n", m->E,
                r->res->value[ADH_FIT_EINF], r->res->value[ADH_FIT_TAU]);
    else
        fprintf(f, "\n[material]\nE = %.10gPa\n", m->E);
    fprintf(f, "A = %.10gJ\nz0 = %.10gm\nR = %.10gm\n", m->A, m->z0, m->R);
    if (!cfg->spec.grid.use.graded)
        fprintf(f, "\n[grid]\nnodes = %zu\nspacing = %.10gm\nkernel = %s\n", cfg->spec.grid.use.nodes, adh_config_spacing(&cfg->spec),
                adh_kernel_name(cfg->spec.grid.use.kernel));
    fprintf(f, "\n[protocol]\nstep = %.10gm\nturns = %.10gm\n", cfg->spec.proto.step,
            time_model(r) ? r->res->turn : cfg->spec.proto.turns[0]);
    if (time_model(r)) {   /* the drive the data were fitted at, from the model's start */
        fprintf(f, "start = %.10gm\n", r->res->start);
        write_scene_drive(f, r);
        /* the tolerance the model was fitted at (eval_time's), which a
         * rerun at the default 5e-5 left for another model */
        fprintf(f, "\n[solver]\ntime_tol = %.10g\n", adh_fit_model_time_tol(r->fs->model.visco.s.tol));
    }
    return 0;
}

/* fit.png: the points, the best model's curve and the residuals. 0, or -1
 * with why. */
static int write_png(const cli_fit_report *r, adh_outdir *dir, char *why, size_t whylen)
{
    size_t n = r->fd->d.n, nc = r->ncurve;
    double *cx = malloc((nc ? nc : 1) * sizeof *cx), *cF = malloc((nc ? nc : 1) * sizeof *cF);
    if (!cx || !cF) {
        free(cx);
        free(cF);
        snprintf(why, whylen, "out of memory for fit.png");
        return -1;
    }
    /* the model in the measured coordinates */
    for (size_t i = 0; i < nc; i++) {
        cx[i] = r->ch0[i] + r->res->value[ADH_FIT_OFFSET];
        cF[i] = r->cF[i] + r->res->value[ADH_FIT_BASELINE];
    }
    char title[512], msg[960];   /* with "fit.png: ", within the caller's 1024 */
    char solid[96] = "";   /* the time model's fit is of the solid: its Einf and tau in the title too */
    if (time_model(r))
        snprintf(solid, sizeof solid, ", Einf = %.4g GPa, tau = %.4g s", r->res->value[ADH_FIT_EINF] * 1e-9,
                 r->res->value[ADH_FIT_TAU]);
    snprintf(title, sizeof title, "adhere fit: %s = %.4g GPa%s, A = %.4g J (%s model)", pname(r, ADH_FIT_E),
             r->res->best.E * 1e-9, solid, r->res->best.A, model_word(r, 1));
    adh_fitplot p = { .n = n, .x = r->fd->x, .F = r->fd->F, .resid = r->resid, .dir = r->fd->dir, .ncurve = nc,
                      .cx = cx, .cF = cF, .stable = r->cstable, .title = title, .style = r->cfg->output.gnuplot_style };
    int rc = adh_fitplot_write(&p, dir, r->fs->cancel, msg, sizeof msg);
    free(cx);
    free(cF);
    if (rc != 0)
        snprintf(why, whylen, "fit.png: %s", msg);
    return rc != 0 ? -1 : 0;
}

/* One file that was not written: its name to missing, the reason to why. */
static void not_written(const char *name, const char *msg, char *missing, size_t mlen, char *why, size_t whylen)
{
    size_t m = strlen(missing), w = strlen(why);
    snprintf(missing + m, mlen - m, "%s%s", m ? ", " : "", name);
    snprintf(why + w, whylen - w, "%s%s", w ? "; " : "", msg);
}

int cli_fit_write(const cli_fit_report *r, adh_outdir *dir, int plot, char *why, size_t whylen)
{
    /* every file is tried: a full disk that stops one (fit-points.tsv is
     * the large one) leaves the others, best.scene above all; fit.tsv,
     * written last, names what is missing, as a run's summary.tsv does */
    cli_fit_report last = *r;
    char missing[128] = "", msg[1024];
    int rc = 0;
    why[0] = '\0';
    if (adh_outdir_write(dir, "fit-points.tsv", write_points_tsv, r, msg, sizeof msg) != 0) {
        not_written("fit-points.tsv", msg, missing, sizeof missing, why, whylen);
        rc = 2;
    }
    if (adh_outdir_write(dir, "best.scene", write_scene, r, msg, sizeof msg) != 0) {
        not_written("best.scene", msg, missing, sizeof missing, why, whylen);
        rc = 2;
    }
    if (plot && write_png(r, dir, msg, sizeof msg) != 0) {
        not_written("fit.png", msg, missing, sizeof missing, why, whylen);
        rc = rc ? rc : 3;
    }
    last.missing = missing;
    if (adh_outdir_write(dir, "fit.tsv", write_fit_tsv, &last, msg, sizeof msg) != 0) {
        not_written("fit.tsv", msg, missing, sizeof missing, why, whylen);
        rc = 2;
    }
    return rc;
}
