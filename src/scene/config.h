/* One configuration per session, from defaults, a scene file, the flags and
 * (in the TUI) edits, in that order, each value set by its key through
 * adh_config_set. Three parts: the run specification (what the core is
 * asked to compute: material, solver, protocol, one grid with what was
 * asked and what was chosen), the output options (what the drivers write,
 * where) and the TUI's options; a sweep varies the run specification.
 * Passed by pointer; the plotter is handed only what it draws. */
#ifndef ADH_SCENE_CONFIG_H
#define ADH_SCENE_CONFIG_H

#include <limits.h>
#include <stddef.h>

#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/params.h"
#include "adhere/protocol.h"
#include "adhere/relax.h"
#include "adhere/rings.h"
#include "adhere/static.h"
#include "adhere/units.h"
#include "scene/figures.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

/* RIGID: eq 22 at the drive positions, no kernel and no elastic solve.
 * TIME: physical time (adhere/visco.h), a standard linear solid or an
 * elastic sphere driven at a speed through the instrument's spring. */
typedef enum adh_mode { ADH_MODE_RELAX = 0, ADH_MODE_STATIC = 1, ADH_MODE_RIGID = 2, ADH_MODE_TIME = 3 } adh_mode;

/* Combined figures of a sweep, drawn from every run at once. */
typedef enum adh_sweep_plot {
    ADH_SWEEP_PLOT_AUTO = -1,  /* a map of a study of two or more parameters, none for one */
    ADH_SWEEP_PLOT_NONE = 0,
    ADH_SWEEP_PLOT_JUMP,       /* Figure 3: jump separation vs sigma against eq 24 (jump.png) */
    ADH_SWEEP_PLOT_FORCE,      /* Figure 7: every run's force curve and the JKR curve (force.png) */
    ADH_SWEEP_PLOT_MAP,        /* a heat map of one column over the first two parameters (map.png) */
    ADH_SWEEP_PLOT_CURVES,     /* one column against the last parameter, a curve per value of the others (curves.png) */
    ADH_SWEEP_PLOT_SPEED,      /* physical time: pull-off and hysteresis against the swept speed,
                                  the static pull-offs at E0 and Einf as lines (speed.png) */
    ADH_SWEEP_PLOT_SNAP        /* the spring: snap-in against k (snap.png) */
} adh_sweep_plot;

/* A study: each swept key takes a list of values or a range, and the runs
 * are their Cartesian product (the first key varies slowest), each an
 * independent run of the configuration with those keys set. Every key of
 * the run (ADH_KEY_RUN) can be swept, and sigma, which sets E by eq 17
 * from the run's A, z0 and R (set after the others). */
#define ADH_SWEEP_MAX_AXES 6
#define ADH_SWEEP_MAX_LIST 64        /* values listed one by one; a range has up to ADH_SWEEP_MAX_RUNS */
#define ADH_SWEEP_MAX_RUNS 100000
#define ADH_SWEEP_VALUE_LEN 32

typedef enum adh_sweep_spacing { ADH_SWEEP_LIST = 0, ADH_SWEEP_LIN, ADH_SWEEP_LOG } adh_sweep_spacing;

typedef struct adh_sweep_axis {
    char name[32];                 /* the key's name in [sweep]: "E", "turns", "sigma" */
    char key[48];                  /* the configuration's key: "material.E"; "sigma" for sigma */
    int quantity;                  /* adh_quantity of its values (ADH_Q_NONE: numbers or words) */
    int count;                     /* whole numbers (a range's values are rounded) */
    adh_sweep_spacing spacing;
    size_t n;
    double lo, hi;                 /* a range's ends */
    char text[ADH_SWEEP_MAX_LIST][ADH_SWEEP_VALUE_LEN];   /* a list's values as written */
    double num[ADH_SWEEP_MAX_LIST];                      /* and as numbers (NAN: a word) */
} adh_sweep_axis;

