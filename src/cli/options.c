#include "cli/options.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/grid.h"
#include "adhere/status.h"
#include "adhere/units.h"
#include "scene/scene.h"

enum {
    OPT_SPACING = 256, OPT_START, OPT_TURN, OPT_KERNEL, OPT_REPLAY, OPT_SCREEN, OPT_SIZE,
    OPT_NO_CLOCK, OPT_LIST_KEYS, OPT_NO_PLOT, OPT_PLOTS, OPT_PROFILES, OPT_DRIVE_SPEED,
    OPT_GNUPLOT_STYLE, OPT_PLAN, OPT_DWELL, OPT_MODE, OPT_REFERENCE, OPT_COST, OPT_COST_EPS,
    OPT_COST_NODES, OPT_MAX_ITER, OPT_MIXING, OPT_MOMENTUM, OPT_GRID, OPT_FINE_BAND, OPT_GROWTH,
    OPT_GRID_RADIUS, OPT_OPERATOR
};

typedef struct option_doc {
    struct option opt;
    const char *arg;     /* argument name for --help, NULL if none */
    const char *help;
} option_doc;

/* The one list of options: getopt_long's table and --help are both made from
 * it, so they cannot drift apart (the man page test checks the third copy). */
static const option_doc options[] = {
    { { "modulus", required_argument, 0, 'E' }, "PA", "combined modulus E, 2/E = sum (1-nu^2)/E_i (default 0.3GPa, Figure 4)" },
    { { "hamaker", required_argument, 0, 'A' }, "J", "Hamaker constant A (default 1e-19J)" },
    { { "z0", required_argument, 0, 'z' }, "M", "Lennard-Jones equilibrium separation z0 (default 0.5nm)" },
    { { "radius", required_argument, 0, 'R' }, "M", "effective radius R (default 10um)" },
    { { "nodes", required_argument, 0, 'N' }, "N", "grid nodes N, 10 to 20000 (default 1000)" },
    { { "spacing", required_argument, 0, OPT_SPACING }, "M", "grid spacing (default 0.0212 sqrt(R z0): 1.5nm at R=10um, z0=0.5nm)" },
    { { "kernel", required_argument, 0, OPT_KERNEL }, "paper|ring", "elastic kernel: the paper's eqs 18-21 or exact rings (default paper)" },
    { { "grid", required_argument, 0, OPT_GRID }, "uniform|graded", "radial grid: N equal rings, or fine rings over the contact then growing ones (default uniform)" },
    { { "fine-band", required_argument, 0, OPT_FINE_BAND }, "M", "graded grid: radius of the fine band (default 1.25 x the contact expected at the deepest turn, JKR or overlap)" },
    { { "growth", required_argument, 0, OPT_GROWTH }, "R", "graded grid: width ratio of neighbouring rings past the band, 1 to 1.1 (default 1.05)" },
    { { "grid-radius", required_argument, 0, OPT_GRID_RADIUS }, "M", "graded grid: outer radius Rmax (default the default uniform grid's, 1.5um at R=10um, z0=0.5nm)" },
    { { "operator", required_argument, 0, OPT_OPERATOR }, "dense|hmat", "how the kernel is held: dense matrix or hierarchical (hmat-oss) (default dense)" },
    { { "eps", required_argument, 0, 'e' }, "M", "convergence: sqrt(sum du^2)/N below this ends a step (default 1pm)" },
    { { "max-iter", required_argument, 0, OPT_MAX_ITER }, "N", "iteration cap per step; reaching it is reported (default 200000)" },
    { { "mixing", required_argument, 0, OPT_MIXING }, "paper|momentum", "mixing rule of the relaxation: the paper's adaptive ratio or heavy-ball momentum (default momentum)" },
    { { "momentum", required_argument, 0, OPT_MOMENTUM }, "B", "momentum rule: fraction of the previous update kept, 0 to below 1 (default 0.55)" },
    { { "step", required_argument, 0, 'd' }, "M", "drive step d (default 0.05nm)" },
    { { "start", required_argument, 0, OPT_START }, "M", "first drive position h0 (default: where the force is negligible)" },
    { { "turn", required_argument, 0, OPT_TURN }, "M[,M...]", "turning points (default -5nm); 'none' loads to contact only" },
    { { "dwell", required_argument, 0, OPT_DWELL }, "N", "iterations held at each turning point before unloading (default 0)" },
    { { "mode", required_argument, 0, OPT_MODE }, "relax|static|rigid", "paper's relaxation, the static equilibrium curve, or rigid spheres only (eq 22, no elastic solve) (default relax)" },
    { { "reference", required_argument, 0, OPT_REFERENCE }, "static", "also compute the static curve as a reference in relaxation mode" },
    { { "batch", no_argument, 0, 'b' }, NULL, "run the protocol without the TUI and write tables" },
    { { "out", required_argument, 0, 'o' }, "DIR", "write force.tsv, summary.tsv, turns.tsv and plots into DIR (created)" },
    { { "no-plot", no_argument, 0, OPT_NO_PLOT }, NULL, "write no PNG plots" },
    { { "plots", required_argument, 0, OPT_PLOTS }, "LIST", "plots to write: force,profile,contact (default all)" },
    { { "profiles", required_argument, 0, OPT_PROFILES }, "M[,M...]", "drive positions where surface profiles are stored" },
    { { "drive-speed", required_argument, 0, OPT_DRIVE_SPEED }, "M/S", "drive speed for contact-line speeds (default 1um/s)" },
    { { "gnuplot-style", required_argument, 0, OPT_GNUPLOT_STYLE }, "FILE", "gnuplot style file overriding the installed one" },
    { { "plan", no_argument, 0, OPT_PLAN }, NULL, "print the run plan (branches, steps, what is stored) and exit" },
    { { "cost", no_argument, 0, OPT_COST }, NULL, "report what accuracy costs: runs over a grid of eps, N and kernels" },
    { { "cost-eps", required_argument, 0, OPT_COST_EPS }, "M[,M...]", "eps values of the cost grid (default 2,1,0.5,0.2,0.1pm)" },
    { { "cost-nodes", required_argument, 0, OPT_COST_NODES }, "N[,N...]", "node counts of the cost grid (default 500,1000,2000)" },
    { { "replay", required_argument, 0, OPT_REPLAY }, "FILE", "drive the TUI from a keystroke script, with no terminal" },
    { { "screen", required_argument, 0, OPT_SCREEN }, "FILE", "write the final TUI screen as text (with --replay)" },
    { { "size", required_argument, 0, OPT_SIZE }, "COLSxROWS", "screen size for --replay (default 100x32)" },
    { { "no-clock", no_argument, 0, OPT_NO_CLOCK }, NULL, "mask timings on the screen so replays are deterministic" },
    { { "list-keys", no_argument, 0, OPT_LIST_KEYS }, NULL, "print the TUI's keys and exit" },
    { { "quiet", no_argument, 0, 'q' }, NULL, "no progress bar or notes on standard error" },
    { { "help", no_argument, 0, 'h' }, NULL, "print this help and exit" },
    { { "version", no_argument, 0, 'V' }, NULL, "print the version and exit" },
};
#define NOPTIONS (sizeof options / sizeof options[0])

