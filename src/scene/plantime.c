/* The plan of a run in physical time (mode time): what `adhere --plan`
 * says of the material, the instrument and the time the protocol spans. */
#include "scene/plan.h"

#include <math.h>
#include <stdio.h>

#include "adhere/models.h"
#include "adhere/params.h"
#include "adhere/static.h"
#include "adhere/units.h"
#include "adhere/visco.h"

void adh_plan_time_print(FILE *f, const adh_config *cfg)
{
    adh_run_spec s;
    adh_config_sweep_run(cfg, 0, &s);
    adh_visco_rule_settings v;
    adh_config_visco(&s, &v);
    char a[64], b[64], c[64];
    if (s.time.sls && !adh_visco_rothe_applies(&v.sls, &v.drive, &v.s))
        fprintf(f, "mode: time (physical time: the path integrated by IDAS with error control, relative tolerance %g; "
                   "each fold or spring instability crossed as a jump)\n", v.s.tol);
    else if (s.time.sls)
        fprintf(f, "mode: time (physical time: the path integrated by Rothe steps, each a static problem at the "
                   "drive's h0, q's error held below %g; each fold crossed as a jump)\n",
                ADH_ROTHE_TOL_FACTOR * v.s.tol);
    else
        fprintf(f, "mode: time (physical time, no time integration needed: an elastic solid without inertia is "
                   "rate-independent; the static curve followed by continuation, as mode static does, the path the "
                   "base drives along it read off it, each jump where the base turns on it, dF/dh0 = k through a "
                   "spring; time from the base's travel and the dwells)\n");
    if (s.time.sls && adh_visco_tol_loose(v.s.tol))
        fprintf(f, "tolerance: %s, looser than the default %g, up to which halving it moves the numbers by under "
                   "0.5 %%: the run will be marked unconverged\n", adh_format_shortest(v.s.tol, a, sizeof a),
                ADH_VISCO_TOL_DEFAULT);
    adh_format_quantity(v.sls.E0, ADH_Q_PRESSURE, 4, a, sizeof a);
    if (s.time.sls) {
        adh_material inf = s.mat;
        inf.E = v.sls.Einf;
        adh_derived d0, di;
        adh_material_derive(&s.mat, &d0);
        adh_material_derive(&inf, &di);
        adh_format_quantity(v.sls.Einf, ADH_Q_PRESSURE, 4, b, sizeof b);
        adh_format_quantity(v.sls.tau, ADH_Q_TIME, 4, c, sizeof c);
        fprintf(f, "material: standard linear solid: E0 = %s (relaxed, sigma %.4g), Einf = %s%s (instantaneous, "
                   "sigma %.4g), tau = %s\n", a, d0.sigma, b, isnan(s.time.Einf) ? " (auto: 10 E0)" : "",
                di.sigma, c);
    } else {
        fprintf(f, "material: elastic, E = %s (time only labels the base's position: the curve is the static one)\n", a);
    }
    adh_format_quantity(v.drive.speed_in, ADH_Q_SPEED, 4, a, sizeof a);
    adh_format_quantity(v.drive.speed_out, ADH_Q_SPEED, 4, b, sizeof b);
    adh_format_quantity(v.drive.dwell, ADH_Q_TIME, 4, c, sizeof c);
    fprintf(f, "drive: the base at %s approaching, %s retracting; held %s at each turn\n", a, b, c);
    if (isfinite(v.drive.spring)) {
        adh_format_quantity(v.drive.spring, ADH_Q_STIFFNESS, 4, a, sizeof a);
        fprintf(f, "spring: k = %s between the base and the sphere (h0 = base + F/k; it snaps where dF/dh0 = k)\n", a);
    } else {
        fprintf(f, "spring: none (displacement control: h0 is the base)\n");
    }
    /* from the start to the deepest turn and back to the start (a spring's
     * run starts further out; a contact still held goes on past it) */
    double start = adh_config_start(&s), deep = adh_protocol_deepest_turn(&s.proto);
    if (s.proto.nturns && s.proto.unload) {
        double T = (start - deep) / v.drive.speed_in + (double)s.proto.nturns * v.drive.dwell +
                   (start - deep) / v.drive.speed_out;
        adh_format_quantity(T, ADH_Q_TIME, 4, a, sizeof a);
        fprintf(f, "span: about %s of physical time from the start to the deepest turn and back (%.3g tau)%s\n", a, T / v.sls.tau,
                isfinite(v.drive.spring) ? ", more from a spring's start" : "");
    }
}

