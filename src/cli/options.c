#include "cli/options.h"

#include <ctype.h>
#include <getopt.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>
#include <sys/stat.h>
#include <unistd.h>

#include "adhere/drive.h"
#include "adhere/grid.h"
#include "adhere/status.h"
#include "adhere/units.h"
#include "cli/advice.h"
#include "scene/text.h"
#include "cli/studyrow.h"
#include "plot/outdir.h"
#include "scene/scene.h"
#include "adhere/run.h"

enum {
    OPT_SPACING = 256, OPT_START, OPT_TURN, OPT_KERNEL, OPT_REPLAY, OPT_SCREEN, OPT_SIZE,
    OPT_NO_CLOCK, OPT_LIST_KEYS, OPT_NO_PLOT, OPT_PLOTS, OPT_PROFILES, OPT_DRIVE_SPEED,
    OPT_GNUPLOT_STYLE, OPT_PLAN, OPT_DWELL, OPT_MODE, OPT_REFERENCE, OPT_COST, OPT_COST_EPS,
    OPT_COST_NODES, OPT_MAX_ITER, OPT_MIXING, OPT_MOMENTUM, OPT_ALLOW_UNCONVERGED, OPT_FORCE, OPT_DATA,
    OPT_GRID, OPT_FINE_BAND, OPT_GROWTH, OPT_GRID_RADIUS, OPT_OPERATOR, OPT_OVERWRITE, OPT_COLUMNS, OPT_FREE,
    OPT_MODEL, OPT_OFFSET, OPT_BASELINE, OPT_MATERIAL, OPT_E0, OPT_EINF, OPT_TAU, OPT_SPEED, OPT_DWELL_TIME,
    OPT_SPRING, OPT_TIME_TOL,
    OPT_SWEEP, OPT_RUN_DIRS, OPT_SHARD, OPT_ALLOW_PARTIAL
};

typedef struct option_doc {
    struct option opt;
    const char *arg;     /* argument name for --help, NULL if none */
    const char *help;
    const char *key;     /* the configuration key it sets (adh_config_set); NULL: an action or the CLI's own */
    const char *value;   /* a flag without an argument: the text it sets its key to */
} option_doc;

/* The one list of options: getopt_long's table and --help are both made from
 * it, so they cannot drift apart (the man page test checks the third copy).
 * A flag that sets the configuration names its key: the flag's value goes
 * through adh_config_set, as a scene's and a TUI edit's do. */
