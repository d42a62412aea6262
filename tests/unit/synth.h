/* Synthetic measured curves for the fit's tests and benchmark: the
 * program's own static curve at chosen parameters, at evenly spaced
 * positions down (approach) and back up (retract), each point on the
 * branch the drive is on (the outer branch until the jump-in, the contact
 * branch until the jump-out), plus Gaussian noise from a seeded generator
 * (GSL's MT19937: the same numbers on every machine). The truth of a test
 * is the parameters it chose here. */
#ifndef ADH_TEST_SYNTH_H
#define ADH_TEST_SYNTH_H

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "adhere/fitmodel.h"
#include "adhere/models.h"
#include "adhere/status.h"

typedef struct synth {
    size_t n;
    double x[1024], F[1024];
    int dir[1024], contact[1024], seg[1024];
    adh_fit_data d;
    double jump_in, jump_out;   /* the model's folds, m */
} synth;

/* napp points from top down to bottom, then nret back up (bottom not
 * repeated); x = h0 + offset, F = F_model + baseline + noise |F_JKR| N(0,1).
 * 0, or -1 when the model fails. */
static int synth_make(synth *s, const adh_grid *g, const adh_kernel *k, const adh_material *m, double top,
                      double bottom, size_t napp, size_t nret, double noise, unsigned long seed, double offset,
                      double baseline)
{
    s->n = napp + nret;
    if (s->n > 1024)
        return -1;
    for (size_t i = 0; i < napp; i++) {
        s->x[i] = top - (top - bottom) * (double)i / (double)(napp - 1);
        s->dir[i] = 1;
        s->seg[i] = 0;
    }
    for (size_t i = 0; i < nret; i++) {
        s->x[napp + i] = bottom + (top - bottom) * (double)(i + 1) / (double)nret;
        s->dir[napp + i] = -1;
        s->seg[napp + i] = 1;
    }
    for (size_t i = 0; i < s->n; i++)
        s->contact[i] = 0;
    s->d = (adh_fit_data){ .n = s->n, .x = s->x, .F = s->F, .dir = s->dir, .contact = s->contact, .seg = s->seg };
    adh_fit_model_settings ms = adh_fit_model_settings_default();
    adh_fit_model *fm = adh_fit_model_alloc(g, k, &ms);
    double *Fm = malloc(s->n * sizeof *Fm);
    int rc = fm && Fm ? adh_fit_model_eval(fm, m, offset, &s->d, Fm, NULL) : ADH_ENOMEM;
    if (rc == ADH_SUCCESS) {
        const double *h, *F;
        size_t n0 = adh_fit_model_branch(fm, 0, &h, &F);
        s->jump_in = h[0];
        size_t n1 = adh_fit_model_branch(fm, 1, &h, &F);
        s->jump_out = h[n1 - 1];
        (void)n0;
        for (size_t i = 0; i < s->n; i++)
            s->contact[i] = s->x[i] - offset < (s->dir[i] > 0 ? s->jump_in : s->jump_out);
        rc = adh_fit_model_eval(fm, m, offset, &s->d, Fm, NULL);
    }
    if (rc == ADH_SUCCESS) {
        gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
        gsl_rng_set(r, seed);
        double sd = noise * fabs(adh_jkr_pulloff(m));
        for (size_t i = 0; i < s->n; i++)
            s->F[i] = Fm[i] + baseline + (noise > 0 ? gsl_ran_gaussian(r, sd) : 0.0);
        gsl_rng_free(r);
    }
    free(Fm);
    adh_fit_model_free(fm);
    return rc == ADH_SUCCESS ? 0 : -1;
}

/* The curve as an instrument writes it: a header with spaces and units,
 * tab-separated, three columns (position in nm, force in nN, a time). */
static int synth_write(const synth *s, const char *path, const char *comment)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fprintf(f, "# %s\nSeparation (nm)\tForce (nN)\tTime (s)\n", comment);
    for (size_t i = 0; i < s->n; i++)
        fprintf(f, "%.6f\t%.6f\t%.4f\n", s->x[i] * 1e9, s->F[i] * 1e9, 0.01 * (double)i);
    return fclose(f);
}

#endif
