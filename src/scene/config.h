/* Everything a run needs, from defaults, a scene file and command-line flags
 * (in that order of precedence, lowest first). The CLI and the TUI read
 * this one struct; the plotter is handed only what it draws. */
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
#include "scene/figures.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

/* RIGID: eq 22 at the drive positions, no kernel and no elastic solve. */
typedef enum adh_mode { ADH_MODE_RELAX = 0, ADH_MODE_STATIC = 1, ADH_MODE_RIGID = 2 } adh_mode;

/* A sweep: one parameter takes a list of values, each an independent run
 * (Figure 3's sigma, Figure 7's eps). Every other value is the scene's. */
typedef enum adh_sweep_kind {
    ADH_SWEEP_NONE = 0,
    ADH_SWEEP_E,       /* combined modulus, Pa */
    ADH_SWEEP_SIGMA,   /* sets E = gamma sqrt(R/z0^3) / sigma (eq 17) */
    ADH_SWEEP_EPS      /* convergence parameter, m */
} adh_sweep_kind;

/* Combined figures of a sweep, drawn from every run at once. */
typedef enum adh_sweep_plot {
    ADH_SWEEP_PLOT_NONE = 0,
    ADH_SWEEP_PLOT_JUMP,   /* Figure 3: jump separation vs sigma against eq 24 (jump.png) */
    ADH_SWEEP_PLOT_FORCE   /* Figure 7: every run's force curve and the JKR curve (force.png) */
} adh_sweep_plot;

#define ADH_MAX_SWEEP 32

typedef struct adh_sweep {
    adh_sweep_kind kind;
    size_t n;
    double values[ADH_MAX_SWEEP];
    int jobs;                      /* runs at once; 0 = one per core */
    adh_sweep_plot plot;
} adh_sweep;

/* The grid settings as they were asked for, before adh_config_grid chose
 * (what a new choice starts from when the material changes). */
typedef struct adh_grid_asked {
    size_t nodes;
    double spacing, fine_band, growth, grid_radius;
    adh_kernel_type kernel;
    adh_kernel_storage storage;
    int graded;
} adh_grid_asked;

typedef struct adh_config {
    adh_material mat;
    size_t nodes;                  /* N */
    int nodes_given;               /* N set by a scene or -N (else adh_config_grid may choose) */
    int force;                     /* --force: run a grid coarser than the resolved limit */
    double spacing;                /* m; NAN = adh_grid_default_rmax / nodes */
    adh_kernel_type kernel;
    int kernel_given;              /* kernel set by a scene or --kernel (the automatic grid keeps it) */
    adh_kernel_storage storage;    /* dense (default), hmat or h2 */
    int storage_given;             /* --operator given (the automatic grid keeps it) */
    /* Graded grid (adhere/rings.h): fine rings of the spacing above over
     * [0, fine_band], then widths growing by `growth` out to grid_radius. */
    int graded;
    double fine_band;              /* m; NAN = 1.25 x the contact expected at the deepest turn */
    double growth;                 /* ratio, 1 to 1.1 (default 1.05) */
    double grid_radius;            /* m; NAN = the default uniform grid's radius */
    int grid_chosen;               /* adh_config_grid chose the grid (from `asked`) */
    adh_grid_asked asked;
    adh_relax_settings relax;
    adh_protocol_settings proto;
    adh_mode mode;
    adh_sweep sweep;               /* kind ADH_SWEEP_NONE: a single run */

    /* outputs */
    char out_dir[PATH_MAX];        /* "" = force table to standard output */
    int overwrite;                 /* --overwrite: files under adhere's names it did not write go */
    int quiet;
    int allow_unconverged;         /* --allow-unconverged: steps at the cap exit 0 */
    int plot;                      /* 0 with --no-plot */
    unsigned plots;                /* mask of adh_plot_kind */
    double drive_speed;            /* m/s, for contact-line speeds */
    char gnuplot_style[PATH_MAX];  /* "" = installed style */
    char data[PATH_MAX];           /* --data: a measured curve to overlay, "" = none */
    const struct adh_measured *measured;   /* it, read before any run (NULL = none) */

    /* TUI */
    char replay[PATH_MAX];         /* "" = interactive terminal */
    char screen[PATH_MAX];         /* final screen dump, "" = none */
    int cols, rows;                /* replay screen size */
    int no_clock;                  /* mask timings so replays are deterministic */

    char scene[PATH_MAX];          /* scene file in use, "" = built-in default */
    char title[256];
} adh_config;

