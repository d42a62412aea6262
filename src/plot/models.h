/* The model curves drawn beside a run (JKR, Maugis-Dugdale and DMT on the
 * drive position, eq 22 for rigid spheres) and their table, models.tsv,
 * written beside force.tsv so a figure can be drawn again from tables
 * alone. force.png draws exactly these curves. */
#ifndef ADH_PLOT_MODELS_H
#define ADH_PLOT_MODELS_H

#include <stddef.h>

#include "adhere/models.h"
#include "adhere/run.h"
#include "plot/outdir.h"
#include "plot/setup.h"

enum { ADH_PLOT_MD, ADH_PLOT_JKR, ADH_PLOT_DMT, ADH_PLOT_NMODELS };

typedef struct adh_plot_models {
    adh_model_curve curve[ADH_PLOT_NMODELS];   /* n = 0: that model is not drawn */
    double lambda;                             /* Maugis-Dugdale's */
} adh_plot_models;

/* The name models.tsv gives model k ("maugis_dugdale", "jkr", "dmt"). */
const char *adh_plot_model_name(int k);

/* The deepest drive position force.png frames: the lowest h0 of the run,
 * the reference run (may be NULL) and the measured points, less 2 % of
 * their span; the model curves start there. NAN for no rows. */
double adh_plot_models_start(const adh_plot_setup *s, const adh_run *run, const adh_run *ref);

/* Whether row o is one of eq 22's points: on path 0 on the way in (a
 * static curve turns back at its folds: eq 22 is a function of h0, drawn
 * once), the rigid surfaces apart (h0 > 0). *last carries the lowest h0 of
 * path 0 so far: start it at INFINITY. */
int adh_plot_rigid_point(const adh_obs *o, double *last);

/* The three model curves from h0_min (none for rigid spheres, where E
 * means nothing). */
void adh_plot_models_make(const adh_plot_setup *s, double h0_min, adh_plot_models *m);

/* Writes out/models.tsv: each model's curve, part by part (load: what a
 * load-controlled contact follows down to its pull-off; displacement: the
 * rest, which only a displacement-controlled drive reaches), and eq 22 at
 * the run's approach positions before contact. 0, or -1 with msg. */
int adh_tsv_models(const adh_plot_setup *s, const adh_run *run, const adh_run *ref, adh_outdir *out, char *msg,
                   size_t msglen);

#endif