static const option_doc options[] = {
    { { "modulus", required_argument, 0, 'E' }, "PA", "combined modulus E, 2/E = sum (1-nu^2)/E_i (default 0.3GPa, Figure 4)", "material.E", NULL },
    { { "hamaker", required_argument, 0, 'A' }, "J", "Hamaker constant A (default 1e-19J)", "material.A", NULL },
    { { "z0", required_argument, 0, 'z' }, "M", "Lennard-Jones equilibrium separation z0 (default 0.5nm)", "material.z0", NULL },
    { { "radius", required_argument, 0, 'R' }, "M", "effective radius R (default 10um)", "material.R", NULL },
    { { "material", required_argument, 0, OPT_MATERIAL }, "elastic|sls", "elastic spheres, or a standard linear solid run in physical time (default elastic)", "material.material", NULL },
    { { "E0", required_argument, 0, OPT_E0 }, "PA", "sls: relaxed modulus E0, the material's E under its solid's name", "material.E0", NULL },
    { { "Einf", required_argument, 0, OPT_EINF }, "PA|auto", "sls: instantaneous modulus, at least E0 (default auto: 10 E0)", "material.Einf", NULL },
    { { "tau", required_argument, 0, OPT_TAU }, "S", "sls: relaxation time of the creep compliance (default 1ms)", "material.tau", NULL },
    { { "nodes", required_argument, 0, 'N' }, "N|auto", "grid nodes N, 10 to 20000 (default 1000, more where the contact edge needs it)", "grid.nodes", NULL },
    { { "spacing", required_argument, 0, OPT_SPACING }, "M|auto", "grid spacing (default: the paper's 0.0212 sqrt(R z0), or finer where the contact edge needs it)", "grid.spacing", NULL },
    { { "force", no_argument, 0, OPT_FORCE }, NULL, "run a grid coarser than the resolved limit (0.45 edge-zone widths, static 0.3); marked resolved 0", "grid.force", "yes" },
    { { "kernel", required_argument, 0, OPT_KERNEL }, "paper|ring", "elastic kernel: the paper's eqs 18-21 or exact rings (default paper)", "grid.kernel", NULL },
    { { "grid", required_argument, 0, OPT_GRID }, "uniform|graded", "radial grid: N equal rings, or fine rings over the contact then growing ones (default uniform; graded when neither N nor the spacing is given and a resolved uniform grid needs over 1000 nodes)", "grid.grid", NULL },
    { { "fine-band", required_argument, 0, OPT_FINE_BAND }, "M|auto", "graded grid: radius of the fine band (default, auto: 1.25 x the contact expected at the deepest turn, JKR or overlap)", "grid.fine_band", NULL },
    { { "growth", required_argument, 0, OPT_GROWTH }, "R", "graded grid: width ratio of neighbouring rings past the band, 1 to 1.1 (default 1.05)", "grid.growth", NULL },
    { { "grid-radius", required_argument, 0, OPT_GRID_RADIUS }, "M|auto", "graded grid: outer radius Rmax (default, auto: the default uniform grid's, 1.5um at R=10um, z0=0.5nm)", "grid.radius", NULL },
    { { "operator", required_argument, 0, OPT_OPERATOR }, "dense|hmat|h2", "how the kernel is held: dense matrix, hierarchical by hmat-oss, or H^2 (default: h2 for the relaxation from 256 nodes on a uniform grid, past 4000 nodes and on an automatic graded grid; else dense)", "grid.operator", NULL },
    { { "eps", required_argument, 0, 'e' }, "M", "convergence: the change per iteration below this ends a step, measured as the paper's sqrt(sum du^2)/N on its own grid, so the same eps is the same drive on every grid (default 1pm)", "solver.eps", NULL },
    { { "max-iter", required_argument, 0, OPT_MAX_ITER }, "N", "iteration cap per step; reaching it is reported (default 200000)", "solver.max_iter", NULL },
    { { "allow-unconverged", no_argument, 0, OPT_ALLOW_UNCONVERGED }, NULL, "accept steps that reach the cap: exit 0 (the summary still says unconverged)", "output.allow_unconverged", "yes" },
    { { "mixing", required_argument, 0, OPT_MIXING }, "paper|momentum", "mixing rule of the relaxation: the paper's adaptive ratio or heavy-ball momentum (default momentum)", "solver.mixing", NULL },
    { { "momentum", required_argument, 0, OPT_MOMENTUM }, "B", "momentum rule: fraction of the previous update kept, 0 to below 1 (default 0.55)", "solver.momentum", NULL },
    { { "step", required_argument, 0, 'd' }, "M", "drive step d (default 0.05nm)", "protocol.step", NULL },
    { { "start", required_argument, 0, OPT_START }, "M|auto", "first drive position h0 (default: where the force is negligible)", "protocol.start", NULL },
    { { "turn", required_argument, 0, OPT_TURN }, "M[,M...]", "turning points (default -5nm); 'none' loads to contact only", "protocol.turns", NULL },
    { { "turns", required_argument, 0, OPT_TURN }, "M[,M...]", "the same as --turn, by the scene key's name", "protocol.turns", NULL },
    { { "dwell", required_argument, 0, OPT_DWELL }, "N", "iterations held at each turning point before unloading (default 0)", "protocol.dwell", NULL },
    { { "speed", required_argument, 0, OPT_SPEED }, "M/S[,M/S]", "physical time: the base's speed, or approach and retraction speeds (default 1um/s)", "protocol.speed", NULL },
    { { "dwell-time", required_argument, 0, OPT_DWELL_TIME }, "S", "physical time: held at each turn before retracting (default 0)", "protocol.dwell_time", NULL },
    { { "spring", required_argument, 0, OPT_SPRING }, "N/M|none", "instrument spring k between the base and the sphere: physical time, or the static curve's snap points (default none)", "protocol.spring", NULL },
    { { "time-tol", required_argument, 0, OPT_TIME_TOL }, "X", "sls: relative tolerance of the time integration, 1e-10 to 1e-2 (default 5e-5)", "solver.time_tol", NULL },
    { { "mode", required_argument, 0, OPT_MODE }, "relax|static|rigid|time", "paper's relaxation, the static equilibrium curve, rigid spheres only (eq 22, no elastic solve), or physical time (default relax; time with --material=sls)", "scene.mode", NULL },
    { { "reference", required_argument, 0, OPT_REFERENCE }, "static|none", "also compute the static curve as a reference in relaxation mode (none: not, the default)", NULL, NULL },
    { { "batch", no_argument, 0, 'b' }, NULL, "run the protocol without the TUI and write tables", NULL, NULL },
    { { "out", required_argument, 0, 'o' }, "DIR", "write force.tsv, summary.tsv, turns.tsv and plots into DIR (created)", "output.dir", NULL },
    { { "overwrite", no_argument, 0, OPT_OVERWRITE }, NULL, "replace files in DIR under adhere's names that it did not write (else refused)", "output.overwrite", "yes" },
    { { "no-plot", no_argument, 0, OPT_NO_PLOT }, NULL, "write no PNG plots", "output.plot", "no" },
    { { "plots", required_argument, 0, OPT_PLOTS }, "LIST", "plots to write: force,profile,contact,precontact,bulge or none (default force,profile,contact)", "output.plots", NULL },
    { { "profiles", required_argument, 0, OPT_PROFILES }, "M[,M...]", "drive positions where surface profiles are stored", "output.profiles", NULL },
    { { "drive-speed", required_argument, 0, OPT_DRIVE_SPEED }, "M/S", "drive speed for contact-line speeds (default 1um/s)", "output.drive_speed", NULL },
    { { "gnuplot-style", required_argument, 0, OPT_GNUPLOT_STYLE }, "FILE|DIR", "gnuplot style file, or a directory holding style.gp, overriding the installed one", "output.gnuplot_style", NULL },
    { { "data", required_argument, 0, OPT_DATA }, "FILE", "a measured force-position curve (nm, nN, or the header's units) drawn over force.png and the TUI preview; up to 8, each in the key", NULL, NULL },
    { { "columns", required_argument, 0, OPT_COLUMNS }, "POS,FORCE", "--data's position and force columns, by number from 1 or header name (default: the only two, or by name)", NULL, NULL },
    { { "free", required_argument, 0, OPT_FREE }, "LIST", "adhere fit: the parameters to fit, from E,A,z0,R,offset,baseline, and E0,Einf,tau with --model=time (default E,A; E0,A,Einf,tau)", NULL, NULL },
    { { "model", required_argument, 0, OPT_MODEL }, "static|relax|time", "adhere fit: the static curve, the relaxation's loading and unloading branches, or a standard linear solid's in physical time (--material=sls; default static)", NULL, NULL },
    { { "offset", required_argument, 0, OPT_OFFSET }, "M", "adhere fit: start value of the position offset (model h0 = measured - offset, default 0)", NULL, NULL },
    { { "baseline", required_argument, 0, OPT_BASELINE }, "N", "adhere fit: start value of the force baseline (measured = model + baseline, default 0)", NULL, NULL },
    { { "sweep", required_argument, 0, OPT_SWEEP }, "KEY=VALUES", "sweep KEY (E, sigma, turns, ...) over V1,V2,... or LO..HI,[lin|log,]N; given again, every combination (as [sweep])", NULL, NULL },
    { { "jobs", required_argument, 0, 'j' }, "N|auto", "runs of a sweep at once (default auto: one per core)", "sweep.jobs", NULL },
    { { "run-dirs", required_argument, 0, OPT_RUN_DIRS }, "yes|no|auto", "a sweep's run-K directories, each run's tables and plots (default auto: up to 32 runs)", "sweep.run_dirs", NULL },
    { { "shard", required_argument, 0, OPT_SHARD }, "K/N", "run shard K of N of a sweep (its drives K, K+N, ...) into -o DIR; a rerun skips the runs done", NULL, NULL },
    { { "allow-partial", no_argument, 0, OPT_ALLOW_PARTIAL }, NULL, "adhere merge: join shards with runs missing (sweep.tsv says # PARTIAL)", NULL, NULL },
    { { "plan", no_argument, 0, OPT_PLAN }, NULL, "print the run plan (branches, steps, what is stored) and exit", NULL, NULL },
    { { "cost", no_argument, 0, OPT_COST }, NULL, "report what accuracy costs: runs over a grid of eps, N and kernels", NULL, NULL },
    { { "cost-eps", required_argument, 0, OPT_COST_EPS }, "M[,M...]", "eps values of the cost grid (default 2,1,0.5,0.2,0.1pm)", NULL, NULL },
    { { "cost-nodes", required_argument, 0, OPT_COST_NODES }, "N[,N...]", "node counts of the cost grid (default 500,1000,2000)", NULL, NULL },
    { { "replay", required_argument, 0, OPT_REPLAY }, "FILE", "drive the TUI from a keystroke script, with no terminal", "tui.replay", NULL },
    { { "screen", required_argument, 0, OPT_SCREEN }, "FILE", "write the final TUI screen as text (with --replay)", "tui.screen", NULL },
    { { "size", required_argument, 0, OPT_SIZE }, "COLSxROWS", "screen size for --replay (default 100x32)", "tui.size", NULL },
    { { "no-clock", no_argument, 0, OPT_NO_CLOCK }, NULL, "mask timings on the screen so replays are deterministic", "tui.no_clock", "yes" },
    { { "list-keys", no_argument, 0, OPT_LIST_KEYS }, NULL, "print the TUI's keys and exit", NULL, NULL },
    { { "quiet", no_argument, 0, 'q' }, NULL, "no progress line, notes or closing line on standard error (warnings stay)", "output.quiet", "yes" },
    { { "help", no_argument, 0, 'h' }, NULL, "print this help and exit", NULL, NULL },
    { { "version", no_argument, 0, 'V' }, NULL, "print the version and exit", NULL, NULL },
};
#define NOPTIONS (sizeof options / sizeof options[0])

