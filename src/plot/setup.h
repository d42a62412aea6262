/* What the plots of one run show, beside the run itself: the plot module's
 * small description of a run (never the whole configuration), and the one
 * place a configuration becomes one (batch, sweeps, the TUI). */
#ifndef ADH_PLOT_SETUP_H
#define ADH_PLOT_SETUP_H

#include <signal.h>
#include <stddef.h>

#include "adhere/grid.h"
#include "adhere/params.h"
#include "scene/config.h"
#include "scene/measured.h"

/* Strings and arrays are borrowed: they must outlive the call they are
 * passed to. */
typedef struct adh_plot_setup {
    adh_material mat;              /* headings, model curves, the tables' preamble */
    unsigned figures;              /* adh_plot_kind bits asked for: ADH_PLOT_CONTACT
                                      also asks for contact.tsv */
    int draw;                      /* 0: the tables only, no PNG (--no-plot) */
    const char *title;             /* the scene's title, "" for none */
    int rigid;                     /* rigid spheres: no JKR, DMT, MD curves (E means nothing) */
    int equilibrium;               /* path 0 is the static equilibrium curve (--mode=static) */
    double drive_speed;            /* |dh0/dt|, m/s: contact-line speeds (in physical
                                      time: the base's retraction speed, for the heading) */
    int timed;                     /* the rows are in physical time (mode time) */
    int sprung;                    /* through an instrument's spring: h0 is the sphere's
                                      position, the base drives it (h0 = base + F/k) */
    double spring;                 /* that spring's k, N/m; INFINITY: none */
    double Einf, tau;              /* a standard linear solid's (mat.E is E0); Einf NAN: elastic */
    double step;                   /* drive step d, m */
    size_t nodes;                  /* the run's grid: N nodes (each profile's length), */
    double dr;                     /* its (finest) spacing, m, */
    const double *r;               /* and its node radii; NULL: uniform, (n + 1/2) dr */
    const char *style;             /* gnuplot style file or directory, "" = the installed one */
    const adh_measured *measured;  /* --data: drawn over force.png, NULL = none */
    const volatile sig_atomic_t *cancel; /* the caller's interrupt flag: a wait for gnuplot
                                            stops once it is raised (NULL: none) */
} adh_plot_setup;

/* Node n's radius on the setup's grid. */
double adh_plot_setup_radius(const adh_plot_setup *s, size_t n);

/* Fills s from cfg's outputs, the run's specification (a sweep's run: its
 * own) and grid g (NULL for rigid spheres, which have none: the spec's N
 * and spacing then). s borrows cfg's strings and g's radii: both must
 * outlive its use. */
void adh_plot_setup_fill(const adh_config *cfg, const adh_run_spec *run, const adh_grid *g, adh_plot_setup *s);

#endif
