/* Scene files and the planner: every shipped scene carries its figure's
 * parameters and plans the least work; every bad scene names file:line. */
#include <string.h>

#include "adhere/models.h"
#include "adhere/params.h"
#include "scene/plan.h"
#include "scene/scene.h"
#include "tap.h"

/* equal up to the rounding of a unit conversion ("0.5nm" is 0.5 x 1e-9) */
static int same(double a, double b)
{
    return fabs(a - b) <= 1e-12 * fabs(b);
}

static int load(const char *name, adh_config *c)
{
    char why[1024] = "";
    adh_config_default(c);
    int rc = adh_scene_load(name, c, why, sizeof why);
    ok(rc == 0, "shipped scene %s parses %s", name, why);
    return rc;
}

static double sigma_of(const adh_material *m)
{
    adh_derived d;
    adh_material_derive(m, &d);
    return d.sigma;
}

/* A bad scene: rejected, and the message is "name:LINE: ..." naming what. */
static void bad(const char *text, int line, const char *mentions)
{
    adh_config c;
    adh_config_default(&c);
    char why[1024] = "", want[64];
    int rc = adh_scene_parse_string(text, "bad.scene", &c, why, sizeof why);
    snprintf(want, sizeof want, "bad.scene:%d: ", line);
    int ctl = 0;   /* an escape sequence quoted in the message would reach the terminal */
    for (const char *p = why; *p; p++)
        ctl |= (unsigned char)*p < 0x20 || *p == 0x7f;
    ok(rc != 0 && strncmp(why, want, strlen(want)) == 0 && strstr(why, mentions) && !ctl,
       "rejected at line %d, mentions '%s'%s: %s", line, mentions, ctl ? ", but quotes a control byte" : "", why);
}

static int has_skip(const adh_plan *p, const char *what)
{
    for (size_t i = 0; i < p->nskipped; i++)
        if (strstr(p->skipped[i].what, what))
            return 1;
    return 0;
}

static int has_stored(const adh_plan *p, const char *what)
{
    for (size_t i = 0; i < p->nstored; i++)
        if (strcmp(p->stored[i].what, what) == 0)
            return 1;
    return 0;
}

static void default_scene_is_builtin_default(void)
{
    adh_config c, d;
    if (load("default", &c))
        return;
    adh_config_default(&d);
    ok(same(c.spec.mat.E, d.spec.mat.E) && same(c.spec.mat.A, d.spec.mat.A) && same(c.spec.mat.z0, d.spec.mat.z0) && same(c.spec.mat.R, d.spec.mat.R),
       "default.scene's material is the built-in default's (E = %g)", c.spec.mat.E);
    ok(c.spec.grid.use.nodes == d.spec.grid.use.nodes && isnan(c.spec.grid.use.spacing) && c.spec.grid.use.kernel == d.spec.grid.use.kernel, "default.scene's grid is the built-in default's");
    ok(c.spec.grid.use.graded == d.spec.grid.use.graded && isnan(c.spec.grid.use.fine_band) && same(c.spec.grid.use.growth, d.spec.grid.use.growth) && isnan(c.spec.grid.use.radius) &&
       c.spec.grid.use.storage == d.spec.grid.use.storage && !c.spec.grid.storage_given, "default.scene's grid = uniform, fine_band, growth, radius are the "
       "built-in default's and it gives no operator (growth %g)", c.spec.grid.use.growth);
    ok(!c.spec.grid.kernel_given && !c.spec.grid.nodes_given, "default.scene leaves N and the kernel to the automatic grid, as the built-in "
       "default does (so a soft material gets graded rings)");
    ok(same(c.spec.relax.eps, d.spec.relax.eps) && c.spec.relax.max_iter == d.spec.relax.max_iter, "default.scene's solver is the built-in default's");
    ok(isnan(c.spec.proto.start) && same(c.spec.proto.step, d.spec.proto.step) && c.spec.proto.nturns == 1 &&
       same(c.spec.proto.turns[0], d.spec.proto.turns[0]) && c.spec.proto.unload == 1 && c.spec.proto.dwell == 0 && c.spec.proto.nprofiles == 0,
       "default.scene's protocol is the built-in default's (turn %g m)", c.spec.proto.turns[0]);
    ok(c.output.plots == d.output.plots && c.output.plot == 1 && same(c.output.drive_speed, d.output.drive_speed) && c.sweep.naxes == 0,
       "default.scene's outputs are the built-in default's");
    ok_rel(sigma_of(&c.spec.mat), 7.50, 2e-3, "default sigma (Figure 4)");
}