/* Measured on the Figure 4 sphere (sigma0 = 7.5, N = 648, tau = 1 ms) and
 * on sigma0 = 2.25 (N = 400 of 3 nm), Einf/E0 = 1 ... 1000, 1 nm/s ...
 * 1 mm/s (docs/viscoelastic.md: planned 0.68-1.73 of the run's steps from
 * Einf = 3 E0 up): the contact line moves about 0.068 edge zones a step,
 * of the edge zone at an effective modulus E0 (1 + 2 y),
 * y = sqrt(10 v tau / l(E0)), up to Einf; out of contact about 60 steps a
 * branch, 40 more for a dwell; steps rejected or spent on jumps add about
 * 15 %. The effective modulus is no interpolation between E0 and Einf:
 * past Einf ~ 10 E0 the steps do not depend on Einf at all (at 100 nm/s
 * 1530, 1530 and 1547 steps at Einf = 10, 100 and 1000 E0): the solid's
 * creep, J(t) = 1/Einf + (1/E0 - 1/Einf)(1 - e^-t/tau), is then all in its
 * delayed part, whose pace is tau's, not Einf's (the former
 * E0^(1-f) Einf^f, f = y/(1+y), planned 170 steps for 680 at 1000 E0). A
 * branch in contact takes at least about 60 steps (measured 50-74 where
 * Einf is large and the drive fast, the sphere then nearly as stiff as
 * DMT's, with no edge zone to follow: the contact's growth itself). */
#define TIME_EDGE_PER_STEP 0.068
#define TIME_SPEED_STIFFENING 2.0
#define TIME_CONTACT_MIN_STEPS 60.0
#define TIME_FREE_STEPS 60.0
#define TIME_DWELL_STEPS 40.0
#define TIME_EXTRA 1.15

/* Near the elastic limit (Einf close to E0) the instantaneous problem has
 * the relaxed one's lattice folds, one at each ring the contact line
 * crosses, and the integrator crawls round each or jumps it: measured at
 * sigma = 7.5 and 2.25, about 8 steps a ring loading and 16 unloading when
 * elastic, 3.3 times the steps of the edge-zone rule above; 2.3 times at
 * Einf = 1.1 E0, 1.35 at 2 E0, none at 10 E0 (docs/viscoelastic.md). */
static double lattice_factor(const adh_visco_rule_settings *v)
{
    double r = v->sls.Einf / v->sls.E0;
    return 1.0 + 2.5 / (1.0 + (r - 1.0) / 0.15);
}

/* The edge zone at the effective modulus E0 (1 + 2 y), y = sqrt(rate tau
 * / l(E0)) (rate: 10 v, v the contact line's speed), up to cap: the length
 * a step of IDAS's (cap Einf) and of the Rothe steps (no cap) is a part
 * of; *E that modulus. */
static double stiffened_zone(const adh_material *m0, const adh_visco_rule_settings *v, double rate, double cap,
                             double *E)
{
    adh_material m = *m0;
    m.E = v->sls.E0;
    double y = sqrt(rate * v->sls.tau / adh_edge_zone(&m));
    double E1 = v->sls.E0 * (1.0 + TIME_SPEED_STIFFENING * y);
    *E = isinf(cap) ? E1 : fmin(E1, cap);   /* no cap: E1 as it is, NaN too */
    m.E = *E;
    return adh_edge_zone(&m);
}

static double travel_step(const adh_material *m0, const adh_visco_rule_settings *v, double speed, double *E)
{
    return TIME_EDGE_PER_STEP * stiffened_zone(m0, v, 10.0 * speed, v->sls.Einf, E);
}

/* The steps of a branch whose contact line travels a at step a step. */
static double contact_branch(double a, double step)
{
    return a > 0 ? fmax(a / step, TIME_CONTACT_MIN_STEPS) : 0.0;
}