void adh_cli_usage(FILE *out)
{
    fprintf(out, "usage: adhere [OPTIONS] [SCENE]\n"
                 "Two elastic spheres with a Lennard-Jones surface force (Attard 2000).\n"
                 "Without --batch, opens the TUI. Numbers are SI or take a unit: 1GPa 0.5nm 10um 1e-19J.\n\n");
    for (size_t i = 0; i < NOPTIONS; i++) {
        const option_doc *o = &options[i];
        char lhs[64];
        int n = 0;
        if (o->opt.val < 256)
            n = snprintf(lhs, sizeof lhs, "-%c, ", o->opt.val);
        else
            n = snprintf(lhs, sizeof lhs, "    ");
        snprintf(lhs + n, sizeof lhs - (size_t)n, "--%s%s%s", o->opt.name, o->arg ? "=" : "", o->arg ? o->arg : "");
        fprintf(out, "  %-28s %s\n", lhs, o->help);
    }
    fprintf(out, "\nSCENE is a scene file or the name of a shipped one (default, fig1 ... fig8).\n"
                 "See adhere(1) and adhere-scene(5).\n");
}

static int quantity(const char *name, const char *arg, adh_quantity q, double *out, char *why, size_t n)
{
    char msg[256];
    if (adh_parse_quantity(arg, q, out, msg, sizeof msg) != 0) {
        snprintf(why, n, "--%s: %s", name, msg);
        return 2;
    }
    return 0;
}