static void figure_parameters(void)
{
    adh_config c;
    adh_plan p;
    if (!load("fig1", &c)) {
        ok_rel(sigma_of(&c.spec.mat), 2.25, 3e-3, "fig1 sigma");
        adh_plan_make(&c, &p);
        ok(p.loading_branches == 1 && p.unloading_branches == 0 && p.snapshots == 0 && !p.stop_at_contact,
           "fig1: approach into contact, no unloading (unload %zu)", p.unloading_branches);
        ok(c.output.plots == (ADH_PLOT_FORCE | ADH_PLOT_PRECONTACT) && has_stored(&p, "precontact.png"),
           "fig1 draws the force and its eq 23 inset");
    }
    if (!load("fig2", &c)) {
        adh_plan_make(&c, &p);
        ok(same(c.spec.mat.E, 1e9) && p.stop_at_contact && p.unloading_branches == 0 && has_skip(&p, "loading past contact"),
           "fig2: approach only, stops at the jump into contact");
        ok(c.output.plots == ADH_PLOT_BULGE && !p.contact_speeds && p.profiles_stored == 0, "fig2 keeps only the bulge figure");
    }
    if (!load("fig3", &c)) {
        adh_plan_make(&c, &p);
        const adh_sweep_axis *a = &c.sweep.axis[0];
        size_t n = c.sweep.naxes == 1 ? a->n : 0;
        ok(n >= 7 && !strcmp(a->name, "sigma") && a->num[0] <= 0.03 && a->num[n - 1] >= 30,
           "fig3 sweeps sigma over three decades (%zu values)", n);
        ok(p.nruns == n && p.stop_at_contact && p.unloading_branches == 0, "fig3: %zu approach-only runs", p.nruns);
        ok(p.kernels == 1 && p.shared_kernel, "fig3: one kernel shared by every run");
        ok(p.jobs >= 1 && c.sweep.plot == ADH_SWEEP_PLOT_JUMP && has_stored(&p, "jump.png") && has_stored(&p, "sweep.tsv"),
           "fig3 writes sweep.tsv and jump.png (%d jobs)", p.jobs);
        adh_run_spec r;
        size_t wrong = n;   /* the first run whose sigma is off, if any */
        for (size_t i = 0; i < n && wrong == n; i++) {
            adh_config_sweep_run(&c, i, &r);
            if (fabs(sigma_of(&r.mat) - a->num[i]) > 1e-9 * a->num[i])
                wrong = i;
        }
        ok(n > 0 && wrong == n, "every fig3 run has the sigma it names (E from eq 17)%s", wrong < n ? ": one is off" : "");
        if (wrong < n)
            printf("#   run %zu: sigma %g, named %g\n", wrong, sigma_of(&r.mat), a->num[wrong]);
        ok(same(c.spec.mat.z0, 0.5e-9), "fig3: z0 = 0.5 nm");
    }
    if (!load("fig4", &c)) {
        static const double want[] = { -5, -3.5, -2, -0.5, 1, 2.5, 4, 5.5, 7, 8.5 };
        int listed = c.spec.proto.nprofiles == 10;
        for (size_t i = 0; listed && i < 10; i++)
            listed = same(c.spec.proto.profiles[i], want[i] * 1e-9);
        ok(listed, "fig4 stores profiles at the caption's ten positions");
        adh_plan_make(&c, &p);
        ok(p.profiles_reached == 10 && p.profiles_stored >= 10, "fig4: every profile position is on a branch (%zu stored)", p.profiles_stored);
        ok_rel(sigma_of(&c.spec.mat), 7.50, 2e-3, "fig4 sigma");
        ok(c.spec.proto.nturns == 1 && same(c.spec.proto.turns[0], -5e-9) && p.unloading_branches == 1, "fig4 turns at -5 nm and unloads");
    }
    if (!load("fig5", &c)) {
        ok_rel(sigma_of(&c.spec.mat), 4.36, 3e-3, "fig5 sigma");
        ok(same(c.spec.mat.R, 1.5e-2) && same(c.spec.mat.E, 1e11) && same(c.spec.mat.A, 5e-19) && c.spec.proto.nturns == 8, "fig5: R = 1.5 cm, 8 turns");
        adh_plan_make(&c, &p);
        ok(p.loading_branches == 1 && p.snapshots == 8 && p.unloading_branches == 8,
           "fig5 plan: one loading branch, 8 snapshots, 8 unloading branches");
        ok(same(p.runs[0].end, -10e-9), "fig5 loads only to the deepest turn");
    }
    if (!load("fig6", &c)) {
        ok_rel(sigma_of(&c.spec.mat), 17.43, 3e-3, "fig6 sigma");
        adh_plan_make(&c, &p);
        ok(c.spec.proto.nturns == 9 && p.loading_branches == 1 && p.unloading_branches == 9, "fig6: 9 turns on one loading branch");
    }
    if (!load("fig7", &c)) {
        const adh_sweep_axis *a = &c.sweep.axis[0];
        ok(c.sweep.naxes == 1 && !strcmp(a->key, "solver.eps") && a->n == 3 && same(a->num[0], 1e-12) &&
           same(a->num[1], 0.5e-12) && same(a->num[2], 1e-13), "fig7 sweeps eps = 1, 0.5, 0.1 pm");
        adh_plan_make(&c, &p);
        ok(p.nruns == 3 && p.unloading_branches == 1 && c.sweep.plot == ADH_SWEEP_PLOT_FORCE, "fig7: 3 loops, combined force figure");
        ok_rel(sigma_of(&c.spec.mat), 7.50, 2e-3, "fig7 sigma (Figure 4's material)");
    }
    if (!load("fig8", &c)) {
        adh_plan_make(&c, &p);
        ok(same(c.output.drive_speed, 1e-6) && p.contact_speeds && c.output.plots == ADH_PLOT_CONTACT, "fig8 tracks the contact line at 1 um/s");
    }
}