typedef struct adh_sweep {
    size_t naxes;                  /* 0: a single run */
    adh_sweep_axis axis[ADH_SWEEP_MAX_AXES];
    int jobs;                      /* runs at once; 0 = one per core */
    adh_sweep_plot plot;
    int run_dirs;                  /* run-K directories: 1 yes, 0 no, -1 auto (up to 32 runs, or plot = force) */
    char map[32];                  /* the sweep.tsv column a map or curves show ("" = pulloff_F) */
} adh_sweep;

/* A radial grid and the kernel on it. Graded (adhere/rings.h): fine rings
 * of the spacing over [0, fine_band], then widths growing by `growth` out
 * to `radius`. */
typedef struct adh_grid_spec {
    size_t nodes;                  /* N */
    double spacing;                /* m; NAN = the paper's grid radius (scaled with sqrt(R z0)) / N */
    int graded;
    double fine_band;              /* m; NAN = 1.25 x the contact expected at the deepest turn */
    double growth;                 /* ratio, 1 to 1.1 (default 1.05) */
    double radius;                 /* m; NAN = the default uniform grid's radius */
    adh_kernel_type kernel;
    adh_kernel_storage storage;    /* dense (default), hmat or h2 */
} adh_grid_spec;

/* The grid of a run: what was asked for, and what a run builds. While
 * neither N nor the spacing was given, adh_config_grid chooses `use` for
 * the material and protocol from `asked`; else `use` is `asked`. */
typedef struct adh_grid_settings {
    adh_grid_spec asked;           /* as the defaults, a scene, the flags and edits left it */
    adh_grid_spec use;             /* what a run builds (adh_config_grid) */
    int chosen;                    /* use was chosen, not given */
    int chosen_h2;                 /* ... as graded rings held as H^2 (adh_rings_choose) */
    int nodes_given;               /* N set (by a scene, a flag or an edit) */
    int kernel_given;              /* the kernel set: a choice keeps it */
    int storage_given;             /* the operator set: a choice keeps it */
    int force;                     /* run a grid coarser than the resolved limit (marked resolved 0) */
} adh_grid_settings;

/* Physical time (mode time) and the instrument: the material beyond
 * adh_material (whose E is the relaxed modulus E0) and the drive. */
typedef struct adh_time_settings {
    int sls;                       /* material = sls: a standard linear solid (else elastic) */
    double Einf;                   /* instantaneous modulus, Pa; NAN = 10 E0 */
    double tau;                    /* relaxation time, s */
    double speed_in, speed_out;    /* the base's speed approaching and retracting, m/s */
    double dwell;                  /* held at each turn, s */
    double spring;                 /* instrument stiffness k, N/m; INFINITY = none */
    double tol;                    /* the time integration's relative tolerance (a solid's: an
                                      elastic path integrates nothing) */
    unsigned given;                /* ADH_TIME_* bits: keys set, which a mode that
                                      cannot use them refuses */
} adh_time_settings;

enum { ADH_TIME_E0 = 1, ADH_TIME_EINF = 2, ADH_TIME_TAU = 4, ADH_TIME_SPEED = 8, ADH_TIME_DWELL = 16,
       ADH_TIME_SPRING = 32, ADH_TIME_MODE = 64 /* scene.mode was set: material = sls does not choose it */,
       ADH_TIME_TOL = 128 };

/* What the core is asked to compute: one run. */
typedef struct adh_run_spec {
    adh_material mat;
    adh_relax_settings relax;      /* the relaxation solver */
    adh_protocol_settings proto;   /* start, step, turns, unload, dwell, profiles */
    adh_mode mode;
    adh_grid_settings grid;
    adh_time_settings time;        /* mode time's material and drive; the spring also static's */
    size_t max_points;             /* the static curve's cap on points; 0: the solver's own */
} adh_run_spec;