/* A comma-separated list of lengths into out[]; "none" gives an empty list. */
static int length_list(const char *name, const char *arg, double *out, size_t cap, size_t *count,
                       char *why, size_t n)
{
    char buf[1024];
    if (strlen(arg) >= sizeof buf) {
        snprintf(why, n, "--%s: list longer than %zu characters", name, sizeof buf - 1);
        return 2;
    }
    *count = 0;
    if (strcmp(arg, "none") == 0)
        return 0;
    snprintf(buf, sizeof buf, "%s", arg);
    char *save = NULL;
    for (char *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        if (*count == cap) {
            snprintf(why, n, "--%s: more than %zu values", name, cap);
            return 2;
        }
        if (quantity(name, tok, ADH_Q_LENGTH, &out[*count], why, n))
            return 2;
        (*count)++;
    }
    if (*count == 0) {
        snprintf(why, n, "--%s: expected one or more lengths separated by commas", name);
        return 2;
    }
    return 0;
}

static int apply(adh_cli *cli, int c, const char *arg, const char *name, char *why, size_t n)
{
    adh_config *cfg = &cli->cfg;
    long v;
    char msg[256];
    switch (c) {
    case 'E': return quantity(name, arg, ADH_Q_PRESSURE, &cfg->mat.E, why, n);
    case 'A': return quantity(name, arg, ADH_Q_ENERGY, &cfg->mat.A, why, n);
    case 'z': return quantity(name, arg, ADH_Q_LENGTH, &cfg->mat.z0, why, n);
    case 'R': return quantity(name, arg, ADH_Q_LENGTH, &cfg->mat.R, why, n);
    case 'e': return quantity(name, arg, ADH_Q_LENGTH, &cfg->relax.eps, why, n);
    case 'd': return quantity(name, arg, ADH_Q_LENGTH, &cfg->proto.step, why, n);
    case OPT_SPACING: return quantity(name, arg, ADH_Q_LENGTH, &cfg->spacing, why, n);
    case OPT_START: return quantity(name, arg, ADH_Q_LENGTH, &cfg->proto.start, why, n);
    case OPT_DRIVE_SPEED: return quantity(name, arg, ADH_Q_SPEED, &cfg->drive_speed, why, n);
    case OPT_FINE_BAND: return quantity(name, arg, ADH_Q_LENGTH, &cfg->fine_band, why, n);
    case OPT_GRID_RADIUS: return quantity(name, arg, ADH_Q_LENGTH, &cfg->grid_radius, why, n);
    case OPT_GROWTH: {
        char *end;
        double g = strtod(arg, &end);
        if (end == arg || *end || !(g >= 1.0 && g <= ADH_RINGS_MAX_RATIO)) {
            snprintf(why, n, "--growth: '%s' is not allowed: use a ratio from 1 to %g", arg, ADH_RINGS_MAX_RATIO);
            return 2;
        }
        cfg->growth = g;
        return 0;
    }
    case OPT_GRID:
        if (strcmp(arg, "uniform") != 0 && strcmp(arg, "graded") != 0) {
            snprintf(why, n, "--grid: '%s' is not a grid: use uniform or graded", arg);
            return 2;
        }
        cfg->graded = strcmp(arg, "graded") == 0;
        return 0;
    case OPT_OPERATOR:
        if (adh_kernel_storage_parse(arg, &cfg->storage) != 0) {
            snprintf(why, n, "--operator: '%s' is not an operator: use dense or hmat", arg);
            return 2;
        }
        return 0;
    case 'N':
    case OPT_MAX_ITER:
    case OPT_DWELL: {
        long lo = c == 'N' ? 10 : c == OPT_DWELL ? 0 : 1;
        long hi = c == 'N' ? 20000 : 100000000;
        if (adh_parse_count(arg, lo, hi, &v, msg, sizeof msg) != 0) {
            snprintf(why, n, "--%s: %s", name, msg);
            return 2;
        }
        if (c == 'N')
            cfg->nodes = (size_t)v;
        else if (c == OPT_DWELL)
            cfg->proto.dwell = (size_t)v;
        else
            cfg->relax.max_iter = (size_t)v;
        return 0;
    }
    case OPT_TURN:
        if (length_list(name, arg, cfg->proto.turns, ADH_MAX_TURNS, &cfg->proto.nturns, why, n))
            return 2;
        cfg->proto.unload = cfg->proto.nturns > 0;
        return 0;
    case OPT_PROFILES:
        return length_list(name, arg, cfg->proto.profiles, ADH_MAX_PROFILES, &cfg->proto.nprofiles, why, n);
    case OPT_KERNEL:
        if (adh_kernel_parse(arg, &cfg->kernel) != 0) {
            snprintf(why, n, "--kernel: '%s' is not a kernel: use paper or ring", arg);
            return 2;
        }
        return 0;
    case OPT_MIXING:
        if (adh_mix_rule_parse(arg, &cfg->relax.rule) != 0) {
            snprintf(why, n, "--mixing: '%s' is not a mixing rule: use paper or momentum", arg);
            return 2;
        }
        return 0;
    case OPT_MOMENTUM: {
        double b;
        if (adh_parse_quantity(arg, ADH_Q_NONE, &b, msg, sizeof msg) != 0 || !(b >= 0 && b < 1)) {
            snprintf(why, n, "--momentum: '%s' is not allowed: a number from 0 to below 1", arg);
            return 2;
        }
        cfg->relax.momentum = b;
        return 0;
    }
    case OPT_MODE:
        if (strcmp(arg, "relax") == 0)
            cfg->mode = ADH_MODE_RELAX;
        else if (strcmp(arg, "static") == 0)
            cfg->mode = ADH_MODE_STATIC;
        else if (strcmp(arg, "rigid") == 0)
            cfg->mode = ADH_MODE_RIGID;
        else {
            snprintf(why, n, "--mode: '%s' is not a mode: use relax, static or rigid", arg);
            return 2;
        }
        return 0;
    case OPT_REFERENCE:
        if (strcmp(arg, "static") != 0 && strcmp(arg, "none") != 0) {
            snprintf(why, n, "--reference: '%s' is not allowed: use static or none", arg);
            return 2;
        }
        snprintf(cli->reference, sizeof cli->reference, "%s", strcmp(arg, "none") ? arg : "");
        return 0;
    case OPT_PLOTS: {
        unsigned mask = 0;
        char buf[256], *save = NULL;
        snprintf(buf, sizeof buf, "%s", arg);
        for (char *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
            if (strcmp(t, "force") == 0) mask |= ADH_PLOT_FORCE;
            else if (strcmp(t, "profile") == 0) mask |= ADH_PLOT_PROFILE;
            else if (strcmp(t, "contact") == 0) mask |= ADH_PLOT_CONTACT;
            else {
                snprintf(why, n, "--plots: '%s' is not a plot: use force, profile or contact, separated by commas", t);
                return 2;
            }
        }
        if (!mask) {
            snprintf(why, n, "--plots: name at least one of force, profile, contact");
            return 2;
        }
        cfg->plots = mask;
        return 0;
    }
    case OPT_SIZE: {
        int cols, rows;
        char extra;
        if (sscanf(arg, "%dx%d%c", &cols, &rows, &extra) != 2 || cols < 40 || cols > 1000 ||
            rows < 12 || rows > 1000) {
            snprintf(why, n, "--size: '%s' is not allowed: use COLSxROWS with 40-1000 columns and 12-1000 rows", arg);
            return 2;
        }
        cfg->cols = cols;
        cfg->rows = rows;
        return 0;
    }
    case 'o': case OPT_REPLAY: case OPT_SCREEN: case OPT_GNUPLOT_STYLE: {
        char *dst = c == 'o' ? cfg->out_dir : c == OPT_REPLAY ? cfg->replay
                  : c == OPT_SCREEN ? cfg->screen : cfg->gnuplot_style;
        if (!*arg || strlen(arg) >= PATH_MAX) {
            snprintf(why, n, "--%s: a path of 1 to %d characters is needed", name, PATH_MAX - 1);
            return 2;
        }
        snprintf(dst, PATH_MAX, "%s", arg);
        return 0;
    }
    case OPT_COST_EPS: case OPT_COST_NODES:
        snprintf(c == OPT_COST_EPS ? cli->cost_eps : cli->cost_nodes, 256, "%s", arg);
        cli->action = ADH_ACT_COST;
        return 0;
    case OPT_NO_CLOCK: cfg->no_clock = 1; return 0;
    case OPT_NO_PLOT: cfg->plot = 0; return 0;
    case 'q': cfg->quiet = 1; return 0;
    case 'b': if (cli->action == ADH_ACT_TUI) cli->action = ADH_ACT_BATCH; return 0;
    case OPT_PLAN: cli->action = ADH_ACT_PLAN; return 0;
    case OPT_COST: cli->action = ADH_ACT_COST; return 0;
    case OPT_LIST_KEYS: cli->action = ADH_ACT_LIST_KEYS; return 0;
    case 'h': cli->action = ADH_ACT_HELP; return 0;
    case 'V': cli->action = ADH_ACT_VERSION; return 0;
    }
    snprintf(why, n, "internal: option %d has no handler", c);
    return 2;
}