static void planner(void)
{
    adh_config c;
    adh_plan p;
    char why[1024];
    adh_config_default(&c);
    ok(adh_scene_parse_string("[scene]\nmode = rigid\n[protocol]\nturns = none\n", "rigid", &c, why, sizeof why) == 0,
       "mode = rigid parses");
    adh_plan_make(&c, &p);
    ok(!p.elastic && p.kernels == 0 && p.unloading_branches == 0 && has_skip(&p, "elastic solve"),
       "a rigid scene builds no kernel and does no elastic solve");
    ok(p.runs[0].end == 0.7 * c.spec.mat.z0, "rigid spheres with no turn stop at 0.7 z0, above h0 = 0 (got %g m)",
       p.runs[0].end);

    adh_config_default(&c);
    adh_scene_parse_string("[output]\nprofiles = 1.02nm, 2nm\n", "p", &c, why, sizeof why);
    adh_plan_make(&c, &p);
    ok(p.profiles_asked == 2 && p.profiles_reached == 1 && has_skip(&p, "profile at 1.02 nm"),
       "a profile between drive positions is reported as skipped");

    adh_config_default(&c);
    adh_scene_parse_string("[protocol]\nturns = -1nm\ndwell = 500\nunload = no\n", "d", &c, why, sizeof why);
    adh_plan_make(&c, &p);
    ok(p.unloading_branches == 0 && has_skip(&p, "dwell"), "a dwell without unloading is skipped");

    adh_config_default(&c);
    adh_scene_parse_string("[protocol]\nunload = no\nturns = -1nm, -2nm\n", "u", &c, why, sizeof why);
    ok(c.spec.proto.unload == 0 && c.spec.proto.nturns == 2, "unload = no holds whatever the order of the keys");

    adh_config_default(&c);
    adh_scene_parse_string("[sweep]\nE = 1GPa, 2GPa\njobs = 1\n", "e", &c, why, sizeof why);
    adh_plan_make(&c, &p);
    ok(p.nruns == 2 && p.jobs == 1 && same(p.runs[1].E, 2e9), "[sweep] E = list, jobs = 1: two runs one at a time");
    adh_config_default(&c);
    adh_scene_parse_string("[sweep]\neps = 2pm, 1pm, 3pm, 4pm\n", "e", &c, why, sizeof why);
    adh_plan_make(&c, &p);
    ok(p.jobs >= 1 && p.jobs <= 4 && p.kernels == 1, "an eps sweep runs on at most the cores, one kernel (%d jobs)", p.jobs);

    adh_config_default(&c);
    adh_scene_parse_string("[output]\nplots = none\n", "n", &c, why, sizeof why);
    ok(c.output.plots == 0 && c.output.plot == 1, "plots = none draws no figure of the run");
}

