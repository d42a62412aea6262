#include "scene/config.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "adhere/grid.h"
#include "adhere/models.h"
#include "adhere/status.h"
#include "adhere/units.h"

void adh_config_default(adh_config *c)
{
    memset(c, 0, sizeof *c);
    c->mat = adh_material_default();
    c->mat.E = 3e8; /* Figure 4: sigma = 7.50, the paper's hysteresis showcase */
    c->nodes = 1000;
    c->spacing = NAN;
    c->kernel = ADH_KERNEL_PAPER;
    c->storage = ADH_STORAGE_DENSE;
    c->graded = 0;
    c->fine_band = NAN;
    c->growth = 1.05;
    c->grid_radius = NAN;
    c->relax = adh_relax_settings_default();
    c->proto = adh_protocol_settings_default();
    c->mode = ADH_MODE_RELAX;
    c->plot = 1;
    c->plots = ADH_PLOT_ALL;
    c->drive_speed = 1e-6;
    c->cols = 100;
    c->rows = 32;
}

adh_grid_use adh_config_grid_use(const adh_config *c)
{
    return c->mode == ADH_MODE_STATIC ? ADH_GRID_STATIC : ADH_GRID_RELAX;
}

int adh_config_grid(adh_config *cfg, char *why, size_t whylen, unsigned *fix)
{
    if (fix)
        *fix = 0;
    if (cfg->nodes_given || !isnan(cfg->spacing) || cfg->mode == ADH_MODE_RIGID)
        return 0;
    adh_config run, soft;
    double narrowest = INFINITY;
    for (size_t i = 0; i < adh_config_nruns(cfg); i++) {
        adh_config_sweep_run(cfg, i, &run);
        /* a bad material is the validation's to report, with its own words */
        if (adh_material_validate(&run.mat, NULL, 0) != ADH_SUCCESS)
            return 0;
        double l = adh_edge_zone(&run.mat);
        if (l < narrowest) {
            narrowest = l;
            soft = run;
        }
    }
    double deepest = fmin(0.0, adh_protocol_deepest_turn(&cfg->proto));
    adh_rings_choice gc;
    /* graded rings need the ring kernel: not when the paper's was asked for */
    int graded_ok = !(cfg->kernel_given && cfg->kernel == ADH_KERNEL_PAPER);
    if (adh_rings_choose(&soft.mat, adh_config_grid_use(cfg), deepest, graded_ok, &gc, why, whylen, fix) != ADH_SUCCESS)
        return -1;
    cfg->asked = (adh_grid_asked){ cfg->nodes, cfg->spacing, cfg->fine_band, cfg->growth, cfg->grid_radius,
                                   cfg->kernel, cfg->storage, cfg->graded };
    cfg->grid_chosen = 1;
    cfg->nodes = gc.n;
    cfg->spacing = gc.dr;
    if (gc.graded) {
        /* a graded grid asked for keeps its own band, growth and radius */
        if (!cfg->graded)
            cfg->growth = gc.ratio;
        cfg->graded = 1;
        cfg->kernel = ADH_KERNEL_RING;
        if (isnan(cfg->fine_band))
            cfg->fine_band = gc.fine;
        if (isnan(cfg->grid_radius))
            cfg->grid_radius = gc.rmax;
        if (gc.hierarchical && !cfg->storage_given)
            cfg->storage = ADH_STORAGE_H2;
    }
    return 0;
}

int adh_config_grid_again(adh_config *cfg, char *why, size_t whylen)
{
    if (!cfg->grid_chosen)
        return 0;
    const adh_grid_asked *a = &cfg->asked;
    cfg->nodes = a->nodes;
    cfg->spacing = a->spacing;
    cfg->fine_band = a->fine_band;
    cfg->growth = a->growth;
    cfg->grid_radius = a->grid_radius;
    cfg->kernel = a->kernel;
    cfg->storage = a->storage;
    cfg->graded = a->graded;
    cfg->grid_chosen = 0;
    if (adh_config_grid(cfg, why, whylen, NULL) != 0) {
        /* refused: the asked grid stays, and the choice is still the config's */
        cfg->grid_chosen = 1;
        return -1;
    }
    cfg->grid_chosen = 1;
    return 0;
}

double adh_config_spacing(const adh_config *c)
{
    return isnan(c->spacing) ? adh_grid_spacing_for(&c->mat, c->nodes) : c->spacing;
}

adh_rings_spec adh_config_rings(const adh_config *c)
{
    adh_rings_spec s = { .dr = adh_config_spacing(c), .ratio = c->growth, .fine = c->fine_band, .rmax = c->grid_radius };
    if (isnan(s.rmax)) /* the default uniform grid's, whatever the spacing */
        s.rmax = (double)c->nodes * adh_grid_spacing_for(&c->mat, c->nodes);
    if (isnan(s.fine)) {
        /* the contact expected at the deepest position (with no turn, at
         * h0 = 0), and a quarter more: the contact line sweeps fine rings only */
        double lowest = fmin(c->mat.z0, adh_protocol_deepest_turn(&c->proto));
        s.fine = fmin(s.rmax, 1.25 * adh_rings_contact_estimate(&c->mat, fmin(lowest, 0.0)));
    }
    return s;
}