int adh_cli_parse(int argc, char **argv, adh_cli *cli, char *why, size_t whylen)
{
    struct option longopts[NOPTIONS + 1];
    char shortopts[3 * NOPTIONS + 2] = ":";
    size_t sl = 1;
    for (size_t i = 0; i < NOPTIONS; i++) {
        longopts[i] = options[i].opt;
        if (options[i].opt.val < 256) {
            shortopts[sl++] = (char)options[i].opt.val;
            if (options[i].opt.has_arg == required_argument)
                shortopts[sl++] = ':';
        }
    }
    shortopts[sl] = '\0';
    memset(&longopts[NOPTIONS], 0, sizeof longopts[0]);
    memset(cli, 0, sizeof *cli);
    adh_config_default(&cli->cfg);

    /* Two passes: the scene (positional) sets values first, then the flags
     * override them whatever their order on the line. */
    struct { int c; const char *arg; const char *name; } seen[512];
    size_t nseen = 0;
    opterr = 0;
    optind = 1;
    int c, idx;
    while ((c = getopt_long(argc, argv, shortopts, longopts, &idx)) != -1) {
        if (c == '?') {
            if (optopt)
                snprintf(why, whylen, "unknown option '-%c' (see adhere --help)", optopt);
            else
                snprintf(why, whylen, "unknown option '%s' (see adhere --help)", argv[optind - 1]);
            return 2;
        }
        if (c == ':') {
            snprintf(why, whylen, "option '%s' needs a value (see adhere --help)", argv[optind - 1]);
            return 2;
        }
        if (nseen == sizeof seen / sizeof seen[0]) {
            snprintf(why, whylen, "too many options");
            return 2;
        }
        const char *name = "?";
        for (size_t i = 0; i < NOPTIONS; i++)
            if (options[i].opt.val == c)
                name = options[i].opt.name;
        seen[nseen].c = c;
        seen[nseen].arg = optarg;
        seen[nseen].name = name;
        nseen++;
    }
    if (optind < argc - 1) {
        snprintf(why, whylen, "more than one scene given ('%s' and '%s'): name at most one", argv[optind], argv[optind + 1]);
        return 2;
    }
    if (optind == argc - 1) {
        cli->scene_arg = argv[optind];
        int rc = adh_scene_load(cli->scene_arg, &cli->cfg, why, whylen);
        if (rc != 0)
            return 2;
    }
    for (size_t i = 0; i < nseen; i++)
        if (apply(cli, seen[i].c, seen[i].arg, seen[i].name, why, whylen) != 0)
            return 2;
    return 0;
}