void cli_options_usage(FILE *out)
{
    fprintf(out, "usage: adhere [OPTIONS] [SCENE]\n"
                 "       adhere fit --data=FILE [--free=LIST] [OPTIONS] [SCENE]\n"
                 "       adhere merge [-o DIR] [--allow-partial] SHARD_DIR...\n"
                 "Two elastic spheres with a Lennard-Jones surface force (Attard 2000).\n"
                 "Without --batch, opens the TUI; fit fits the model to a measured curve.\n"
                 "Numbers are SI or take a unit: 1GPa 0.5nm 10um 1e-19J.\n\n");
    for (size_t i = 0; i < NOPTIONS; i++) {
        const option_doc *o = &options[i];
        char lhs[64];
        int n = 0;
        if (o->opt.val < 256)
            n = snprintf(lhs, sizeof lhs, "-%c, ", o->opt.val);
        else
            n = snprintf(lhs, sizeof lhs, "    ");
        snprintf(lhs + n, sizeof lhs - (size_t)n, "--%s%s%s", o->opt.name, o->arg ? "=" : "", o->arg ? o->arg : "");
        if (strlen(lhs) > 28)   /* too long for the column: the help on the next line, in the column */
            fprintf(out, "  %s\n  %-28s %s\n", lhs, "", o->help);
        else
            fprintf(out, "  %-28s %s\n", lhs, o->help);
    }
    fprintf(out, "\nSCENE is a scene file or the name of a shipped one (default, fig1 ... fig8, visco,\n"
                 "visco-speed, afm).\n"
                 "See adhere(1) and adhere-scene(5).\n");
}

/* The flag that sets key, "" when none does. */
static const char *flag_of(const char *key)
{
    for (size_t i = 0; i < NOPTIONS; i++)
        if (options[i].key && strcmp(options[i].key, key) == 0)
            return options[i].opt.name;
    return "";
}

/* How a sentence names its keys: the keys the scene set, and the flags
 * set, among those it names; the scene's keys already located. */
typedef struct voice {
    const adh_config *cfg;
    int scene, flag;               /* the sentence names a key the scene (a flag) set */
    char located[8][40];           /* scene keys already given their file and line */
    size_t nlocated;
    int file_named;                /* the scene's file named once: later keys say "line N" */
} voice;

/* The first pass: whose keys the sentence names. */
static void hear(const char *key, const char *value, char *buf, size_t len, void *ctx)
{
    voice *v = ctx;
    int from = adh_config_origin(v->cfg, key);
    v->scene |= from == -1 || from > 0;
    v->flag |= from == 0;
    snprintf(buf, len, "%s", key);
}

/* A scene key's first mention: where it was written, the file once. */
static void locate(voice *v, const char *key, int line, char *buf, size_t len)
{
    for (size_t i = 0; i < v->nlocated; i++)
        if (!strcmp(v->located[i], key))
            return;
    if (v->nlocated < sizeof v->located / sizeof v->located[0])
        snprintf(v->located[v->nlocated++], sizeof v->located[0], "%s", key);
    size_t n = strlen(buf);
    if (line > 0 && v->file_named)
        snprintf(buf + n, len - n, " (line %d)", line);
    else if (line > 0)
        snprintf(buf + n, len - n, " (%s:%d)", v->cfg->scene, line);
    else
        snprintf(buf + n, len - n, " (%s)", v->cfg->scene);
    v->file_named = 1;
}

/* The second pass: a key a flag set (or nobody, in a sentence not the
 * scene's alone) becomes its flag (--kernel), "key = value" the flag with
 * its value (--kernel=paper); a scene's key its name under its section
 * (kernel = paper), located. */
static void say_flag(const char *key, const char *value, char *buf, size_t len, void *ctx)
{
    voice *v = ctx;
    int from = adh_config_origin(v->cfg, key);
    const adh_config_key *k = adh_config_key_find(key);
    int scene = from == -1 || from > 0 || (from == -2 && v->scene && !v->flag);
    const char *flag = flag_of(key), *dot = strchr(key, '.'), *swept = adh_config_swept_as(v->cfg, key);
    if (scene && k && (k->where & ADH_KEY_SCENE) && dot)
        snprintf(buf, len, "%s%s%s", dot + 1, value ? " = " : "", value ? value : "");
    else if (from == 0 && swept)   /* a run's value of --sweep=E=1GPa,2GPa: --sweep=E=1GPa */
        snprintf(buf, len, "--sweep=%s%s%s", swept, value ? "=" : "", value ? value : "");
    else if (!*flag)
        snprintf(buf, len, "%s%s%s", key, value ? " = " : "", value ? value : "");
    else
        snprintf(buf, len, "--%s%s%s", flag, value ? "=" : "", value ? value : "");
    if ((from == -1 || from > 0) && v->cfg->scene[0])
        locate(v, key, from, buf, len);
}

void cli_options_words(const adh_config *cfg, const char *sentence, char *out, size_t len)
{
    voice v = { .cfg = cfg };
    adh_config_reword(sentence, hear, &v, out, len);
    adh_config_reword(sentence, say_flag, &v, out, len);
}

/* cli_options_words as an adh_config_words (ctx: the configuration) */
static void flag_words(const char *in, void *ctx, char *out, size_t len)
{
    cli_options_words(ctx, in, out, len);
}

void cli_options_core_words(const adh_config *cfg, const adh_run_spec *run, cli_advice_for who, const char *sentence,
                            char *out, size_t len)
{
    char keyed[1200];
    const char *key = adh_config_key_opening(cfg, run, sentence, keyed, sizeof keyed);
    if (key && who == CLI_ADVICE_COST && (!strcmp(key, "grid.nodes") || !strcmp(key, "solver.eps")))
        snprintf(keyed, sizeof keyed, "%s", sentence);
    cli_options_words(cfg, keyed, out, len);
}

/* strtok would pass over an empty element ("1pm,,2pm"): refuse it. */
static int empty_element(const char *name, const char *arg, char *why, size_t n)
{
    size_t len = strlen(arg);
    if (len == 0 || arg[0] == ',' || arg[len - 1] == ',' || strstr(arg, ",,")) {
        snprintf(why, n, "--%s: '%s' has an empty element: separate values by single commas", name, arg);
        return 1;
    }
    return 0;
}

/* --data (repeatable: the first is also the configuration's output.data),
 * --columns and adhere fit's own flags, kept as typed. */
