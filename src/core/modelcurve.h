/* Inside the core: samples a model given as F(a), overlap(a) into an
 * adh_model_curve (models.h). Not part of the public interface. */
#ifndef ADH_CORE_MODELCURVE_H
#define ADH_CORE_MODELCURVE_H

#include "adhere/models.h"

/* The model at contact radius a; ADH_SUCCESS or an error to pass on. */
typedef int (*adh_radius_model)(const adh_material *m, const void *ctx, double a, double *F,
                                 double *overlap);

/* Contact radii from the one where h0 = z0 - overlap comes down to h0_min
 * (found by bisection: the overlap must rise with a above a_fold) down to
 * a_fold, with a_pull (a_fold <= a_pull) sampled exactly: the pull-off that
 * ends the load-controlled part. */
int adh_model_sample(const adh_material *m, adh_radius_model fn, const void *ctx, double a_fold,
                     double a_pull, double h0_min, adh_model_curve *c);

#endif