/* What the drivers write, and where. */
typedef struct adh_output_options {
    char dir[PATH_MAX];            /* "" = force table to standard output */
    int overwrite;                 /* files under adhere's names it did not write go */
    int quiet;
    int allow_unconverged;         /* steps at the cap exit 0 */
    int plot;                      /* 0: the tables only, no PNG */
    unsigned plots;                /* mask of adh_plot_kind */
    double drive_speed;            /* m/s, for contact-line speeds */
    char gnuplot_style[PATH_MAX];  /* "" = installed style */
    char data[PATH_MAX];           /* a measured curve to overlay, "" = none */
    const struct adh_measured *measured;   /* it, read before any run (NULL = none) */
    char title[256];               /* the scene's */
} adh_output_options;

/* The TUI's own. */
typedef struct adh_tui_options {
    char replay[PATH_MAX];         /* "" = interactive terminal */
    char screen[PATH_MAX];         /* final screen dump, "" = none */
    int cols, rows;                /* replay screen size */
    int no_clock;                  /* mask timings so replays are deterministic */
} adh_tui_options;

/* A quantity given as a bare number, which flags and scenes read in SI:
 * kept so that a refusal of the run can ask whether a unit the screen
 * shows was meant (adh_config_unit_hint). */
#define ADH_MAX_GIVEN 16
typedef struct adh_given {
    char key[32];                  /* "material.R" */
    char text[96];                 /* as given: "10", "-5,-2" */
    char where[160];               /* who gave it: a flag ("--radius"), or a scene file */
} adh_given;

/* Who set a key last, so that a refusal names what the user wrote: a
 * flag, or a scene's line (adh_config_origin). */
#define ADH_MAX_ORIGINS 128
typedef struct adh_origin {
    char key[40];                  /* "material.Einf", "sweep.speed" */
    int line;                      /* 0: a flag; > 0: the scene's line; -1: the scene, line unknown */
} adh_origin;

typedef struct adh_config {
    adh_run_spec spec;
    adh_sweep sweep;               /* kind ADH_SWEEP_NONE: a single run */
    adh_output_options output;
    adh_tui_options tui;
    char scene[PATH_MAX];          /* scene file in use, "" = built-in default */
    adh_given given[ADH_MAX_GIVEN];  /* the bare quantities of the flags and the scene */
    size_t ngiven;
    adh_origin origin[ADH_MAX_ORIGINS];  /* the keys flags and the scene set */
    size_t norigin;
} adh_config;

/* The built-in default scene: Figure 4's material (E = 0.3 GPa), the paper's
 * grid scaled with sqrt(R z0), eps = 1 pm, d = 0.05 nm, turn at -5 nm. */
void adh_config_default(adh_config *c);

/* ---- setting by key (configset.c) ---------------------------------------
 * Every value a scene, a flag or a TUI edit sets has a key, "section.name"
 * as a scene writes it ("material.E", "protocol.turns"); keys a scene may
 * not hold (outputs and the TUI's options given by flags) have one too
 * ("output.dir", "tui.size"). */

/* Where a key may be given besides flags and adh_config_set. */
enum { ADH_KEY_SCENE = 1,   /* a scene file (adhere-scene(5)) */
       ADH_KEY_RUN = 2,     /* part of the run specification (a TUI edit, a study); it sets
                               nothing outside adh_config's spec */
       ADH_KEY_COUNT = 4 }; /* a whole number (a swept range's values are rounded) */

typedef struct adh_config_key {
    const char *key;               /* "section.name" */
    unsigned where;                /* ADH_KEY_* bits */
    adh_quantity q;                /* a quantity's (ADH_Q_NONE: a count, word, list or text) */
    const char *units;             /* the units a screen shows it in, largest first ("GPa MPa kPa");
                                      NULL: SI itself (J), or no quantity */
} adh_config_key;

/* Sets key from text, the same for every driver: 0, or -1 with why naming
 * the value and what is allowed, without the key (the caller prefixes its
 * own word for it: the flag, the scene key, the TUI's field) and nothing
 * changed. A grid setting sets the grid asked for (adh_config_grid chooses
 * again); turns set whether to unload (unload = there are turns). */