static void bad_scenes(void)
{
    bad("[scene]\ntitle = x\n[materials]\nE = 1GPa\n", 3, "unknown section [materials]");
    bad("[material]\nE = 1GPa\nYoung = 3\n", 3, "unknown key 'Young'");
    bad("[material]\nE = 1GPa\nE = 2GPa\n", 3, "given twice");
    bad("[material]\n\nA = abc\n", 3, "'abc' is not a number");
    bad("[material]\nR = 5parsecs\n", 2, "unknown unit");
    bad("[material]\nE = 5nm\n", 2, "a pressure");
    bad("[grid]\nnodes = 5\n", 2, "use 10 to 20000 nodes");
    bad("[protocol]\nturns = -1nm, xyz\n", 2, "'xyz' is not a number");
    bad("[scene]\nmode = fast\n", 2, "not a mode");
    bad("[output]\nplots = force, pie\n", 2, "'pie' is not a plot");
    bad("[output]\nplots = none, force\n", 2, "cannot be combined");
    bad("[sweep]\nsigma = 1, 2\nE = 1GPa\n", 3, "sigma and E both set the modulus");
    bad("[sweep]\nE = 1GPa, 2GPa, 1GPa\n", 2, "given twice");
    bad("[sweep]\nE = 1GPa, 2GPa\nmaterial.E = 3GPa\n", 3, "material.E swept twice in [sweep], as 'E' and as 'material.E'");
    bad("[sweep]\nmaterial.sigma = 1, 2\nsigma = 3\n", 3, "sigma swept twice in [sweep], as 'material.sigma' and as 'sigma'");
    bad("[sweep]\nprotocol.turns = -1nm, -2nm\nturns = -3nm\n", 3, "protocol.turns swept twice");
    bad("[sweep]\nnodes = 100 .. 1000\n", 2, "not a range");
    bad("[sweep]\nE = 1GPa .. 2GPa, cubic, 3\n", 2, "not a spacing");
    bad("[sweep]\nturns = -1nm .. 1nm, log, 3\n", 2, "one sign");
    bad("[sweep]\nmode = relax .. static, 2\n", 2, "not a number");
    bad("[sweep]\nE = 1GPa .. 2GPa, 400\nA = 1e-20J .. 1e-19J, 400\n", 3, "more than 100000 runs");
    bad("[sweep]\nYoung = 1, 2\n", 2, "no key of a run");
    bad("[sweep]\ndir = a, b\n", 2, "no key of a run");
    bad("[sweep]\nsigma = 1, -2\n", 2, "above 0");
    bad("[sweep]\neps = 1GPa\n", 2, "a length");
    bad("[sweep]\nplot = pie\n", 2, "not a sweep plot");
    bad("[sweep]\njobs = 0\n", 2, "jobs");
    bad("[solver]\neps 1pm\n", 2, "syntax error");
    bad("[protocol\nstep = 1nm\n", 1, "syntax error");
    bad("[material]\nE = 1GPa # stiffer\n", 2, "(a comment after a value starts with ' ;', not '#')");
    /* control bytes: an escape sequence in a value or a key was quoted raw
     * in the refusal (a title's alone was refused) */
    bad("[material]\nE = \033]0;owned\007\n", 2, "E: the control character 0x1b is not allowed");
    bad("[material]\n\033[2J = 1\n", 2, "the control character 0x1b is not allowed");
    bad("[protocol]\nturns = -1nm, \033[31m-2nm\n", 2, "turns: the control character 0x1b");
    bad("[scene]\ntitle = a\001b\n", 2, "title: the control character 0x01 is not allowed");
    {   /* a binary file, its control bytes in a line past 198 bytes: it was 'line longer than 198 characters' */
        char binary[600];
        memset(binary, 1, sizeof binary - 1);
        binary[sizeof binary - 1] = '\0';
        bad(binary, 1, "the control character 0x01 is not allowed");
    }
    bad("[grid]\n# a comment \033[2J\n", 2, "the control character 0x1b");
    /* a lone byte that is not UTF-8 was quoted as it was: 0x9b is CSI to
     * some terminals, 0xb5 a Latin-1 micro sign; a comment may keep it */
    bad("[material]\nE = 1\x9b" "2JGPa\n", 2, "E: the byte 0x9b is not UTF-8 text");
    bad("[scene]\ntitle = 5 \xb5m\n", 2, "title: the byte 0xb5 is not UTF-8 text");
    {
        adh_config lc;
        adh_config_default(&lc);
        char lwhy[512] = "";
        ok(adh_scene_parse_string("# caf\xe9\n[scene]\ntitle = 5 \xc2\xb5m\n", "ok.scene", &lc, lwhy, sizeof lwhy) == 0,
           "a Latin-1 comment line and a UTF-8 title parse (%s)", lwhy);
    }

    adh_config c;
    char why[1024] = "";
    adh_config_default(&c);
    ok(adh_scene_load("/nonexistent/dir/x.scene", &c, why, sizeof why) != 0 && strstr(why, "/nonexistent/dir/x.scene"),
       "a missing scene file is named: %s", why);
    ok(adh_scene_load("nosuchfigure", &c, why, sizeof why) != 0 && strstr(why, "no scene named 'nosuchfigure'"),
       "an unknown scene name is reported: %s", why);
}