/* The built-in default scene: Figure 4's material (E = 0.3 GPa), the paper's
 * grid scaled with sqrt(R z0), eps = 1 pm, d = 0.05 nm, turn at -5 nm. */
void adh_config_default(adh_config *c);

/* The grid the config asks for, uniform or graded (NULL if it cannot be
 * built: adh_config_grid_check says why), and its kernel in the asked
 * storage. */
adh_grid *adh_config_grid_alloc(const adh_config *c);
/* The kernel the configuration asks for on g, polling its cancel flag
 * (relax.cancel); NULL with *status ADH_EINTR, ADH_EINVAL or ADH_ENOMEM. */
adh_kernel *adh_config_kernel_alloc(const adh_config *c, const adh_grid *g, int *status);
/* The graded grid's spec as the config resolves it (automatic values filled). */
adh_rings_spec adh_config_rings(const adh_config *c);
/* 0, or -1 with a sentence naming the value when the grid settings cannot
 * make a grid (a graded grid with the paper's kernel, a bad ratio...). */
int adh_config_grid_check(const adh_config *c, char *why, size_t whylen);

/* The grid's settings from text, one function each for --grid, --fine-band,
 * --growth, --grid-radius and --operator and the scene keys that mirror
 * them: 0, or -1 with why naming the value and what is allowed (the caller
 * prefixes the flag or key). The fine band and the grid radius must be
 * lengths above 0 here; how they fit the spacing and each other is
 * adh_config_grid_check's. An operator set here is kept by the automatic
 * grid (storage_given). */
int adh_config_set_grid(adh_config *c, const char *text, char *why, size_t whylen);
int adh_config_set_fine_band(adh_config *c, const char *text, char *why, size_t whylen);
int adh_config_set_growth(adh_config *c, const char *text, char *why, size_t whylen);
int adh_config_set_grid_radius(adh_config *c, const char *text, char *why, size_t whylen);
int adh_config_set_operator(adh_config *c, const char *text, char *why, size_t whylen);
/* Whether the kernel can be used on the grid: the paper's assumes equal
 * cells, so not on a graded one. */
int adh_config_kernel_fits(adh_kernel_type kernel, int graded);

/* Name of a sweep parameter as scenes and tables spell it ("E", "sigma",
 * "eps"), "" for none. */
const char *adh_sweep_name(adh_sweep_kind kind);

/* The configuration of run i of cfg's sweep: cfg with the swept value set
 * and the sweep removed. A config without a sweep is its own run 0. */
void adh_config_sweep_run(const adh_config *cfg, size_t i, adh_config *run);

/* Number of runs: the sweep's length, or 1. */
size_t adh_config_nruns(const adh_config *cfg);

/* The resolution limit that applies: the static curve's in mode = static. */
adh_grid_use adh_config_grid_use(const adh_config *c);

/* When neither N nor the spacing was given: the grid adh_rings_choose picks
 * for the run with the narrowest edge zone (a sweep shares one kernel).
 * 0, or -1 with why (and in *fix, may be NULL, the ADH_FIX_* bits of what
 * to change, for the driver's words) when that grid is beyond the budget. */
int adh_config_grid(adh_config *cfg, char *why, size_t whylen, unsigned *fix);
/* The choice again, from the settings asked for, for the material and
 * protocol cfg holds now (the TUI, after an edit of E, A, z0, R or the
 * turns). Nothing happens for a grid that was given. 0, or -1 with why
 * (cfg then keeps the grid asked for). */
int adh_config_grid_again(adh_config *cfg, char *why, size_t whylen);

/* The grid spacing in use: the explicit one, or the paper's grid radius
 * (scaled with sqrt(R z0)) divided by N. */
double adh_config_spacing(const adh_config *c);

#endif