int adh_config_set(adh_config *c, const char *key, const char *text, char *why, size_t whylen);
/* A sentence of the configuration's (adh_config_set's, adh_config_grid_check's)
 * names keys as "section.name", or "section.name = value" with a value;
 * each driver says them in its own words: say writes the driver's word for
 * the key (a flag, a scene key, a TUI field), value NULL when none was
 * named. out receives the sentence reworded. */
typedef void (*adh_config_say)(const char *key, const char *value, char *buf, size_t len, void *ctx);
void adh_config_reword(const char *in, adh_config_say say, void *ctx, char *out, size_t len);
/* A core check's sentence in run of c (the core names quantities, never a
 * flag) that opens with a setting's quantity and value ("start = 400 pm is
 * not allowed", "E (modulus) = 0 Pa is out of range", "N = 5 nodes is not
 * allowed") opened with the key and the value as typed instead
 * ("protocol.start = 400pm is not allowed"), for adh_config_reword: out
 * receives it, and the key is returned (keyed.c lists every opening).
 * NULL and in as it was when it opens otherwise, when nobody set the key
 * (its default is no setting of the user's), or when the value it names
 * is not the key's (one the core derived: a uniform grid's radius). */
const char *adh_config_key_opening(const adh_config *c, const adh_run_spec *run, const char *in, char *out,
                                   size_t len);
/* A driver's words for a sentence of the configuration's (its keys said
 * as the driver says them: adh_config_reword with its own adh_config_say). */
typedef void (*adh_config_words)(const char *in, void *ctx, char *out, size_t len);
/* adh_config_set's refusal msg of the text a driver's user gave for key,
 * in the driver's words: opened with the setting as the user gave it
 * (setting: "--nodes=5", "nodes = 5", "N = 5") where msg opens with key's
 * quantity and value ("N = 5 nodes is not allowed: ..." becomes "--nodes=5
 * is not allowed: ..."), else "name: msg" (name: "--nodes", "nodes", "N");
 * the rest through words. */
void adh_config_refusal(const char *key, const char *setting, const char *name, const char *msg,
                        adh_config_words words, void *ctx, char *out, size_t len);
/* key's value as text that adh_config_set reads back to the same value
 * (numbers in SI, exactly; "auto", "none", lists by commas). 0, or -1 for
 * no such key. */
int adh_config_get(const adh_config *c, const char *key, char *buf, size_t len);
/* The key's entry (NULL: no such key). */
const adh_config_key *adh_config_key_find(const char *key);
/* The i-th key of the table (NULL past the last), for lists and tests. */
const adh_config_key *adh_config_key_at(size_t i);
/* The unit of k's units a screen shows value in: the largest not above
 * |value| (the smallest for smaller values); *factor its size in SI. NULL
 * when k has none. ASCII ("um"). */
const char *adh_config_key_unit(const adh_config_key *k, double value, double *factor);

/* Edit distance of two names, letters compared without case ("Turn" and
 * "turns": 1), two neighbours swapped one edit ("trun" and "turn": 1): for
 * "did you mean". */
size_t adh_config_name_distance(const char *a, const char *b);
/* The key a scene's unknown name in section most likely meant: a scene
 * key in that section within a small edit distance, else the same name in
 * another section ("E" in [protocol]: material.E). NULL when none is near. */
const adh_config_key *adh_config_key_suggest(const char *section, const char *name);

/* A flag or a scene set key from text (already through adh_config_set):
 * where says who ("--radius", a scene's file). A quantity given bare (no
 * unit anywhere, not 0) is remembered; given with a unit, forgotten. */
void adh_config_note_given(adh_config *c, const char *key, const char *text, const char *where);
/* key was set by a flag (line 0) or by the scene c->scene at line (> 0;
 * -1 when the line is not known); a later word replaces an earlier. */
void adh_config_note_origin(adh_config *c, const char *key, int line);
/* Who set key: -2 nobody (its default), 0 a flag, else the scene's line as
 * noted. A key a [sweep] sets in each run ("protocol.speed" by sweep.speed)
 * is the sweep key's, whoever set the key itself. */