/* One scene's text parsed over the defaults; 0 when it parses. */
static int parse(const char *text, adh_config *c)
{
    char why[1024] = "";
    adh_config_default(c);
    int rc = adh_scene_parse_string(text, "grid.scene", c, why, sizeof why);
    if (rc != 0)
        printf("# %s\n", why);
    return rc;
}

/* [grid] grid, fine_band, growth, radius, operator: read as the flags
 * --grid, --fine-band, --growth, --grid-radius, --operator read them, bad
 * values named at their line (tests/scenes/plan.sh: flags override them, and
 * the plan is the flags'). */
static void grid_keys(void)
{
    adh_config c;
    /* parsed before ok(): its arguments are evaluated in no set order */
    int rc = parse("[grid]\nkernel = ring\ngrid = graded\nfine_band = 700nm\ngrowth = 1.08\nradius = 2um\noperator = h2\n", &c);
    ok(rc == 0 && c.spec.grid.use.graded && c.spec.grid.use.kernel == ADH_KERNEL_RING && same(c.spec.grid.use.fine_band, 7e-7) && same(c.spec.grid.use.growth, 1.08) &&
       same(c.spec.grid.use.radius, 2e-6) && c.spec.grid.use.storage == ADH_STORAGE_H2 && c.spec.grid.storage_given,
       "grid = graded, fine_band, growth, radius and operator = h2 are read (band %g m, ratio %g, Rmax %g m)",
       c.spec.grid.use.fine_band, c.spec.grid.use.growth, c.spec.grid.use.radius);
    adh_config d;
    adh_config_default(&d);
    ok(parse("[grid]\ngrid = uniform\nfine_band = auto\nradius = AUTO\ngrowth = 1\noperator = dense\n", &c) == 0 &&
       !c.spec.grid.use.graded && isnan(c.spec.grid.use.fine_band) && isnan(c.spec.grid.use.radius) && c.spec.grid.use.growth == 1.0 && c.spec.grid.use.storage == ADH_STORAGE_DENSE &&
       c.spec.grid.storage_given, "grid = uniform, auto band and radius (the defaults), growth 1, and an operator given "
       "as dense is kept by the automatic grid (storage_given)");
    ok(parse("[grid]\noperator = hmat\ngrowth = 1.1\n", &c) == 0 && c.spec.grid.use.storage == ADH_STORAGE_HMAT && same(c.spec.grid.use.growth, 1.1),
       "operator = hmat and growth = 1.1, the widest ratio, are read");
    ok(parse("[grid]\nnodes = 500\n", &c) == 0 && !c.spec.grid.storage_given && c.spec.grid.use.graded == d.spec.grid.use.graded && isnan(c.spec.grid.use.fine_band) &&
       same(c.spec.grid.use.growth, d.spec.grid.use.growth) && isnan(c.spec.grid.use.radius), "a scene without the keys keeps their defaults");

    bad("[grid]\ngrid = Graded\n", 2, "grid: 'Graded' is not a grid: use uniform or graded");
    bad("[grid]\nnodes = 500\n\ngrid = rings\n", 4, "'rings' is not a grid");
    bad("[grid]\nfine_band = -2nm\n", 2, "fine_band: '-2nm' is not allowed: use a length above 0, or auto");
    bad("[grid]\nfine_band = 0\n", 2, "use a length above 0");
    bad("[grid]\nfine_band = 1GPa\n", 2, "a length (m, nm, um, ...) is wanted here, or auto");
    bad("[grid]\nradius = 2 parsecs\n", 2, "radius: '2 parsecs': unknown unit");
    bad("[grid]\nradius = -1um\n", 2, "radius: '-1um' is not allowed: use a length above 0, or auto");
    bad("[grid]\ngrowth = 1.2\n", 2, "growth: '1.2' is not allowed: use a ratio from 1 to 1.1");
    bad("[grid]\ngrowth = 0.95\n", 2, "use a ratio from 1 to 1.1");
    bad("[grid]\ngrowth = auto\n", 2, "growth: 'auto' is not allowed");
    bad("[grid]\ngrowth = 1.05nm\n", 2, "growth: '1.05nm' is not allowed");
    bad("[grid]\noperator = fmm\n", 2, "operator: 'fmm' is not an operator: use dense, hmat or h2");
    bad("[grid]\noperator = h2\noperator = h2\n", 3, "given twice");
    /* the paper's kernel assumes equal cells, as --grid=graded --kernel=paper is refused */
    bad("[grid]\nkernel = paper\nnodes = 500\ngrid = graded\n", 4,
        "grid: 'graded' is not allowed with kernel = paper: the paper's kernel assumes equal cells; use kernel = ring");
    bad("[grid]\ngrid = graded\nkernel = paper\n", 3, "kernel: 'paper' is not allowed with grid = graded");
    ok(parse("[grid]\nkernel = paper\ngrid = uniform\n", &c) == 0 && parse("[grid]\ngrid = graded\n", &c) == 0 &&
       c.spec.grid.use.graded && !c.spec.grid.kernel_given, "kernel = paper with grid = uniform parses, and grid = graded alone is left to the "
       "run's check (a flag or the automatic grid may give the ring kernel)");
    char why[512] = "";
    ok(adh_config_grid_check(&c.spec, why, sizeof why) != 0 && strstr(why, "grid = graded") && strstr(why, "kernel = ring"),
       "which refuses it with the paper's kernel, naming the keys: %s", why);
}

