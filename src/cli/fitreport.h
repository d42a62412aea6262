/* What adhere fit reports: the text on standard output, fit.tsv,
 * fit-points.tsv, best.scene and fit.png. */
#ifndef ADH_CLI_FITREPORT_H
#define ADH_CLI_FITREPORT_H

#include <stdio.h>

#include "adhere/fit.h"
#include "plot/outdir.h"
#include "scene/config.h"
#include "scene/fitdata.h"

/* Poor: chi2 per degree of freedom, against the data's own scatter, above this. */
#define CLI_FIT_POOR_CHI2 4.0
/* A correlation above this in magnitude is warned of. */
#define CLI_FIT_CORR_WARN 0.99

typedef struct cli_fit_report {
    const adh_config *cfg;       /* the scene, grid and model settings used */
    const adh_fitdata *fd;
    const adh_fit_result *res;
    const adh_fit_settings *fs;
    const double *model, *resid; /* at the points, N */
    size_t ncurve;               /* the best model's curve, in model coordinates */
    const double *ch0, *cF;
    const int *cstable;
    double grid_edge_nodes;      /* nodes across the edge zone at the optimum */
    int grid_resolved;           /* at the optimum */
    int refits;                  /* fits again on a grid chosen for the optimum */
    size_t evals;                /* over every fit */
    double seconds;
    int partial;                 /* interrupted: the best so far */
    const char *missing;         /* files not written (fit.tsv names them), or NULL */
} cli_fit_report;

/* "fit", "poor fit", "unidentifiable", "not converged", "partial",
 * "failed": the verdict, and 0 when it is a fit. */
int cli_fit_verdict(const cli_fit_report *r, const char **word);

/* Why the fit's last failed model evaluation stopped, as a run's stop is
 * said: "STATUS: REASON (--flag)", its grid's settings in the words cfg's
 * keys were given in (a scene's by key and line) and --model=relax for
 * the relaxation (relax_model: the fit's model is already the relaxation),
 * the status alone where the model gave no reason, "" when none failed.
 * Written to buf (CLI_TABLES_STOPPED_LEN holds it whole), which is returned. */
const char *cli_fit_model_stop(const adh_config *cfg, const adh_fit_result *res, int relax_model, char *buf,
                               size_t len);

/* The report on out (standard output). */
void cli_fit_print(FILE *out, const cli_fit_report *r);
/* fit-points.tsv, best.scene, fit.png (unless plot is 0) and fit.tsv into
 * out, each tried whatever the others did. 0, or 2 (a table) / 3 (only the
 * figure) with why, naming each file not written. */
int cli_fit_write(const cli_fit_report *r, adh_outdir *out, int plot, char *why, size_t whylen);

#endif
