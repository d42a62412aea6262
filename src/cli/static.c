#include "cli/static.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "adhere/grid.h"
#include "adhere/status.h"
#include "adhere/units.h"

int cli_static_run(const adh_run_spec *spec, const adh_grid *g, const adh_kernel *k,
                   adh_step_cb cb, void *ctx, adh_run *run, adh_static_result *res)
{
    adh_static_settings s = adh_config_static_settings(spec);
    /* The same start as the relaxation run, so the two curves share an
     * axis; the drive ends the curve at the protocol's deepest turn. */
    adh_protocol_settings ps = spec->proto;
    ps.start = adh_config_start(spec);
    return adh_runner_static(g, k, &spec->mat, &s, &ps, cb, ctx, run, res);
}

int cli_static_reference_spec(const adh_run_spec *spec, adh_run_spec *ss, char *why, size_t whylen)
{
    *ss = *spec;
    ss->mode = ADH_MODE_STATIC;
    why[0] = '\0';
    /* a grid that follows the material is chosen again for the static
     * curve's finer limit (0.3 edge-zone widths against the relaxation's
     * 0.45); a grid that was given, or a static grid beyond the budget,
     * stays the relaxation's and is checked against that limit */
    if (adh_config_grid_auto(spec) && adh_config_choose_grid(ss, NULL, why, whylen, NULL) != 0) {
        ss->grid = spec->grid;
        why[0] = '\0';
    }
    /* and the static mode's operator on it (dense where the relaxation
     * took H^2 on a uniform grid: its dense LU is the oracle) */
    if (!ss->grid.storage_given)
        ss->grid.use.storage = adh_config_storage_for(ss, ADH_MODE_STATIC);
    adh_grid_report gr;
    adh_grid_check(&ss->mat, ADH_GRID_STATIC, adh_config_nodes(ss), adh_config_spacing(ss), &gr);
    if (!gr.resolved)
        adh_grid_unresolved_sentence(&gr, why, whylen);
    return gr.resolved;
}

/* Whether ss's grid (and kernel type) is spec's. */
static int same_rings(const adh_run_spec *ss, const adh_run_spec *spec)
{
    const adh_grid_spec *a = &ss->grid.use, *b = &spec->grid.use;
    adh_rings_spec ra = adh_config_rings(ss), rb = adh_config_rings(spec);
    return adh_config_nodes(ss) == adh_config_nodes(spec) && a->graded == b->graded && a->kernel == b->kernel &&
           ra.dr == rb.dr && (!a->graded || (ra.fine == rb.fine && ra.rmax == rb.rmax && ra.ratio == rb.ratio));
}

/* ... and held the same way: the relaxation's grid and kernel serve. */
static int same_grid(const adh_run_spec *ss, const adh_run_spec *spec)
{
    return same_rings(ss, spec) && ss->grid.use.storage == spec->grid.use.storage;
}

int cli_static_reference(const adh_run_spec *spec, const adh_grid *g, const adh_kernel *k, adh_run *ref,
                         adh_static_result *res, int *resolved, char *why, size_t whylen)
{
    adh_run_spec ss;
    *resolved = cli_static_reference_spec(spec, &ss, why, whylen);
    if (same_grid(&ss, spec))
        return cli_static_run(&ss, g, k, NULL, NULL, ref, res);
    int kst = ADH_ENOMEM;
    adh_grid *sg = adh_config_grid_alloc(&ss);
    adh_kernel *sk = sg ? adh_config_kernel_alloc(&ss, sg, &kst) : NULL;
    int rc = sk ? cli_static_run(&ss, sg, sk, NULL, NULL, ref, res) : kst;
    if (!sk) {
        ref->status = rc;
        ref->interrupted = rc == ADH_EINTR;
    }
    adh_kernel_free(sk);
    adh_grid_free(sg);
    return rc;
}

void cli_static_reference_plan(FILE *f, const adh_run_spec *spec)
{
    adh_run_spec ss;
    char why[1024];
    int resolved = cli_static_reference_spec(spec, &ss, why, sizeof why);
    adh_grid *g = adh_config_grid_alloc(&ss);
    char dr[64], rmax[64];
    adh_format_quantity(adh_config_spacing(&ss), ADH_Q_LENGTH, 4, dr, sizeof dr);
    adh_format_quantity(g ? g->rmax : NAN, ADH_Q_LENGTH, 4, rmax, sizeof rmax);
    const adh_grid_spec *u = &ss.grid.use;
    /* the relaxation's grid may be held another way for the static curve
     * (dense where the relaxation takes H^2 on a uniform grid) */
    int rings = same_rings(&ss, spec), own = rings && !same_grid(&ss, spec);
    fprintf(f, "reference: the static curve on %s %s grid of %zu %s (spacing %s, Rmax %s, %s kernel, %s%s): %s%s\n",
            rings ? "the relaxation's" : "its own", u->graded ? "graded" : "uniform",
            g ? g->n : adh_config_nodes(&ss), u->graded ? "rings" : "nodes", dr, rmax, adh_kernel_name(u->kernel),
            adh_kernel_storage_name(u->storage), own ? ", a kernel of its own" : "",
            resolved ? "resolved (the static limit is 0.3 l)" : "NOT resolved: ", resolved ? "" : why);
    adh_grid_free(g);
}
