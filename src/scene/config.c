#include "scene/config.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "adhere/grid.h"
#include "adhere/models.h"
#include "adhere/rule_path.h"
#include "adhere/status.h"
#include "adhere/visco.h"

void adh_config_default(adh_config *c)
{
    memset(c, 0, sizeof *c);
    adh_run_spec *s = &c->spec;
    s->mat = adh_material_default();
    s->mat.E = 3e8; /* Figure 4: sigma = 7.50, the paper's hysteresis showcase */
    s->relax = adh_relax_settings_default();
    s->proto = adh_protocol_settings_default();
    s->mode = ADH_MODE_RELAX;
    s->grid.asked = (adh_grid_spec){ .nodes = 1000, .spacing = NAN, .graded = 0, .fine_band = NAN, .growth = 1.05,
                                     .radius = NAN, .kernel = ADH_KERNEL_PAPER, .storage = ADH_STORAGE_DENSE };
    s->grid.use = s->grid.asked;
    s->time = adh_time_settings_default();
    c->output.plot = 1;
    c->output.plots = ADH_PLOT_ALL;
    c->output.drive_speed = 1e-6;
    c->sweep.plot = ADH_SWEEP_PLOT_AUTO;
    c->sweep.run_dirs = -1;
    c->tui.cols = 100;
    c->tui.rows = 32;
}

double adh_config_start(const adh_run_spec *s)
{
    if (!isnan(s->proto.start))
        return s->proto.start;
    /* a static curve under a spring starts outside its snap-in, and so
     * does a path in physical time through it (the time rules' own start,
     * adh_visco_auto_start: the plan and the screen say where it is) */
    if ((s->mode == ADH_MODE_STATIC || s->mode == ADH_MODE_TIME) && isfinite(s->time.spring))
        return adh_visco_auto_start(&s->mat, s->time.spring, s->proto.step);
    return adh_protocol_auto_start(&s->mat, s->proto.step);
}

adh_static_settings adh_config_static_settings(const adh_run_spec *s)
{
    /* under a spring close points, as physical time's elastic path takes
     * them (one curve, one setting), polling the run's one cancel flag */
    adh_static_settings ss = adh_rule_path_static_settings(s->time.spring, s->relax.cancel);
    if (s->max_points)
        ss.max_points = s->max_points;
    return ss;
}

/* Up to max profile positions spread from the deepest turn (without turns:
 * the jump-in gap of eq 24) to half the start, each on the drive's lattice
 * start - k d so that the run really stores it. */
size_t adh_config_default_profiles(const adh_material *mat, const adh_protocol_settings *ps, double *out, size_t max)
{
    double step = ps->step;
    if (!(step > 0) || max == 0)
        return 0;
    double start = isnan(ps->start) ? adh_protocol_auto_start(mat, step) : ps->start;
    adh_derived d;
    adh_material_derive(mat, &d);
    double lo = ps->nturns ? adh_protocol_deepest_turn(ps) : d.h_star;
    double hi = 0.5 * start;
    if (!(hi > lo))
        hi = start;
    if (!(hi > lo))
        return 0;
    size_t n = 0;
    for (size_t j = 0; j < max; j++) {
        double x = max == 1 ? lo : lo + (hi - lo) * (double)j / (double)(max - 1);
        double k = round((start - x) / step);
        if (k < 0)
            k = 0;
        double h = start - k * step;     /* exactly as the protocol computes it */
        if (j == 0 && ps->nturns)
            h = lo;                       /* turns are hit exactly, on their own */
        if (n == 0 || fabs(out[n - 1] - h) > 0.5 * step)
            out[n++] = h;
    }
    return n;
}

adh_protocol_settings adh_config_protocol_for(const adh_config *c, adh_mode mode)
{
    adh_protocol_settings ps = c->spec.proto;
    /* a profile figure with no positions asked gets a spread of them, so
     * that the plan and the run agree on what is stored */
    if ((c->output.plots & ADH_PLOT_PROFILE) && ps.nprofiles == 0 && (mode == ADH_MODE_RELAX || mode == ADH_MODE_TIME))
        ps.nprofiles = adh_config_default_profiles(&c->spec.mat, &ps, ps.profiles, 6);
    return ps;
}

adh_protocol_settings adh_config_protocol(const adh_config *c)
{
    return adh_config_protocol_for(c, c->spec.mode);
}

