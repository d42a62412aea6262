/* Everything a run needs, from defaults, a scene file and command-line flags
 * (in that order of precedence, lowest first). The CLI, the TUI and the
 * plotter all read this one struct. */
#ifndef ADH_SCENE_CONFIG_H
#define ADH_SCENE_CONFIG_H

#include <limits.h>
#include <stddef.h>

#include "adhere/kernel.h"
#include "adhere/params.h"
#include "adhere/protocol.h"
#include "adhere/relax.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

typedef enum adh_mode { ADH_MODE_RELAX = 0, ADH_MODE_STATIC = 1 } adh_mode;

enum adh_plot_kind {
    ADH_PLOT_FORCE = 1u << 0,
    ADH_PLOT_PROFILE = 1u << 1,
    ADH_PLOT_CONTACT = 1u << 2,
    ADH_PLOT_ALL = 7u
};

typedef struct adh_config {
    adh_material mat;
    size_t nodes;                  /* N */
    double spacing;                /* m; NAN = adh_grid_default_rmax / nodes */
    adh_kernel_type kernel;
    adh_relax_settings relax;
    adh_protocol_settings proto;
    adh_mode mode;

    /* outputs */
    char out_dir[PATH_MAX];        /* "" = force table to standard output */
    int quiet;
    int plot;                      /* 0 with --no-plot */
    unsigned plots;                /* mask of adh_plot_kind */
    double drive_speed;            /* m/s, for contact-line speeds */
    char gnuplot_style[PATH_MAX];  /* "" = installed style */

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

/* The grid spacing in use: the explicit one, or the paper's grid radius
 * (scaled with sqrt(R z0)) divided by N. */
double adh_config_spacing(const adh_config *c);

#endif