int adh_config_grid_check(const adh_config *c, char *why, size_t whylen)
{
    if (!c->graded)
        return 0;
    if (!adh_config_kernel_fits(c->kernel, c->graded)) {
        snprintf(why, whylen, "--grid=graded is not allowed with --kernel=paper (in a scene: grid = graded with "
                 "kernel = paper, the default): the paper's kernel assumes equal cells; use --kernel=ring "
                 "(kernel = ring)");
        return -1;
    }
    adh_rings_spec s = adh_config_rings(c);
    return adh_rings_spec_validate(&s, why, whylen) == ADH_SUCCESS ? 0 : -1;
}

int adh_config_kernel_fits(adh_kernel_type kernel, int graded)
{
    return !(graded && kernel == ADH_KERNEL_PAPER);
}

int adh_config_set_grid(adh_config *c, const char *text, char *why, size_t whylen)
{
    if (strcmp(text, "uniform") != 0 && strcmp(text, "graded") != 0) {
        snprintf(why, whylen, "'%s' is not a grid: use uniform or graded", text);
        return -1;
    }
    c->graded = strcmp(text, "graded") == 0;
    return 0;
}

/* A radius of the graded grid: a length above 0. */
static int radius(const char *text, double *out, char *why, size_t whylen)
{
    double v;
    if (strcasecmp(text, "auto") == 0) {   /* back to the default, as a scene's key says */
        *out = NAN;
        return 0;
    }
    if (adh_parse_quantity(text, ADH_Q_LENGTH, &v, why, whylen) != 0)
        return -1;
    if (!(v > 0)) {
        snprintf(why, whylen, "'%s' is not allowed: use a length above 0", text);
        return -1;
    }
    *out = v;
    return 0;
}

int adh_config_set_fine_band(adh_config *c, const char *text, char *why, size_t whylen)
{
    return radius(text, &c->fine_band, why, whylen);
}

int adh_config_set_grid_radius(adh_config *c, const char *text, char *why, size_t whylen)
{
    return radius(text, &c->grid_radius, why, whylen);
}

int adh_config_set_growth(adh_config *c, const char *text, char *why, size_t whylen)
{
    double g = NAN;
    /* the ratio's limits are the rings spec's: asked of a spec that is
     * valid but for its ratio */
    int number = adh_parse_quantity(text, ADH_Q_NONE, &g, NULL, 0) == 0;
    adh_rings_spec s = { .dr = 1, .fine = 1, .ratio = g, .rmax = 1 };
    if (!number || adh_rings_spec_validate(&s, NULL, 0) != ADH_SUCCESS) {
        snprintf(why, whylen, "'%s' is not allowed: use a ratio from 1 to %g", text, ADH_RINGS_MAX_RATIO);
        return -1;
    }
    c->growth = g;
    return 0;
}

int adh_config_set_operator(adh_config *c, const char *text, char *why, size_t whylen)
{
    if (adh_kernel_storage_parse(text, &c->storage) != 0) {
        snprintf(why, whylen, "'%s' is not an operator: use dense, hmat or h2", text);
        return -1;
    }
    c->storage_given = 1;
    return 0;
}

adh_grid *adh_config_grid_alloc(const adh_config *c)
{
    if (!c->graded)
        return adh_grid_alloc(c->nodes, adh_config_spacing(c));
    char why[256];   /* checked with a reason before; here only the verdict counts */
    if (adh_config_grid_check(c, why, sizeof why) != 0)
        return NULL;
    adh_rings_spec s = adh_config_rings(c);
    return adh_rings_alloc(&s);
}

adh_kernel *adh_config_kernel_alloc(const adh_config *c, const adh_grid *g, int *status)
{
    return adh_kernel_alloc_stored_cancel(g, c->kernel, c->storage, c->relax.cancel, status);
}

const char *adh_sweep_name(adh_sweep_kind kind)
{
    switch (kind) {
    case ADH_SWEEP_E: return "E";
    case ADH_SWEEP_SIGMA: return "sigma";
    case ADH_SWEEP_EPS: return "eps";
    case ADH_SWEEP_NONE: break;
    }
    return "";
}

size_t adh_config_nruns(const adh_config *c)
{
    return c->sweep.kind == ADH_SWEEP_NONE ? 1 : c->sweep.n;
}

void adh_config_sweep_run(const adh_config *c, size_t i, adh_config *run)
{
    *run = *c;
    memset(&run->sweep, 0, sizeof run->sweep);
    if (c->sweep.kind == ADH_SWEEP_NONE || i >= c->sweep.n)
        return;
    double v = c->sweep.values[i];
    switch (c->sweep.kind) {
    case ADH_SWEEP_E:
        run->mat.E = v;
        break;
    case ADH_SWEEP_SIGMA:
        run->mat.E = adh_material_modulus_at_sigma(&c->mat, v);
        break;
    case ADH_SWEEP_EPS:
        run->relax.eps = v;
        break;
    case ADH_SWEEP_NONE:
        break;
    }
}