/* The tolerance: measured at the default, each model's error-held steps
 * scaled by its integrator's own rule for the others. IDAS's steps, every
 * one held by its error test, shorten as tol^(1/(q+1)) at its order q,
 * 5 (IDAS's most, which visco_dae.c leaves): steps x (tol/5e-5)^(-1/6)
 * (measured 1.25-1.30 times the steps a quarter of the tolerance, 4^(1/6)
 * = 1.26: Einf = 100 E0, and 3 E0 through a spring). A Rothe step's
 * length in contact is held by q's third-order error and the force's
 * change, (tol)^(1/3) both (visco_rothe.c): the contact line's step x
 * (tol/5e-5)^(1/3); the base's move caps (0.4 z0 out of contact, 0.17 z0
 * in) do not follow tol (measured 1.38-1.44 times the steps a quarter of
 * the tolerance, the contact line's part 4^(1/3) = 1.59 of them). */
static double tol_ratio(const adh_visco_rule_settings *v)
{
    return v->s.tol / ADH_VISCO_TOL_DEFAULT;
}

/* The Rothe steps (visco_rothe.c), measured on the same two spheres at
 * Einf/E0 = 1.5, 3 and 10, 1 nm/s ... 1 mm/s, and R = 1 um
 * (docs/viscoelastic.md: planned 0.73-1.23 of the steps run): a
 * step's length is held by q's error or by the move of the base and the
 * surface (0.4 z0), whichever is shorter. Out of contact the move: the base
 * 0.4 z0 a step from the start to z0 and back (94-245 steps measured). In
 * contact q's error holds the contact line's step to ROTHE_EDGE_PER_STEP
 * edge zones at E0 (1 + 2 y), as IDAS's, but y of the contact line's speed
 * (the base's times a0 / (z0 - turn), a0 JKR's radius at E0 there, over
 * ROTHE_LINE_REF, the Figure 4 sphere's 59: at R = 1 um it is 18, and the
 * line stepped half as far at 100 nm/s) and with no cap at Einf (fast, q
 * hardly moves within a step and its error vanishes), longer where less of
 * the compliance is delayed, by 1 / sqrt(g), g = (1 - E0/Einf) / 0.9 (at
 * 1.5 E0 0.55 of 10 E0's steps at 1 nm/s), and no lattice factor (a static
 * problem at each step, no integrator crawling round a fold); the surface's
 * move holds the base to ROTHE_CONTACT_MOVE z0 a step in contact (0.08-0.09
 * nm measured at 1 mm/s and 10 um/s) over its travel in contact, z0 - turn
 * in and about twice that out (the jump-out lies about as far out as the
 * turn is deep: 15-17 nm at sigma 7.5 to -5 nm, 9 nm at 2.25 to -3 nm),
 * the steps the more of the two. A step's work grows with the contact
 * line's move a step against Einf's edge zone, the static problem's length
 * scale (its Newton and GMRES iterations: 9 GMRES a step at 10 E0 and
 * 1 nm/s, 38 at 1.5 E0 and 1 mm/s, where the line moves 0.55 of it a step):
 * 1 + ROTHE_WORK_PER_EDGE times that move, on IDAS's step price. */
#define ROTHE_MOVE 0.4
#define ROTHE_EDGE_PER_STEP 0.055
#define ROTHE_DELAYED_REF 0.9
#define ROTHE_CONTACT_MOVE 0.17
#define ROTHE_WORK_PER_EDGE 4.5
#define ROTHE_LINE_REF 60.0

/* The contact line's step in contact: q's error's, at E0 (1 + 2 y), y of
 * the contact line's speed (line: its speed over the base's) */
static double rothe_step(const adh_material *m0, const adh_visco_rule_settings *v, double speed, double g, double line)
{
    double E;
    return ROTHE_EDGE_PER_STEP * stiffened_zone(m0, v, 10.0 * speed * line / ROTHE_LINE_REF, INFINITY, &E) / sqrt(g) *
           cbrt(tol_ratio(v));
}

/* The steps of a branch in contact: the contact line's travel a at step,
 * or the base's travel h in contact at ROTHE_CONTACT_MOVE z0, the more. */
static double rothe_contact(double a, double step, double h, double z0)
{
    return a > 0 ? fmax(a / step, fmax(h, 0.0) / (ROTHE_CONTACT_MOVE * z0)) : 0.0;
}