/* Mutated shipped scenes: each either parses or is rejected with
 * "fuzz:LINE: message" and a line inside the text; nothing crashes (the
 * sanitizer build runs this too). A fixed seed keeps it reproducible. */
static void mutations(void)
{
    char path[PATH_MAX], why[1024];
    if (adh_scene_find("fig5", path, sizeof path, why, sizeof why) != 0) {
        ok(0, "fig5 found for mutation: %s", why);
        return;
    }
    FILE *f = fopen(path, "r");
    char base[4096];
    size_t n = f ? fread(base, 1, sizeof base - 1, f) : 0;
    if (f)
        fclose(f);
    base[n] = '\0';
    static const char alphabet[] = "[]=,;#\n \tE0.5nm-xyzGPa\r";
    unsigned long seed = 12345;
    int lines = 1, bad = 0, parsed = 0;
    for (const char *c = base; *c; c++)
        lines += *c == '\n';
    for (int trial = 0; trial < 3000 && !bad; trial++) {
        char text[4200];
        memcpy(text, base, n + 1);
        size_t len = n;
        for (int k = 0; k < 1 + trial % 4; k++) {
            seed = seed * 6364136223846793005UL + 1442695040888963407UL;
            size_t at = (size_t)(seed >> 33) % (len + 1);
            char ch = alphabet[(seed >> 20) % (sizeof alphabet - 1)];
            switch ((seed >> 8) % 3) {
            case 0: if (at < len) text[at] = ch; break;                      /* replace */
            case 1: if (len + 1 < sizeof text) {                              /* insert */
                        memmove(text + at + 1, text + at, len - at + 1);
                        text[at] = ch;
                        len++;
                    }
                    break;
            default: if (at < len) { memmove(text + at, text + at + 1, len - at); len--; } /* delete */
            }
        }
        adh_config c;
        adh_config_default(&c);
        why[0] = '\0';
        if (adh_scene_parse_string(text, "fuzz", &c, why, sizeof why) == 0) {
            parsed++;
            continue;
        }
        int line = 0;
        if (sscanf(why, "fuzz:%d: ", &line) != 1 || line < 1 || line > lines + 4 || !strstr(why, ": ")) {
            bad = 1;
            ok(0, "mutation %d rejected with a bad message: %s", trial, why);
        }
    }
    ok(!bad, "3000 mutations of fig5.scene: each parses (%d did) or names fuzz:LINE", parsed);
}