adh_grid_use adh_config_grid_use(const adh_run_spec *s)
{
    /* physical time crosses its folds as the static curve does */
    return s->mode == ADH_MODE_STATIC || s->mode == ADH_MODE_TIME ? ADH_GRID_STATIC : ADH_GRID_RELAX;
}

void adh_config_grid_report(const adh_run_spec *s, adh_grid_report *r)
{
    adh_grid_check(&s->mat, adh_config_grid_use(s), s->grid.use.nodes, adh_config_spacing(s), r);
}

/* The choice for the softest run: N and the spacing, and graded rings with
 * their band, growth, radius and operator where a uniform grid would need
 * too many nodes. What was asked for a graded grid is kept. */
static void grid_take(adh_grid_settings *gs, const adh_rings_choice *gc)
{
    adh_grid_spec *u = &gs->use;
    u->nodes = gc->n;
    u->spacing = gc->dr;
    if (!gc->graded)
        return;
    if (!u->graded)
        u->growth = gc->ratio;
    u->graded = 1;
    u->kernel = ADH_KERNEL_RING;
    if (isnan(u->fine_band))
        u->fine_band = gc->fine;
    if (isnan(u->radius))
        u->radius = gc->rmax;
    gs->chosen_h2 = gc->hierarchical;
    if (gc->hierarchical && !gs->storage_given)
        u->storage = ADH_STORAGE_H2;
}

int adh_config_grid_auto(const adh_run_spec *s)
{
    return !s->grid.nodes_given && isnan(s->grid.asked.spacing) && s->mode != ADH_MODE_RIGID;
}

adh_kernel_storage adh_config_storage_for(const adh_run_spec *s, adh_mode mode)
{
    const adh_grid_settings *gs = &s->grid;
    if (gs->storage_given || mode == ADH_MODE_RIGID)
        return gs->use.storage;
    size_t n = adh_config_nodes(s);
    /* an automatic graded grid (adh_rings_choose) is held as H^2 in every mode */
    int h2 = gs->chosen_h2 || n > ADH_GRID_MAX_NODES ||
             (mode == ADH_MODE_RELAX && !gs->use.graded && n >= ADH_CONFIG_H2_MIN_NODES);
    return h2 ? ADH_STORAGE_H2 : ADH_STORAGE_DENSE;
}

static void grid_operator(adh_run_spec *s)
{
    if (s->mode != ADH_MODE_RIGID && !s->grid.storage_given)
        s->grid.use.storage = adh_config_storage_for(s, s->mode);
}

/* The material with the narrowest edge zone so far (a bad one is the
 * validation's to report, with its own words). */
typedef struct softest {
    adh_material m;
    double edge;
    int bad;
} softest;

static void note_material(const adh_material *m, void *ctx)
{
    softest *s = ctx;
    if (adh_material_validate(m, NULL, 0) != ADH_SUCCESS) {
        s->bad = 1;
        return;
    }
    double l = adh_edge_zone(m);
    if (l < s->edge) {
        s->edge = l;
        s->m = *m;
    }
}

/* The choice for the run of study's sweep with the narrowest edge zone. */
static int grid_choose(adh_run_spec *s, const adh_config *study, char *why, size_t whylen, unsigned *fix)
{
    adh_grid_settings *gs = &s->grid;
    softest soft = { .m = s->mat, .edge = INFINITY };
    if (study)
        adh_sweep_materials(&study->sweep, s, note_material, &soft);
    else
        note_material(&s->mat, &soft);
    if (soft.bad)
        return 0;
    double deepest = fmin(0.0, adh_protocol_deepest_turn(&s->proto));
    const adh_sweep_axis *turns = study ? adh_sweep_axis_of(&study->sweep, "protocol.turns") : NULL;
    for (size_t j = 0; turns && j < turns->n; j++)   /* a run of each turn */
        deepest = fmin(deepest, adh_sweep_value(turns, j, NULL, 0));
    adh_rings_choice gc;
    /* graded rings need the ring kernel: not when the paper's was asked for */
    int graded_ok = !(gs->kernel_given && gs->asked.kernel == ADH_KERNEL_PAPER);
    if (adh_rings_choose(&soft.m, adh_config_grid_use(s), deepest, graded_ok, &gc, why, whylen, fix) != ADH_SUCCESS)
        return -1;
    grid_take(gs, &gc);
    gs->chosen = 1;
    return 0;
}