static void rothe_steps(const adh_run_spec *s, const adh_visco_rule_settings *v, adh_plan_time_cost *c)
{
    const adh_protocol_settings *ps = &s->proto;
    adh_material m = s->mat;
    double z0 = m.z0, g = fmax((1.0 - v->sls.E0 / v->sls.Einf) / ROTHE_DELAYED_REF, 1e-6);
    double start = adh_config_start(s), deep = ps->nturns ? adh_protocol_deepest_turn(ps) : start;
    m.E = v->sls.E0;
    double line = ps->nturns && deep < z0 ? adh_jkr_radius(&m, z0 - deep) / (z0 - deep) : ROTHE_LINE_REF;
    c->step_in = rothe_step(&s->mat, v, v->drive.speed_in, g, line);
    c->step_out = rothe_step(&s->mat, v, v->drive.speed_out, g, line);
    /* the contact's size as IDAS's rule has it (at most Einf's JKR) */
    (void)travel_step(&s->mat, v, v->drive.speed_in, &c->E_in);
    (void)travel_step(&s->mat, v, v->drive.speed_out, &c->E_out);
    double branch_free = fmax(start - z0, 0.0) / (ROTHE_MOVE * z0);
    m.E = c->E_in;
    c->a_turn = ps->nturns ? adh_jkr_radius(&m, m.z0 - deep) : 0.0;
    double travel = c->a_turn;
    c->free_steps = branch_free;
    c->contact_steps = rothe_contact(c->a_turn, c->step_in, z0 - deep, z0);
    m.E = c->E_out;
    for (size_t i = 0; ps->unload && i < ps->nturns; i++) {
        double a = adh_jkr_radius(&m, m.z0 - ps->turns[i]);
        travel += a;
        c->free_steps += branch_free + (v->drive.dwell > 0 ? TIME_DWELL_STEPS : 0.0);
        c->contact_steps += rothe_contact(a, c->step_out, 2.0 * (z0 - ps->turns[i]), z0);
    }
    c->lattice = 1.0;
    c->steps = c->free_steps + c->contact_steps;
    m.E = v->sls.Einf;
    c->work = c->contact_steps > 0 ? 1.0 + ROTHE_WORK_PER_EDGE * travel / c->contact_steps / adh_edge_zone(&m) : 1.0;
}

void adh_plan_time_steps(const adh_run_spec *s, adh_plan_time_cost *c)
{
    adh_visco_rule_settings v;
    adh_config_visco(s, &v);
    c->E_ratio = v.sls.Einf / v.sls.E0;
    c->spring = v.drive.spring;
    c->rothe = adh_visco_rothe_applies(&v.sls, &v.drive, &v.s);
    c->work = 1.0;
    if (c->rothe) {
        rothe_steps(s, &v, c);
        return;
    }
    const adh_protocol_settings *ps = &s->proto;
    adh_material m = s->mat;
    double step_in = travel_step(&s->mat, &v, v.drive.speed_in, &c->E_in);
    double step_out = travel_step(&s->mat, &v, v.drive.speed_out, &c->E_out);
    double deep = ps->nturns ? adh_protocol_deepest_turn(ps) : adh_config_start(s);
    m.E = c->E_in;
    c->a_turn = ps->nturns ? adh_jkr_radius(&m, m.z0 - deep) : 0.0;
    c->free_steps = TIME_FREE_STEPS;
    c->contact_steps = contact_branch(c->a_turn, step_in);
    m.E = c->E_out;
    for (size_t i = 0; ps->unload && i < ps->nturns; i++) {
        c->free_steps += TIME_FREE_STEPS + (v.drive.dwell > 0 ? TIME_DWELL_STEPS : 0.0);
        c->contact_steps += contact_branch(adh_jkr_radius(&m, m.z0 - ps->turns[i]), step_out);
    }
    c->lattice = lattice_factor(&v);
    double k = pow(tol_ratio(&v), -1.0 / 6.0);   /* every step IDAS's error test's */
    c->free_steps *= k;
    c->contact_steps *= c->lattice * k;
    c->step_in = step_in / k;
    c->step_out = step_out / k;
    c->steps = TIME_EXTRA * (c->free_steps + c->contact_steps);
}

double adh_plan_path_points(const adh_run_spec *s, const adh_grid *g, int *exact)
{
    double deep = s->proto.nturns ? adh_protocol_deepest_turn(&s->proto) : adh_static_settings_default().h0_end;
    int ex = !adh_static_skips(g, &s->mat, deep);
    if (exact)
        *exact = ex;
    return ex ? adh_static_exact_points(g, &s->mat, deep) : ADH_STATIC_STEP_POINTS;
}