int adh_config_origin(const adh_config *c, const char *key);
/* The name a sweep of key was given by ("E" for material.E, from
 * --sweep=E=... or a [sweep] line E = ...), NULL when key is not swept. */
const char *adh_config_swept_as(const adh_config *c, const char *key);
/* Of two keys that set one value (material.E and material.E0), the one
 * whose value holds: set last, a swept one after any other; a when nobody
 * set either. */
const char *adh_config_origin_last(const adh_config *c, const char *a, const char *b);

/* After c was refused (accept(c) != 0): each bare quantity tried on a copy
 * of c in each of its key's units; accept(copy, ctx) == 0 says the copy
 * would run. out receives, for the first bare quantity some unit rescues,
 * "R = 10 m is out of range; did you mean --radius=10um?" (a scene's:
 * "did you mean R = 10um in FILE?"). 1 with out written, 0 when no unit
 * rescues any (out = ""), -1 out of memory. */
int adh_config_unit_hint(const adh_config *c, int (*accept)(adh_config *copy, void *ctx), void *ctx, char *out,
                         size_t len);

/* ---- the run ------------------------------------------------------------ */

/* The protocol a run of c steps, as every driver (batch, sweeps, --cost,
 * --plan, the TUI) hands it to the drive: c's own, whole (turns, unload,
 * dwell, profiles), with profile positions spread along the path when the
 * profile figure is asked in relaxation and none was given. */
adh_protocol_settings adh_config_protocol(const adh_config *c);
/* mode's word as scene.mode and --mode take it: relax, static, rigid, time. */
const char *adh_config_mode_word(adh_mode m);
/* The same for c's run in mode (the TUI keeps one path per mode). */
adh_protocol_settings adh_config_protocol_for(const adh_config *c, adh_mode mode);
/* The positions adh_config_protocol spreads: up to max, from the deepest
 * turn (none: the jump-in gap of eq 24) to half the start, each on the
 * drive's lattice so that the run stores it. How many went into out. */
size_t adh_config_default_profiles(const adh_material *mat, const adh_protocol_settings *ps, double *out, size_t max);
/* The start a run of s begins at: s's, or the automatic one. */
double adh_config_start(const adh_run_spec *s);
/* The static curve's settings for run s, as every driver (--batch
 * --mode=static, the reference curve, the screen's m) hands them to the
 * solver: the spring's closer points (adh_rule_path_static_settings),
 * s's cancel flag and its cap on points (solver.max_points). */
adh_static_settings adh_config_static_settings(const adh_run_spec *s);

/* The grid the run s builds, uniform or graded (NULL if it cannot be
 * built: adh_config_grid_check says why), and its kernel in the storage
 * asked for, polling the relax settings' cancel flag; NULL with *status
 * ADH_EINTR, ADH_EINVAL or ADH_ENOMEM. */
adh_grid *adh_config_grid_alloc(const adh_run_spec *s);
adh_kernel *adh_config_kernel_alloc(const adh_run_spec *s, const adh_grid *g, int *status);
/* The graded grid's spec as s resolves it (automatic values filled). */
adh_rings_spec adh_config_rings(const adh_run_spec *s);
/* 0, or -1 with a sentence naming the keys when the grid settings cannot
 * make a grid (a graded grid with the paper's kernel, a bad ratio...). */
int adh_config_grid_check(const adh_run_spec *s, char *why, size_t whylen);
/* Whether the kernel can be used on the grid: the paper's assumes equal
 * cells, so not on a graded one. */
int adh_config_kernel_fits(adh_kernel_type kernel, int graded);
/* Whether runs a and b build the same grid and kernel (one can serve
 * both): rigid runs build none. */
int adh_config_same_grid(const adh_run_spec *a, const adh_run_spec *b);
/* A grid and its kernel kept for the run they were built for, between
 * calls (kernelkeep.c): the screen's start check at every edit builds one
 * only when the grid changes. Owned (freed by adh_config_kept_drop), or
 * lent by a caller that holds the same grid for itself. */