static int apply_data_fit(cli_options *cli, const option_doc *o, const char *arg, char *why, size_t n)
{
    const char *name = o->opt.name;
    char msg[512];
    switch (o->opt.val) {
    case OPT_DATA:
        if (cli->ndata == CLI_MAX_DATA) {
            snprintf(why, n, "--data: at most %d files", CLI_MAX_DATA);
            return 2;
        }
        if (cli->ndata == 0 && adh_config_set(&cli->cfg, "output.data", arg, msg, sizeof msg) != 0) {
            snprintf(why, n, "--data: %s", msg);
            return 2;
        }
        cli->data[cli->ndata++] = arg;
        return 0;
    case OPT_COLUMNS:
        if (!*arg) {   /* refused as every flag's empty value is: not the default guessed */
            snprintf(why, n, "--columns: '' names no column: give POS,FORCE, each a number from 1 or a header name");
            return 2;
        }
        if (strlen(arg) >= sizeof cli->columns) {
            snprintf(why, n, "--columns: longer than %zu characters", sizeof cli->columns - 1);
            return 2;
        }
        snprintf(cli->columns, sizeof cli->columns, "%s", arg);
        return 0;
    case OPT_FREE: case OPT_MODEL: {
        char *dst = o->opt.val == OPT_FREE ? cli->fit.free : cli->fit.model;
        size_t len = o->opt.val == OPT_FREE ? sizeof cli->fit.free : sizeof cli->fit.model;
        if (!*arg) {   /* '' is the default's mark: given, it is refused, not taken for E,A or static */
            snprintf(why, n, o->opt.val == OPT_FREE ? "--free: '' names no parameter: use E, A, z0, R, offset and "
                                                      "baseline (and E0, Einf and tau with --model=time), separated by "
                                                      "commas"
                                                    : "--model: '' is not a model: use static, relax or time");
            return 2;
        }
        if (strlen(arg) >= len) {
            snprintf(why, n, "--%s: '%s' is too long", name, arg);
            return 2;
        }
        if (o->opt.val == OPT_FREE && empty_element(name, arg, why, n))   /* 'E,' */
            return 2;
        if (o->opt.val == OPT_FREE && *dst) {   /* the second list replaced the first without a word */
            snprintf(why, n, "--free given twice ('%s' and '%s'): give one list, --free=%s,%s", dst, arg, dst, arg);
            return 2;
        }
        memcpy(dst, arg, strlen(arg) + 1);   /* fits: checked above */
        cli->fit.given = 1;
        return 0;
    }
    case OPT_OFFSET: case OPT_BASELINE:
        cli->fit.given = 1;
        if (adh_parse_quantity(arg, o->opt.val == OPT_OFFSET ? ADH_Q_LENGTH : ADH_Q_FORCE,
                               o->opt.val == OPT_OFFSET ? &cli->fit.offset : &cli->fit.baseline, msg, sizeof msg) != 0) {
            snprintf(why, n, "--%s: %s", name, msg);
            return 2;
        }
        return 0;
    }
    return -1;
}

/* adhere fit's line: a fit, not a run, so the run's actions do not go with it. */
static int fit_check(cli_options *cli, int action, char *why, size_t whylen)
{
    if (action) {
        snprintf(why, whylen, "adhere fit fits and writes its report: --batch, --plan, --cost, --replay, --help and "
                 "--version do not go with it");
        return 2;
    }
    if (cli->ndata == 0) {
        snprintf(why, whylen, "adhere fit needs the measured curve: --data=FILE");
        return 2;
    }
    /* what the fit's model does not hold was silently left out of it */
    if (cli->cfg.sweep.naxes) {
        snprintf(why, whylen, "adhere fit fits one model to the curve: a sweep (of %s, from --sweep or the scene's "
                 "[sweep]) would be ignored; leave it out, the scene's own values are the start", cli->cfg.sweep.axis[0].name);
        return 2;
    }
    adh_mode mode = cli->cfg.spec.mode;
    const char *model = cli->fit.model;
    if (*model && strcmp(model, "static") != 0 && strcmp(model, "relax") != 0 && strcmp(model, "time") != 0) {
        snprintf(why, whylen, "--model: '%s' is not a model: use static, relax or time", model);
        return 2;
    }
    if (strcmp(model, "time") == 0) {   /* the solid in physical time, its drive and spring: fit.c checks */
        if (mode == ADH_MODE_RIGID || mode == ADH_MODE_STATIC) {
            snprintf(why, whylen, "adhere fit --model=time runs its model in physical time: mode = %s would be "
                     "ignored; leave it out", mode == ADH_MODE_RIGID ? "rigid" : "static");
            return 2;
        }
        cli->action = CLI_ACT_FIT;
        return 0;
    }
    if (mode == ADH_MODE_TIME && cli->cfg.spec.time.sls) {   /* the solid chose the mode: "leave it out" named none given */
        /* in the words the solid was given in: the flag, or the scene's key */
        cli_options_words(&cli->cfg, "adhere fit's models are the static curve and the relaxation (--model=static|relax) "
                          "of an elastic sphere: material.material = sls, a standard linear solid in physical time, would be "
                          "ignored; give material.material = elastic, with E for its modulus, or --model=time to fit the solid", why, whylen);
        return 2;
    }
    unsigned drive = cli->cfg.spec.time.given & (ADH_TIME_SPEED | ADH_TIME_DWELL | ADH_TIME_SPRING);
    if (mode == ADH_MODE_TIME && !(cli->cfg.spec.time.given & ADH_TIME_MODE) && drive) {   /* an elastic sphere's drive */
        snprintf(why, whylen, "adhere fit's models are the static curve and the relaxation (--model=static|relax): "
                 "the %s given puts the sphere in physical time, which would be ignored; leave it out",
                 drive & ADH_TIME_SPEED ? "speed" : drive & ADH_TIME_DWELL ? "dwell_time" : "spring");
        return 2;
    }
    if (mode == ADH_MODE_TIME || mode == ADH_MODE_RIGID) {
        snprintf(why, whylen, "adhere fit's models are the static curve and the relaxation (--model=static|relax): "
                 "mode = %s would be ignored; leave it out", mode == ADH_MODE_TIME ? "time" : "rigid");
        return 2;
    }
    if (isfinite(cli->cfg.spec.time.spring)) {
        snprintf(why, whylen, "adhere fit's model has no spring: spring = %s would be ignored; give the positions as "
                 "the tip-sample separation h0 = base + F/k (the piezo's position corrected for the cantilever's "
                 "bending) and leave the spring out", adh_qtext(cli->cfg.spec.time.spring, ADH_Q_STIFFNESS).s);
        return 2;
    }
    cli->action = CLI_ACT_FIT;
    return 0;
}

/* A key a flag set, and its text, kept for the study's fingerprint. */
static int record(cli_options *cli, const char *key, const char *value, char *why, size_t n)
{
    if (cli->nset == CLI_MAX_SET) {
        snprintf(why, n, "more than %d options", CLI_MAX_SET);
        return 2;
    }
    cli_set *s = &cli->set[cli->nset++];
    snprintf(s->key, sizeof s->key, "%s", key);
    s->value = value;
    return 0;
}

/* --sweep KEY=VALUES: the key sweep.KEY, as a scene's [sweep] KEY = VALUES. */
static int sweep_flag(cli_options *cli, const char *arg, char *why, size_t n)
{
    const char *eq = strchr(arg, '=');
    char key[64], msg[512];
    if (!eq || eq == arg || (size_t)(eq - arg) >= sizeof key - 6) {
        snprintf(why, n, "--sweep: '%.100s' is not KEY=VALUES (e.g. --sweep=E=1GPa,2GPa or --sweep='sigma=0.1..10,log,5')", arg);
        return 2;
    }
    snprintf(key, sizeof key, "sweep.%.*s", (int)(eq - arg), arg);
    /* one key, one --sweep: a second (E and material.E too) would silently
     * replace the first's values */
    char mine[64], theirs[64];
    for (size_t i = 0; i < cli->nset && adh_sweep_key_of(key + 6, mine, sizeof mine) == 0; i++)
        if (!strncmp(cli->set[i].key, "sweep.", 6) && adh_sweep_key_of(cli->set[i].key + 6, theirs, sizeof theirs) == 0 &&
            !strcmp(mine, theirs)) {
            snprintf(why, n, "--sweep: %s swept twice (--sweep=%s=... and --sweep=%.*s=...): give its values once",
                     mine, cli->set[i].key + 6, (int)(eq - arg), arg);
            return 2;
        }
    if (adh_config_set(&cli->cfg, key, eq + 1, msg, sizeof msg) != 0) {
        snprintf(why, n, "--sweep: %.*s: %s", (int)(eq - arg), arg, msg);
        return 2;
    }
    adh_config_note_origin(&cli->cfg, key, 0);
    return record(cli, key, eq + 1, why, n);
}