/* Each key the scene set is noted with its line (comments, blank lines and
 * sections counted; inih does not say it), a swept key's run key with the
 * sweep's; a later flag's word replaces the scene's. */
static void origins(void)
{
    adh_config c;
    char why[512];
    adh_config_default(&c);
    int rc = adh_scene_parse_string("# a comment\n\n[material]\n; another\nE = 1GPa\nEinf = 3GPa\n[sweep]\n"
                                    "speed = 1um/s, 2um/s\n", "o.scene", &c, why, sizeof why);
    ok(rc == 0, "origins: the scene parses (%s)", rc ? why : "");
    ok(adh_config_origin(&c, "material.E") == 5, "origins: E at line 5 (%d)", adh_config_origin(&c, "material.E"));
    ok(adh_config_origin(&c, "material.Einf") == 6, "origins: Einf at line 6 (%d)", adh_config_origin(&c, "material.Einf"));
    ok(adh_config_origin(&c, "protocol.speed") == 8, "origins: the swept speed at the sweep's line 8 (%d)",
       adh_config_origin(&c, "protocol.speed"));
    ok(adh_config_origin(&c, "material.R") == -2, "origins: R set by nobody (%d)", adh_config_origin(&c, "material.R"));
    adh_config_note_origin(&c, "material.E", 0);
    ok(adh_config_origin(&c, "material.E") == 0, "origins: a flag's E replaces the scene's (%d)",
       adh_config_origin(&c, "material.E"));
    /* E and E0 set one value: the one set last holds, and is named */
    ok(!strcmp(adh_config_origin_last(&c, "material.E", "material.E0"), "material.E"), "origins: E holds, E0 unset");
    adh_config_note_origin(&c, "material.E0", 0);
    ok(!strcmp(adh_config_origin_last(&c, "material.E", "material.E0"), "material.E0"), "origins: E0 set after E holds");
    adh_config_note_origin(&c, "material.E", 0);
    ok(!strcmp(adh_config_origin_last(&c, "material.E", "material.E0"), "material.E"), "origins: E set again holds");
    ok(!strcmp(adh_config_origin_last(&c, "protocol.speed", "material.E"), "protocol.speed"),
       "origins: a swept key is set after any other (each run sets it)");
    /* a key set and swept: each run's value is the sweep's, and so is the
     * line named (it named the key's own line, whose value no run took) */
    adh_config_default(&c);
    rc = adh_scene_parse_string("[material]\nE = 0.05GPa\n[sweep]\nE = 1GPa, 2GPa\n", "s.scene", &c, why, sizeof why);
    ok(rc == 0 && adh_config_origin(&c, "material.E") == 4, "origins: E set at line 2 and swept at line 4: the sweep's "
       "line (%d; %s)", adh_config_origin(&c, "material.E"), rc ? why : "");
    adh_config_note_origin(&c, "sweep.E", 0);
    ok(adh_config_origin(&c, "material.E") == 0, "origins: swept by a flag (--sweep=E=...) after the scene's E: the "
       "flag (%d)", adh_config_origin(&c, "material.E"));
    /* ... named by the sweep's name, as given: a message says --sweep=E=1GPa */
    const char *as = adh_config_swept_as(&c, "material.E");
    ok(as && !strcmp(as, "E"), "origins: material.E is swept as E (%s)", as ? as : "NULL");
    ok(!adh_config_swept_as(&c, "material.A"), "origins: material.A is not swept");
    adh_config_note_origin(&c, "sweep.protocol.turns", 0);
    as = adh_config_swept_as(&c, "protocol.turns");
    ok(as && !strcmp(as, "protocol.turns"), "origins: a sweep by the key's full name is that name (%s)", as ? as : "NULL");
}

int main(void)
{
    origins();
    default_scene_is_builtin_default();
    figure_parameters();
    planner();
    bad_scenes();
    grid_keys();
    mutations();
    return tap_done();
}