typedef struct adh_config_kept {
    adh_run_spec spec;   /* the run g and k were built for */
    adh_grid *g;
    adh_kernel *k;       /* NULL: none kept */
    int lent;            /* g and k are the lender's: never freed here */
    size_t built;        /* kernels built into it so far */
} adh_config_kept;
void adh_config_kept_init(adh_config_kept *kp);
/* Forgets g and k, freeing them unless lent. */
void adh_config_kept_drop(adh_config_kept *kp);
/* Keeps the caller's g and k, built for run s (until dropped). */
void adh_config_kept_lend(adh_config_kept *kp, const adh_run_spec *s, adh_grid *g, adh_kernel *k);
/* The grid and kernel of run s in kp: those kept when s builds the same
 * grid (adh_config_same_grid), else built now (counted in kp->built).
 * ADH_SUCCESS; ADH_ENOMEM or ADH_EINTR with none kept. */
int adh_config_kept_get(adh_config_kept *kp, const adh_run_spec *s);
/* Moves an owned grid and kernel that run s builds into *g, *k (the caller
 * frees them now): 1; else 0, nothing moved. */
int adh_config_kept_take(adh_config_kept *kp, const adh_run_spec *s, adh_grid **g, adh_kernel **k);

/* The nodes (uniform) or rings (graded) of the grid the run s builds. */
size_t adh_config_nodes(const adh_run_spec *s);
/* The grid spacing in use: the explicit one, or the paper's grid radius
 * (scaled with sqrt(R z0)) divided by N. */
double adh_config_spacing(const adh_run_spec *s);
/* The resolution limit that applies: the static curve's in mode = static. */
adh_grid_use adh_config_grid_use(const adh_run_spec *s);
/* How the grid in use (s->grid.use) resolves the contact edge under the
 * limit that applies (adh_grid_check): one question asked by every driver
 * and table. */
void adh_config_grid_report(const adh_run_spec *s, adh_grid_report *r);

/* Whether the grid follows the material: neither N nor the spacing was
 * given (and the spheres deform). */
int adh_config_grid_auto(const adh_run_spec *s);
/* The grid a run of s builds (s->grid.use): the one asked for, or, while
 * it follows the material, the one adh_rings_choose picks for the run of
 * study's sweep (NULL: s alone) with the narrowest edge zone (a sweep
 * shares one kernel), for the material, protocol and mode s holds now.
 * Either way the operator is adh_config_storage_for's for the mode unless
 * it was given. 0, or -1 with
 * why (and in *fix, may be NULL, the ADH_FIX_* bits of what to change,
 * for the driver's words) when the choice is beyond the budget (use is
 * then the grid asked for). */
int adh_config_choose_grid(adh_run_spec *s, const adh_config *study, char *why, size_t whylen, unsigned *fix);
/* The same for c's run and sweep. */
int adh_config_grid(adh_config *c, char *why, size_t whylen, unsigned *fix);

/* From this many nodes the relaxation holds a uniform grid's kernel as H^2
 * unless the operator is given: there the H^2 product is the faster (measured: 3.0
 * against 3.1 us at N = 200, 5.0 against 6.2 at 300, 20 against 68 at 1000,
 * paper kernel) and within ~3e-12 of the dense one, which moves no
 * iteration count and no printed digit (docs/performance.md). */
#define ADH_CONFIG_H2_MIN_NODES 256
/* The operator a run of s in mode takes on s's grid (after the choice of
 * the grid): the one given; else H^2 on an automatic graded grid, past
 * ADH_GRID_MAX_NODES nodes, and for the relaxation on a uniform grid from
 * ADH_CONFIG_H2_MIN_NODES nodes; else dense (a graded grid given by hand
 * keeps it as before: not measured for this choice). The static mode keeps the
 * dense kernel on the rest: its dense LU there is the oracle, and the
 * HODLR preconditioner an H^2 kernel takes moves its Newton iterations,
 * points and folds (docs/performance.md). */