/* --shard K/N: 1 <= K <= N <= 100000. */
static int shard_flag(cli_options *cli, const char *arg, char *why, size_t n)
{
    unsigned k, m;
    char extra;
    if (sscanf(arg, "%u/%u%c", &k, &m, &extra) != 2 || k < 1 || k > m || m > ADH_SWEEP_MAX_RUNS || !isdigit((unsigned char)arg[0])) {
        snprintf(why, n, "--shard: '%.60s' is not allowed: use K/N with 1 <= K <= N <= %d (shard K of N)", arg, ADH_SWEEP_MAX_RUNS);
        return 2;
    }
    cli->shard_k = k;
    cli->shard_n = m;
    return 0;
}

/* A flag: its key's value through adh_config_set, or the CLI's own. */
static int apply(cli_options *cli, const option_doc *o, const char *arg, char *why, size_t n)
{
    int rc = apply_data_fit(cli, o, arg, why, n);
    if (rc >= 0)
        return rc;
    const char *name = o->opt.name;
    if (o->key) {
        char msg[512], words[600];
        if (adh_config_set(&cli->cfg, o->key, o->value ? o->value : arg, msg, sizeof msg) == 0) {
            snprintf(words, sizeof words, "--%s", name);
            adh_config_note_given(&cli->cfg, o->key, o->value ? o->value : arg, words);
            adh_config_note_origin(&cli->cfg, o->key, 0);
            return record(cli, o->key, o->value ? o->value : arg, why, n);
        }
        /* "--nodes=5 is not allowed", not "--nodes: N = 5 nodes is ..." */
        char setting[600];
        snprintf(setting, sizeof setting, "--%s=%s", name, o->value ? o->value : arg);
        snprintf(words, sizeof words, "--%s", name);
        adh_config_refusal(o->key, setting, words, msg, flag_words, &cli->cfg, why, n);
        return 2;
    }
    switch (o->opt.val) {
    case OPT_SWEEP:
        return sweep_flag(cli, arg, why, n);
    case OPT_SHARD:
        return shard_flag(cli, arg, why, n);
    case OPT_ALLOW_PARTIAL:
        cli->allow_partial = 1;
        return 0;
    case OPT_REFERENCE:
        if (strcmp(arg, "static") != 0 && strcmp(arg, "none") != 0) {
            snprintf(why, n, "--reference: '%s' is not allowed: use static or none", arg);
            return 2;
        }
        snprintf(cli->reference, sizeof cli->reference, "%s", strcmp(arg, "none") ? arg : "");
        return 0;
    case OPT_COST_EPS: case OPT_COST_NODES:
        if (empty_element(name, arg, why, n))
            return 2;
        if (strlen(arg) >= 256) {
            snprintf(why, n, "--%s: list longer than 255 characters", name);
            return 2;
        }
        snprintf(o->opt.val == OPT_COST_EPS ? cli->cost_eps : cli->cost_nodes, 256, "%s", arg);
        cli->action = CLI_ACT_COST;
        return 0;
    case 'b': if (cli->action == CLI_ACT_TUI) cli->action = CLI_ACT_BATCH; return 0;
    case OPT_PLAN: cli->action = CLI_ACT_PLAN; return 0;
    case OPT_COST: cli->action = CLI_ACT_COST; return 0;
    case OPT_LIST_KEYS: cli->action = CLI_ACT_LIST_KEYS; return 0;
    case 'h': cli->action = CLI_ACT_HELP; return 0;
    case 'V': cli->action = CLI_ACT_VERSION; return 0;
    }
    snprintf(why, n, "internal: option %s has no handler", name);
    return 2;
}

/* How far a name may be from the one meant: a letter in a short name, two
 * in a longer one. */
static size_t near_enough(const char *name)
{
    size_t n = strlen(name);
    return n >= 4 ? 2 : n >= 2 ? 1 : 0;
}

/* The option an unknown "--NAME[=VALUE]" most likely meant: a short
 * option's letter exactly ("--E": -E), a long name within a small edit
 * distance, or the name of the key a flag sets ("--max_iter": solver.max_iter,
 * --max-iter). */
static const option_doc *meant(const char *name, int *letter)
{
    const option_doc *best = NULL;
    size_t bd = near_enough(name) + 1;
    for (size_t i = 0; i < NOPTIONS; i++) {
        const option_doc *o = &options[i];
        size_t d = adh_config_name_distance(name, o->opt.name);
        if (o->opt.val < 256 && name[0] == o->opt.val && !name[1])
            d = 0;   /* the letter itself, case and all */
        if (o->key && strchr(o->key, '.')) {
            size_t dk = adh_config_name_distance(name, strchr(o->key, '.') + 1);
            d = dk < d ? dk : d;
        }
        if (d < bd) {
            bd = d;
            best = o;
        }
    }
    *letter = best && best->opt.val < 256 && name[0] == best->opt.val && !name[1];
    return best;
}

static void unknown_option(const char *arg, char *why, size_t whylen)
{
    char name[64];
    snprintf(name, sizeof name, "%s", arg + (arg[0] == '-' && arg[1] == '-' ? 2 : 0));
    char *eq = strchr(name, '=');
    const char *value = eq ? strchr(arg, '=') + 1 : NULL;
    if (eq)
        *eq = '\0';
    int letter = 0;
    const option_doc *o = arg[0] == '-' && arg[1] == '-' ? meant(name, &letter) : NULL;
    if (!o) {
        snprintf(why, whylen, "unknown option '%s' (see adhere --help)", arg);
        return;
    }
    char longform[300];
    snprintf(longform, sizeof longform, "--%s%s%.200s", o->opt.name, value && o->arg ? "=" : "",
             value && o->arg ? value : "");
    if (letter)   /* "--E=1GPa": -E 1GPa was meant */
        snprintf(why, whylen, "unknown option '%s': did you mean -%c%s%.200s (%s)? (see adhere --help)", arg,
                 o->opt.val, value ? " " : "", value ? value : "", longform);
    else
        snprintf(why, whylen, "unknown option '%s': did you mean %s? (see adhere --help)", arg, longform);
}

/* A positional that is no scene but a unit ("-E 1 GPa"): the number and
 * its unit were split by a space. */
static int split_unit_hint(int argc, char **orig, const char *arg, char *why, size_t whylen)
{
    double v;
    char probe[80];
    snprintf(probe, sizeof probe, "1%s", arg);
    int unit = 0;
    for (int q = ADH_Q_LENGTH; q <= ADH_Q_LAST && !unit; q++)
        unit = strlen(arg) < 16 && adh_parse_quantity(probe, (adh_quantity)q, &v, NULL, 0) == 0;
    if (!unit)
        return 0;
    for (int j = 1; j < argc; j++) {
        if (orig[j] != arg)
            continue;
        const char *num = j > 1 ? orig[j - 1] : "";
        const char *opt = j > 2 ? orig[j - 2] : "";
        if (adh_parse_quantity(num, ADH_Q_NONE, &v, NULL, 0) == 0 && opt[0] == '-') {
            snprintf(why, whylen, "'%s' looks like the unit of '%s %s': write the number and its unit together, %s %s%s",
                     arg, opt, num, opt, num, arg);
            return 1;
        }
    }
    snprintf(why, whylen, "'%s' is a unit, not a scene: write a value and its unit together (1%s)", arg, arg);
    return 1;
}