int adh_config_choose_grid(adh_run_spec *s, const adh_config *study, char *why, size_t whylen, unsigned *fix)
{
    adh_grid_settings *gs = &s->grid;
    if (fix)
        *fix = 0;
    gs->use = gs->asked;
    gs->chosen = 0;
    gs->chosen_h2 = 0;
    int rc = adh_config_grid_auto(s) ? grid_choose(s, study, why, whylen, fix) : 0;
    if (rc != 0)
        gs->use = gs->asked;
    grid_operator(s);
    return rc;
}

int adh_config_grid(adh_config *c, char *why, size_t whylen, unsigned *fix)
{
    return adh_config_choose_grid(&c->spec, c, why, whylen, fix);
}

size_t adh_config_nodes(const adh_run_spec *s)
{
    if (!s->grid.use.graded)
        return s->grid.use.nodes;
    adh_rings_spec r = adh_config_rings(s);
    return adh_rings_spec_validate(&r, NULL, 0) == ADH_SUCCESS ? adh_rings_count(&r) : s->grid.use.nodes;
}

double adh_config_spacing(const adh_run_spec *s)
{
    const adh_grid_spec *u = &s->grid.use;
    return isnan(u->spacing) ? adh_grid_spacing_for(&s->mat, u->nodes) : u->spacing;
}

adh_rings_spec adh_config_rings(const adh_run_spec *s)
{
    const adh_grid_spec *u = &s->grid.use;
    adh_rings_spec r = { .dr = adh_config_spacing(s), .ratio = u->growth, .fine = u->fine_band, .rmax = u->radius };
    if (isnan(r.rmax)) /* the default uniform grid's, whatever the spacing */
        r.rmax = (double)u->nodes * adh_grid_spacing_for(&s->mat, u->nodes);
    if (isnan(r.fine)) {
        /* the contact expected at the deepest position (with no turn, at
         * h0 = 0), and a quarter more: the contact line sweeps fine rings only */
        double lowest = fmin(s->mat.z0, adh_protocol_deepest_turn(&s->proto));
        r.fine = fmin(r.rmax, 1.25 * adh_rings_contact_estimate(&s->mat, fmin(lowest, 0.0)));
    }
    return r;
}

int adh_config_grid_check(const adh_run_spec *s, char *why, size_t whylen)
{
    const adh_grid_spec *u = &s->grid.use;
    if (!u->graded)
        return 0;
    if (!adh_config_kernel_fits(u->kernel, u->graded)) {
        snprintf(why, whylen, "grid.grid = graded is not allowed with grid.kernel = paper (the default): the "
                 "paper's kernel assumes equal cells; use grid.kernel = ring");
        return -1;
    }
    adh_rings_spec r = adh_config_rings(s);
    return adh_rings_spec_validate(&r, why, whylen) == ADH_SUCCESS ? 0 : -1;
}

int adh_config_kernel_fits(adh_kernel_type kernel, int graded)
{
    return !(graded && kernel == ADH_KERNEL_PAPER);
}

adh_grid *adh_config_grid_alloc(const adh_run_spec *s)
{
    const adh_grid_spec *u = &s->grid.use;
    if (!u->graded)
        return adh_grid_alloc(u->nodes, adh_config_spacing(s));
    char why[256];   /* checked with a reason before; here only the verdict counts */
    if (adh_config_grid_check(s, why, sizeof why) != 0)
        return NULL;
    adh_rings_spec r = adh_config_rings(s);
    return adh_rings_alloc(&r);
}

adh_kernel *adh_config_kernel_alloc(const adh_run_spec *s, const adh_grid *g, int *status)
{
    adh_kernel_settings ks = { .type = s->grid.use.kernel, .storage = s->grid.use.storage, .cancel = s->relax.cancel };
    return adh_kernel_alloc(g, &ks, status);
}

int adh_config_same_grid(const adh_run_spec *a, const adh_run_spec *b)
{
    const adh_grid_spec *x = &a->grid.use, *y = &b->grid.use;
    if ((a->mode == ADH_MODE_RIGID) != (b->mode == ADH_MODE_RIGID))
        return 0;
    if (a->mode == ADH_MODE_RIGID)
        return 1;   /* no grid at all */
    if (x->graded != y->graded || x->kernel != y->kernel || x->storage != y->storage)
        return 0;
    if (!x->graded)
        return x->nodes == y->nodes && adh_config_spacing(a) == adh_config_spacing(b);
    adh_rings_spec r = adh_config_rings(a), s = adh_config_rings(b);
    return r.dr == s.dr && r.ratio == s.ratio && r.fine == s.fine && r.rmax == s.rmax;
}