adh_kernel_storage adh_config_storage_for(const adh_run_spec *s, adh_mode mode);

/* ---- physical time (timespec.c) ----------------------------------------- */

struct adh_visco_rule_settings;
struct adh_rule_type;

/* Elastic, Einf = 10 E0 when made a solid, tau = 1 ms, 1 um/s both ways,
 * no dwell, no spring. */
adh_time_settings adh_time_settings_default(void);
/* The instantaneous modulus of run s: Einf, or 10 E0 when automatic; E0
 * (the material's E) for an elastic material. */
double adh_config_einf(const adh_run_spec *s);
/* The viscoelastic step rule's settings of run s (adhere/rule_visco.h):
 * the solid (or the elastic material at E), the drive, the integrator
 * polling s's cancel flag. */
void adh_config_visco(const adh_run_spec *s, struct adh_visco_rule_settings *out);
/* The step rule of run s in physical time, with those settings: the
 * integrator (adh_rule_visco) for a standard linear solid, the static
 * curve's path (adh_rule_path: no time integration, an elastic solid is
 * rate-independent) for an elastic material. */
const struct adh_rule_type *adh_config_time_rule(const adh_run_spec *s);
/* 0, or -1 with a sentence naming the keys, when run s's material, drive
 * and mode do not fit: a solid outside mode time, a solid's key or the
 * drive's for an elastic material or a mode without physical time, the
 * spring in relaxation or for rigid spheres, an iteration dwell in
 * physical time, Einf below E0. */
int adh_config_time_check(const adh_config *c, const adh_run_spec *s, char *why, size_t whylen);
/* Before any work, once memory is bounded: whether each run of cfg that is
 * a standard linear solid in physical time from a start given can start at
 * rest out of contact there, on its own grid and kernel
 * (adh_visco_start_check); else that run would stop before its first
 * step. ADH_SUCCESS; or ADH_EINVAL (ADH_ENOMEM) with why naming the start
 * (a sweep's run named) and *fix the settings that get past it, for the
 * driver's words (timestart.c). keyed: the sentence names the start as the
 * configuration's sentences name a key ("protocol.start = 400pm is not
 * allowed", for adh_config_reword: adh_config_key_opening); else as a
 * quantity ("start = 400 pm"). */
int adh_config_start_check(const adh_config *cfg, int keyed, char *why, size_t whylen, unsigned *fix);
/* The same on the grid and kernel kept in kp (adh_config_kept), left
 * there for the next call, the start as a quantity (the screen's words):
 * an edit that leaves the grid builds none (kp is dropped when no run has
 * a start to check). */
int adh_config_start_check_kept(const adh_config *cfg, adh_config_kept *kp, char *why, size_t whylen,
                                unsigned *fix);
/* 0, or -1 with a sentence, when c's study does not fit physical time: plot
 * = speed without one speed swept in time, plot = snap without one spring
 * swept, eps swept in time. */
int adh_config_time_sweep_check(const adh_config *c, char *why, size_t whylen);

/* ---- sweeps (sweep.c) ----------------------------------------------------- */

/* Sets the swept key `name` ("E", "material.E", "sigma", "turns") from
 * text: a list "V1, V2, ..." (at most ADH_SWEEP_MAX_LIST values, each one
 * the key takes), or a range "LO .. HI, N" / "LO .. HI, lin|log, N" (N
 * values spaced evenly or by equal ratios, the ends exact; whole numbers
 * for a count); "none" drops it. A key swept again is replaced in place;
 * a new one comes last. 0, or -1 with why naming the value and what is
 * allowed (nothing changed), also when the runs would pass
 * ADH_SWEEP_MAX_RUNS. */
int adh_sweep_set(adh_config *c, const char *name, const char *text, char *why, size_t whylen);
/* The key a swept name sets, whichever its spelling ("E" and "material.E":
 * material.E), into key: 0, or -1 when name is no key of a run. A source
 * of keys (a scene's [sweep], the --sweep flags) names each key once. */