static int validate_run(const adh_config *cfg, char *why, size_t whylen);

/* A sweep is valid when every one of its runs is (each sets its own E or eps). */
int adh_cli_validate(const adh_config *cfg, char *why, size_t whylen)
{
    if (cfg->sweep.kind == ADH_SWEEP_NONE)
        return validate_run(cfg, why, whylen);
    for (size_t i = 0; i < cfg->sweep.n; i++) {
        adh_config run;
        char msg[1024];
        adh_config_sweep_run(cfg, i, &run);
        if (validate_run(&run, msg, sizeof msg) != 0) {
            snprintf(why, whylen, "sweep run %zu (%s = %g): %s", i + 1, adh_sweep_name(cfg->sweep.kind),
                     cfg->sweep.values[i], msg);
            return 2;
        }
    }
    return 0;
}

static int validate_run(const adh_config *cfg, char *why, size_t whylen)
{
    if (adh_material_validate(&cfg->mat, why, whylen) != ADH_SUCCESS)
        return 2;
    if (adh_relax_settings_validate(&cfg->relax, why, whylen) != ADH_SUCCESS)
        return 2;
    double dr = adh_config_spacing(cfg);
    if (!(isfinite(dr) && dr > 0)) {
        snprintf(why, whylen, "spacing = %g m is not allowed: it must be above 0", dr);
        return 2;
    }
    if (!(isfinite(cfg->drive_speed) && cfg->drive_speed > 0 && cfg->drive_speed < 1e3)) {
        snprintf(why, whylen, "drive speed %g m/s is not allowed: it must be above 0 and below 1000 m/s", cfg->drive_speed);
        return 2;
    }
    if (adh_config_grid_check(cfg, why, whylen) != 0)
        return 2;
    adh_grid *g = adh_config_grid_alloc(cfg);
    if (!g) {
        snprintf(why, whylen, "out of memory for a grid of %zu nodes", cfg->nodes);
        return 2;
    }
    int rc = adh_protocol_check(&cfg->proto, &cfg->mat, g, why, whylen);
    adh_grid_free(g);
    return rc == ADH_SUCCESS ? 0 : 2;
}