/* The flags as given, before any is applied: the scene comes first. */
typedef struct flags_seen {
    struct { const option_doc *o; const char *arg; } list[512];
    size_t n;
    int info, plan, cost, batch, replay, screen, size, reference;
} flags_seen;

static const option_doc *option_for(int val)
{
    for (size_t i = 0; i < NOPTIONS; i++)
        if (options[i].opt.val == val)
            return &options[i];
    return NULL;
}

/* getopt_long over argv into fs; 0, or 2 with why. */
static int collect(int argc, char **argv, flags_seen *fs, char *why, size_t whylen)
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
    memset(fs, 0, sizeof *fs);
    opterr = 0;
    optind = 1;
    int c, idx;
    while ((c = getopt_long(argc, argv, shortopts, longopts, &idx)) != -1) {
        if (c == '?') {
            if (optopt)
                snprintf(why, whylen, "unknown option '-%c' (see adhere --help)", optopt);
            else
                unknown_option(argv[optind - 1], why, whylen);
            return 2;
        }
        if (c == ':') {
            snprintf(why, whylen, "option '%s' needs a value (see adhere --help)", argv[optind - 1]);
            return 2;
        }
        if (fs->n == sizeof fs->list / sizeof fs->list[0]) {
            snprintf(why, whylen, "too many options");
            return 2;
        }
        fs->list[fs->n].o = option_for(c);
        fs->list[fs->n].arg = optarg;
        fs->n++;
        fs->info |= c == 'h' || c == 'V' || c == OPT_LIST_KEYS;
        fs->plan |= c == OPT_PLAN;
        fs->cost |= c == OPT_COST || c == OPT_COST_EPS || c == OPT_COST_NODES;
        fs->batch |= c == 'b';
        fs->replay |= c == OPT_REPLAY;
        fs->screen |= c == OPT_SCREEN;
        fs->size |= c == OPT_SIZE;
        fs->reference |= c == OPT_REFERENCE && strcmp(optarg, "none") != 0;
    }
    return 0;
}

/* adhere merge's line: directories, and only the flags about its own
 * outputs (the study itself is the shards'). */
static int merge_line(cli_options *cli, int argc, char **argv, const flags_seen *fs, char *why, size_t whylen)
{
    static const char *const allowed[] = { "out", "overwrite", "quiet", "no-plot", "gnuplot-style", "allow-partial" };
    for (size_t i = 0; i < fs->n; i++) {
        const char *name = fs->list[i].o->opt.name;
        size_t k = 0;
        while (k < sizeof allowed / sizeof allowed[0] && strcmp(allowed[k], name) != 0)
            k++;
        if (k == sizeof allowed / sizeof allowed[0]) {
            snprintf(why, whylen, "adhere merge takes the study from its shards' directories: --%s does not go with it "
                     "(merge takes -o, --overwrite, -q, --no-plot, --gnuplot-style and --allow-partial)", name);
            return 2;
        }
        if (apply(cli, fs->list[i].o, fs->list[i].arg, why, whylen) != 0)
            return 2;
    }
    if (optind >= argc) {
        snprintf(why, whylen, "merge: name the shards' directories (adhere merge -o DIR SHARD_DIR...)");
        return 2;
    }
    for (int i = optind; i < argc; i++) {
        if (cli->nmerge == CLI_MAX_MERGE) {
            snprintf(why, whylen, "merge: more than %d directories", CLI_MAX_MERGE);
            return 2;
        }
        cli->merge[cli->nmerge++] = argv[i];
    }
    cli->action = CLI_ACT_MERGE;
    return 0;
}

/* Flags that do not go together, and a scene beside what runs nothing. */
static int combinations(int argc, char **argv, const flags_seen *fs, char *why, size_t whylen)
{
    if (optind < argc - 1) {
        snprintf(why, whylen, "more than one scene given ('%s' and '%s'): name at most one", argv[optind], argv[optind + 1]);
        return 2;
    }
    /* --help, --version, --list-keys print and exit: a scene beside them is
     * a mistake, not something to load */
    if (fs->info && optind == argc - 1) {
        snprintf(why, whylen, "'%s': --help, --version and --list-keys take no scene and run nothing", argv[optind]);
        return 2;
    }
    if (fs->plan && fs->cost) {
        snprintf(why, whylen, "--plan and --cost do not go together: --plan prints one run's plan, --cost runs a grid of runs; give one");
        return 2;
    }
    if (fs->replay && (fs->batch || fs->plan || fs->cost)) {
        snprintf(why, whylen, "--replay drives the TUI from a script; it does not go with %s",
                 fs->batch ? "--batch" : fs->plan ? "--plan" : "--cost");
        return 2;
    }
    if (fs->screen && !fs->replay) {
        snprintf(why, whylen, "--screen writes the final screen of a --replay run: give --replay=FILE too");
        return 2;
    }
    /* a terminal has its own size: --size was dropped in silence without --replay */
    if (fs->size && !fs->replay) {
        snprintf(why, whylen, "--size sets the screen of a --replay run (a terminal keeps its own size): give "
                 "--replay=FILE too, or leave --size out");
        return 2;
    }
    return 0;
}

/* The files the session reads (adh_outdir_inputs), known once the line
 * is read: the one list that -o's clearing, --screen and the TUI's :dump
 * and :rows are checked against. output.data is the first --data's
 * path (adh_config's key has no scene word: a scene cannot name a curve),
 * so it is --data's. */
static void inputs(const cli_options *cli)
{
    adh_outdir_input in[CLI_MAX_DATA + 4] = {
        { cli->cfg.scene, "the scene", NULL },
        { cli->cfg.tui.replay, "the replay script", "--replay" },
        { cli->cfg.output.gnuplot_style, "the gnuplot style", "--gnuplot-style" },
        { cli->cfg.output.data, "a measured curve", "--data" },
    };
    for (size_t i = 0; i < cli->ndata; i++)
        in[4 + i] = (adh_outdir_input){ cli->data[i], "a measured curve", "--data" };
    adh_outdir_inputs(in, 4 + cli->ndata);
}

/* --screen: not a file the session reads, and somewhere it can be
 * written, said before the replay runs. 0, or 2 with why. */
static int screen_check(const cli_options *cli, char *why, size_t whylen)
{
    const char *what, *option;
    if (!cli->cfg.tui.screen[0])
        return 0;
    if (adh_outdir_input_named(cli->cfg.tui.screen, &what, &option)) {   /* it was put over the replay script */
        snprintf(why, whylen, "--screen=%s is %s%s%s%s this run reads: the screen would replace it; name another "
                 "file", cli->cfg.tui.screen, what, option ? " (" : "", option ? option : "", option ? ")" : "");
        return 2;
    }
    /* where it cannot go, said before the replay runs (it was said after) */
    int e = adh_outfile_check(cli->cfg.tui.screen);
    if (e) {
        char reason[512];
        snprintf(why, whylen, "--screen=%s: cannot write the screen there: %s", cli->cfg.tui.screen,
                 e == EISDIR ? "it is a directory" : adh_outfile_reason(cli->cfg.tui.screen, e, reason, sizeof reason));
        return 2;
    }
    return 0;
}