int adh_sweep_key_of(const char *name, char *key, size_t len);
/* The swept key `name`'s values as text adh_sweep_set reads back ("none"
 * when not swept). */
void adh_sweep_get(const adh_config *c, const char *name, char *buf, size_t len);
/* The axis sweeping `name` (its name or key), or NULL. */
const adh_sweep_axis *adh_sweep_axis_of(const adh_sweep *s, const char *name);
/* Value j of axis a: its number (NAN for a word) and, in text, what the
 * key is set to (a range's value exactly, %.17g). */
double adh_sweep_value(const adh_sweep_axis *a, size_t j, char *text, size_t len);
/* Number of runs: the product of the axes' lengths (1 without any). */
size_t adh_sweep_runs(const adh_sweep *s);
/* Run i's index along each axis (idx[naxes]): the first axis slowest. */
void adh_sweep_index(const adh_sweep *s, size_t i, size_t *idx);
/* "E = 1e+09, turns = -2e-09": run i's swept values (SI, %g), for messages. */
void adh_sweep_describe(const adh_sweep *s, size_t i, char *buf, size_t len);
/* Whether an axis sets a key starting with prefix ("grid.", "material."). */
int adh_sweep_touches(const adh_sweep *s, const char *prefix);
/* cb on the material of every run of s with base's specification, each
 * once: the product of the axes that set a material key or sigma. */
typedef void (*adh_sweep_material_cb)(const adh_material *m, void *ctx);
void adh_sweep_materials(const adh_sweep *s, const adh_run_spec *base, adh_sweep_material_cb cb, void *ctx);
/* The sweep's figure: plot, or for auto a map with two or more swept
 * keys and none with one (and none without a sweep). */
adh_sweep_plot adh_sweep_plot_kind(const adh_sweep *s);
/* Whether the study's figure is Figure 7 with its panel of hysteresis
 * against eps: eps alone swept, in relaxation, plot = force (the static
 * curve's loop, eps -> 0, is then its line). */
int adh_sweep_fig7_panel(const adh_config *c);
/* Whether run-K directories are written (run_dirs, or auto). */
int adh_sweep_run_dirs(const adh_sweep *s);

/* The run specification of run i of c's sweep: c's, with the swept keys
 * set as adh_config_set sets them (sigma last, as E from eq 17), the grid
 * chosen again for the run alone when a grid key or the mode is swept,
 * and the protocol every run steps (adh_config_protocol). A config
 * without a sweep is its own run 0. */
void adh_config_sweep_run(const adh_config *c, size_t i, adh_run_spec *run);
/* Run i of c's sweep (run, as adh_config_sweep_run gave it) against run
 * 1's mode first: a study's runs share one mode unless scene.mode itself
 * is swept (a material swept between elastic and sls would move runs into
 * physical time or out of it, on run 1's grid, in a table of run 1's
 * columns). 0, or -1 with why naming the run and scene.mode. */
int adh_config_sweep_mode_check(const adh_config *c, size_t i, const adh_run_spec *run, adh_mode first, char *why,
                                size_t whylen);
/* Number of runs: the sweep's, or 1. */
size_t adh_config_nruns(const adh_config *c);

/* Drives: what is stepped. Runs that differ only in their turn (a swept
 * turns key, in relaxation) share one drive, as Figure 5's turns do: one
 * loading branch to the deepest, an unloading branch from each turn (up to
 * ADH_MAX_TURNS a drive); runs that differ only in their spring (mode
 * static) share one static curve, from the softest spring's start; every
 * other run is a drive of its own. The
 * number of drives; drive u's runs (ascending, at most ADH_MAX_TURNS) and
 * their number. */
size_t adh_sweep_drives(const adh_config *c);
size_t adh_sweep_drive_runs(const adh_config *c, size_t u, size_t *runs);
/* The specification drive u steps: its runs' with every one of their
 * turns. */
void adh_sweep_drive_spec(const adh_config *c, size_t u, adh_run_spec *run);

#endif