static int parse(int argc, char **argv, cli_options *cli, char *why, size_t whylen)
{
    static flags_seen fs;
    memset(cli, 0, sizeof *cli);
    adh_config_default(&cli->cfg);
    /* adhere fit and adhere merge: subcommands, the rest of the line their
     * options (and merge's directories) */
    int fit = argc > 1 && strcmp(argv[1], "fit") == 0;
    int merge = argc > 1 && strcmp(argv[1], "merge") == 0;
    if (fit || merge) {
        argc--;
        argv++;
    }
    /* getopt permutes argv: keep the order as typed for the hints */
    char *orig[256];
    int norig = argc < 256 ? argc : 256;
    memcpy(orig, argv, (size_t)norig * sizeof *orig);
    if (collect(argc, argv, &fs, why, whylen) != 0)
        return 2;
    if (merge)
        return merge_line(cli, argc, argv, &fs, why, whylen);
    if (combinations(argc, argv, &fs, why, whylen) != 0)
        return 2;
    /* Two passes: the scene (positional) sets values first, then the flags
     * override them whatever their order on the line. */
    if (optind == argc - 1) {
        cli->scene_arg = argv[optind];
        char path[PATH_MAX];
        if (adh_scene_read(cli->scene_arg, path, sizeof path, &cli->scene_text, why, whylen) != 0) {
            split_unit_hint(norig, orig, cli->scene_arg, why, whylen);
            return 2;
        }
        if (adh_scene_parse_string(cli->scene_text, path, &cli->cfg, why, whylen) != 0)
            return 2;
        snprintf(cli->cfg.scene, sizeof cli->cfg.scene, "%s", path);
    }
    for (size_t i = 0; i < fs.n; i++)
        if (apply(cli, fs.list[i].o, fs.list[i].arg, why, whylen) != 0)
            return 2;
    if (fit)
        return fit_check(cli, fs.batch || fs.plan || fs.cost || fs.replay || fs.info, why, whylen);
    if (cli->fit.given) {
        snprintf(why, whylen, "--free, --model, --offset and --baseline are adhere fit's: write 'adhere fit --data=FILE ...'");
        return 2;
    }
    if (cli->allow_partial) {
        snprintf(why, whylen, "--allow-partial is adhere merge's: adhere merge --allow-partial -o DIR SHARD_DIR...");
        return 2;
    }
    if (cli->columns[0] && !cli->ndata) {   /* it was dropped in silence */
        snprintf(why, whylen, "--columns=%s picks the columns of a measured curve: give --data=FILE too, or leave "
                 "--columns out", cli->columns);
        return 2;
    }
    if (cli->shard_n && !cli->cfg.sweep.naxes) {
        snprintf(why, whylen, "--shard=%u/%u splits a sweep: give a scene with a [sweep] section, or --sweep=KEY=VALUES",
                 cli->shard_k, cli->shard_n);
        return 2;
    }
    if (cli->shard_n && !cli->cfg.output.dir[0] && cli->action == CLI_ACT_BATCH) {
        snprintf(why, whylen, "--shard=%u/%u writes its runs into a directory for adhere merge: give -o DIR (one for each shard)",
                 cli->shard_k, cli->shard_n);
        return 2;
    }
    adh_mode mode = cli->cfg.spec.mode;
    if (fs.reference && mode != ADH_MODE_RELAX) {
        snprintf(why, whylen, "--reference=static is for --mode=relax: %s", mode == ADH_MODE_STATIC
                 ? "in static mode the run is the static curve itself" : mode == ADH_MODE_TIME
                 ? "in physical time the run is integrated in seconds (an elastic sphere's path is its static curve "
                   "itself); --mode=static computes the static curve alone"
                 : "rigid spheres have no elastic curve to compare");
        return 2;
    }
    if (fs.reference && cli->action != CLI_ACT_BATCH && cli->action != CLI_ACT_PLAN) {
        snprintf(why, whylen, "--reference=static is drawn by --batch runs only");
        return 2;
    }
    return 0;
}

int cli_options_parse(int argc, char **argv, cli_options *cli, char *why, size_t whylen)
{
    int rc = parse(argc, argv, cli, why, whylen);
    if (rc != 0)
        return rc;
    inputs(cli);
    return screen_check(cli, why, whylen);
}

static int validate_run(const adh_config *cfg, const adh_run_spec *run, cli_advice_for who, char *why, size_t whylen);

/* A sweep's figure fits its keys: a map needs two, Figure 3's jump a
 * material swept (sigma, E, A, z0 or R), the column shown is sweep.tsv's. */
static int sweep_plot_fits(const adh_config *cfg, char *why, size_t whylen)
{
    const adh_sweep *s = &cfg->sweep;
    adh_sweep_plot plot = adh_sweep_plot_kind(s);
    if (plot == ADH_SWEEP_PLOT_MAP && s->naxes < 2) {
        snprintf(why, whylen, "[sweep] plot = map draws two swept keys against each other: this sweep has %zu; use "
                 "plot = curves", s->naxes);
        return 2;
    }
    if (plot == ADH_SWEEP_PLOT_JUMP && !adh_sweep_touches(s, "material.") && !adh_sweep_axis_of(s, "sigma")) {
        snprintf(why, whylen, "[sweep] plot = jump draws the jump against sigma: sweep sigma (or E, A, z0, R)");
        return 2;
    }
    if (s->map[0] && cli_studyrow_column(s->map) < 0) {
        snprintf(why, whylen, "[sweep] map = %s: no number column of that name in sweep.tsv (pulloff_F, max_load, "
                 "jump_in_h0, jump_out_h0, h_before, iterations, ...)", s->map);
        return 2;
    }
    char msg[1024];
    if (adh_config_time_sweep_check(cfg, msg, sizeof msg) != 0) {
        cli_options_words(cfg, msg, why, whylen);
        return 2;
    }
    if (s->run_dirs == 0 && plot == ADH_SWEEP_PLOT_FORCE) {
        snprintf(why, whylen, "[sweep] plot = force draws every run's force curve from its run-K/force.tsv: "
                 "run_dirs = no leaves them out (use run_dirs = yes or auto)");
        return 2;
    }
    return 0;
}

static int validate(const adh_config *cfg, cli_advice_for who, int study, char *why, size_t whylen);

/* Every run is checked (a sweep's each set their own keys), with the
 * protocol it steps. */
int cli_options_validate(const adh_config *cfg, char *why, size_t whylen)
{
    return validate(cfg, CLI_ADVICE_RUN, 1, why, whylen);
}

int cli_options_validate_screen(const adh_config *cfg, char *why, size_t whylen)
{
    return validate(cfg, CLI_ADVICE_RUN, 0, why, whylen);
}

int cli_options_validate_for(const adh_config *cfg, cli_advice_for who, char *why, size_t whylen)
{
    return validate(cfg, who, 1, why, whylen);
}

/* Every run checked; with study, that they share one mode as well (a
 * study's table and grid are one). Without (the screen, which runs one
 * run), a run in another mode than the first's is not checked: on the
 * first run's grid it is no run anyone steps, and --batch refuses it. */
static int validate(const adh_config *cfg, cli_advice_for who, int study, char *why, size_t whylen)
{
    adh_run_spec run;
    if (!cfg->sweep.naxes) {
        /* a study's figure or run-K directories with no key swept: they
         * were dropped in silence, the scene run once */
        static const char *const study_only[] = { "sweep.plot", "sweep.map", "sweep.run_dirs" };
        for (size_t i = 0; i < sizeof study_only / sizeof study_only[0]; i++)
            if (adh_config_origin(cfg, study_only[i]) != -2) {
                char msg[512], flag[32], value[128] = "";   /* a flag's name as typed: --sweep=plot, --run-dirs */
                snprintf(flag, sizeof flag, i == 2 ? "--run-dirs" : "--sweep=%s", study_only[i] + 6);
                const char *name = adh_config_origin(cfg, study_only[i]) == 0 ? flag : study_only[i];
                adh_config_get(cfg, study_only[i], value, sizeof value);
                if (i == 2 && name == flag)   /* the flag: what it sets, and where a sweep comes from */
                    snprintf(msg, sizeof msg, "%s=%s sets a study's run-K directories: give a scene with a [sweep] "
                             "section, or --sweep=KEY=VALUES, or leave %s out", name, value, name);
                else
                    snprintf(msg, sizeof msg, "%s%s%s is a study's, and no key is swept: sweep one (a key of the run "
                             "under [sweep], or --sweep=KEY=VALUES), or leave %s out", name, name == flag ? "=" : " = ",
                             value, name);
                cli_options_words(cfg, msg, why, whylen);
                return 2;
            }
        adh_config_sweep_run(cfg, 0, &run);
        return validate_run(cfg, &run, who, why, whylen);
    }
    if (sweep_plot_fits(cfg, why, whylen) != 0)
        return 2;
    size_t n = adh_config_nruns(cfg);
    adh_mode first = ADH_MODE_RELAX;
    for (size_t i = 0; i < n; i++) {
        char msg[1024], which[256];
        adh_config_sweep_run(cfg, i, &run);
        if (i == 0)
            first = run.mode;
        if (adh_config_sweep_mode_check(cfg, i, &run, first, msg, sizeof msg) != 0) {
            if (!study)
                continue;   /* the screen's run is in the first's mode: the others are --batch's to refuse */
            cli_options_words(cfg, msg, why, whylen);
            return 2;
        }
        if (validate_run(cfg, &run, who, msg, sizeof msg) == 0)
            continue;
        adh_sweep_describe(&cfg->sweep, i, which, sizeof which);
        snprintf(why, whylen, "sweep run %zu (%s): %s", i + 1, which, msg);
        return 2;
    }
    return 0;
}

/* An input file named on the line is read later (after the run, for a
 * style): find a missing one now, before any work. */
static int readable_file(const char *opt, const char *path, char *why, size_t whylen)
{
    struct stat st;
    if (stat(path, &st) != 0 || access(path, R_OK) != 0) {
        snprintf(why, whylen, "--%s=%.3000s: %s", opt, path, strerror(errno));
        return 2;
    }
    if (!S_ISREG(st.st_mode)) {
        snprintf(why, whylen, "--%s=%.3000s: not a regular file", opt, path);
        return 2;
    }
    return 0;
}

/* The grid of run: its settings make a grid, it holds the run (the core's
 * check) and resolves the contact (unless --force). */
static int validate_grid(const adh_config *cfg, const adh_run_spec *run, cli_advice_for who, char *why, size_t whylen)
{
    const adh_grid_spec *u = &run->grid.use;
    char msg[1024];
    if (adh_config_grid_check(run, msg, sizeof msg) != 0) {
        cli_options_core_words(cfg, run, who, msg, why, whylen);
        return 2;
    }
    /* a uniform grid is checked from its description; a graded one is built */
    double dr = adh_config_spacing(run);
    adh_grid uniform = adh_drive_uniform_grid(u->nodes, dr);
    adh_grid *g = u->graded ? adh_config_grid_alloc(run) : &uniform;
    if (!g) {
        snprintf(why, whylen, "out of memory for a grid of %zu nodes", u->nodes);
        return 2;
    }
    unsigned fix;
    int rc = adh_drive_check(&run->mat, &run->relax, &run->proto, adh_config_grid_use(run), g, msg, sizeof msg, &fix);
    if (g != &uniform)
        adh_grid_free(g);
    if (rc != ADH_SUCCESS) {
        cli_options_core_words(cfg, run, who, msg, why, whylen);
        cli_advice_append_cfg(cfg, who, why, whylen, fix);
        return 2;
    }
    adh_grid_report gr;
    adh_grid_check(&run->mat, adh_config_grid_use(run), u->nodes, dr, &gr);
    if (!gr.resolved && !run->grid.force) {
        /* the spacing in the words the grid was given in (N's or the
         * spacing's: a scene's, or a flag's) */
        char spacing[PATH_MAX + 64];
        cli_advice_key(cfg, ADH_FIX_NODES | ADH_FIX_SPACING, ADH_FIX_SPACING, adh_qtext_arg(gr.max_spacing, ADH_Q_LENGTH).s,
                       spacing, sizeof spacing);
        adh_grid_unresolved_sentence(&gr, why, whylen);
        adh_text_cat(why, whylen, "; use ");
        adh_text_cat(why, whylen, spacing);
        adh_text_cat(why, whylen, " or more nodes over the same radius, or --force to run it anyway (marked resolved 0)");
        return 2;
    }
    return 0;
}

/* Rigid spheres: eq 22 alone, no grid is built. */
static int rigid_check(const adh_config *cfg, const adh_run_spec *run, cli_advice_for who, char *why, size_t whylen)
{
    unsigned fix;
    char msg[1024];
    if (adh_drive_check(&run->mat, &run->relax, &run->proto, ADH_GRID_RELAX, NULL, msg, sizeof msg, &fix) == ADH_SUCCESS)
        return 0;
    cli_options_core_words(cfg, run, who, msg, why, whylen);
    cli_advice_append_cfg(cfg, who, why, whylen, fix);
    return 2;
}

static int validate_run(const adh_config *cfg, const adh_run_spec *run, cli_advice_for who, char *why, size_t whylen)
{
    /* the material first (adh_drive_check meets it again): a graded grid is
     * built from it below */
    char msg[1024];
    if (adh_material_validate(&run->mat, msg, sizeof msg) != ADH_SUCCESS ||
        adh_relax_settings_validate(&run->relax, msg, sizeof msg) != ADH_SUCCESS ||
        adh_config_time_check(cfg, run, msg, sizeof msg) != 0) {   /* the material, drive and mode fit */
        cli_options_core_words(cfg, run, who, msg, why, whylen);
        return 2;
    }
    const adh_output_options *o = &cfg->output;
    if (o->gnuplot_style[0]) {
        /* a directory holds style.gp (adh_plot_style_file reads it there) */
        char style[PATH_MAX + 16];
        struct stat st;
        int dir = stat(o->gnuplot_style, &st) == 0 && S_ISDIR(st.st_mode);
        snprintf(style, sizeof style, "%s%s", o->gnuplot_style, dir ? "/style.gp" : "");
        if (readable_file("gnuplot-style", style, why, whylen))
            return 2;
    }
    if (run->mode == ADH_MODE_RIGID)   /* eq 22 alone: no grid is built */
        return rigid_check(cfg, run, who, why, whylen);
    if (!(isfinite(o->drive_speed) && o->drive_speed > 0 && o->drive_speed < 1e3)) {
        snprintf(why, whylen, "drive speed %s is not allowed: it must be above 0 and below 1000 m/s", adh_qtext(o->drive_speed, ADH_Q_SPEED).s);
        return 2;
    }
    return validate_grid(cfg, run, who, why, whylen);
}
