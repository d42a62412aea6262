/* The kernel operator's interface (adhere/kernel.h): one constructor from
 * settings, the product, entries and bytes through the storage's own
 * (kernel_dense.c, kernel_hier.c), and the closed forms they all share. */
#include "adhere/kernel.h"
#include "adhere/status.h"
#include "core/kernel.h"

#include <gsl/gsl_sf_ellint.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Carlson forms keep every digit as the parameter m -> 1 (one_minus_m passed in
 * exactly), where the modulus-based gsl_sf_ellint_Kcomp loses them. */
static double ellint_K(double one_minus_m)
{
    return gsl_sf_ellint_RF(0.0, one_minus_m, 1.0, GSL_PREC_DOUBLE);
}

static double ellint_E(double m, double one_minus_m)
{
    return gsl_sf_ellint_RF(0.0, one_minus_m, 1.0, GSL_PREC_DOUBLE) -
           m / 3.0 * gsl_sf_ellint_RD(0.0, one_minus_m, 1.0, GSL_PREC_DOUBLE);
}

double adh_disk_integral(double r, double a)
{
    if (a <= 0)
        return 0;
    if (r <= 0)
        return 2.0 * a; /* (4a/pi) E(0) */
    if (r < a) {
        double m = (r / a) * (r / a), om = (a - r) * (a + r) / (a * a);
        return 4.0 * a / M_PI * ellint_E(m, om);
    }
    /* E(m) - (1-m) K(m) = m [RF - RD/3]: no cancellation for small m. */
    double m = (a / r) * (a / r), om = (r - a) * (r + a) / (r * r);
    if (om <= 0)
        return 4.0 * r / M_PI; /* r == a: E(1) = 1 */
    double rf = gsl_sf_ellint_RF(0.0, om, 1.0, GSL_PREC_DOUBLE);
    double rd = gsl_sf_ellint_RD(0.0, om, 1.0, GSL_PREC_DOUBLE);
    return 4.0 * r / M_PI * m * (rf - rd / 3.0);
}

double adh_kernel_k(double r, double t)
{
    double lo = r < t ? r : t, hi = r < t ? t : r;
    double om = (hi - lo) * (hi + lo) / (hi * hi);
    return 4.0 / (M_PI * hi) * ellint_K(om);
}

/* The diagonal of eqs 19-21: the log singularity integrated over the cell,
 * returned as k_nn * dr (so that out_n gets k_nn * dr * r_n * p_n). */
double adh_kernel_paper_diagonal(double rn, double d)
{
    double im = (d / M_PI - d * d / (4.0 * M_PI * rn)) *
                (1.0 + log(16.0 * rn * rn / (rn * d - d * d / 4.0)));
    double ip = d / M_PI * log(16.0 * (rn + d / 2.0) * (rn + d / 2.0) / (rn * d + d * d / 4.0)) +
                4.0 * rn / M_PI * log((2.0 * rn + d) / (2.0 * rn + d / 2.0));
    return (ip + im) / rn;
}

double adh_kernel_formula(const adh_kernel *k, size_t n, size_t j)
{
    const adh_grid *g = k->g;
    if (k->type == ADH_KERNEL_PAPER)
        return n == j ? adh_kernel_paper_diagonal(g->r[n], k->dr) * g->r[j]
                      : k->dr * adh_kernel_k(g->r[n], g->r[j]) * g->r[j];
    double a = g->graded ? g->edge[j] : (double)j * k->dr;
    double b = g->graded ? g->edge[j + 1] : (double)(j + 1) * k->dr;
    return adh_disk_integral(g->r[n], b) - adh_disk_integral(g->r[n], a);
}

adh_kernel_settings adh_kernel_settings_default(void)
{
    return (adh_kernel_settings){ .type = ADH_KERNEL_PAPER, .storage = ADH_STORAGE_DENSE, .cancel = NULL };
}

adh_kernel *adh_kernel_alloc(const adh_grid *g, const adh_kernel_settings *s, int *status)
{
    int st;
    if (!status)
        status = &st;
    *status = ADH_EINVAL;
    /* The paper's diagonal (eqs 19-21) assumes equal cells around each node. */
    if ((s->type != ADH_KERNEL_PAPER && s->type != ADH_KERNEL_RING) || (s->type == ADH_KERNEL_PAPER && g->graded))
        return NULL;
    if (s->storage != ADH_STORAGE_DENSE && s->storage != ADH_STORAGE_HMAT && s->storage != ADH_STORAGE_H2)
        return NULL;
    *status = ADH_ENOMEM;
    adh_kernel *k = calloc(1, sizeof *k);
    if (!k)
        return NULL;
    *k = (adh_kernel){ .type = s->type, .storage = s->storage, .n = g->n, .dr = g->dr, .r = g->r, .g = g };
    int rc = s->storage == ADH_STORAGE_DENSE ? adh_kernel_dense_build(k, s->cancel)
             : s->storage == ADH_STORAGE_H2  ? adh_kernel_h2_build(k)
                                             : adh_kernel_hmat_build(k);
    *status = rc;
    if (rc != ADH_SUCCESS) {
        free(k);
        return NULL;
    }
    return k;
}

void adh_kernel_free(adh_kernel *k)
{
    if (!k)
        return;
    k->ops->free(k->impl);
    free(k);
}

void adh_kernel_apply(const adh_kernel *k, const double *p, double *out, double *scratch)
{
    k->ops->apply(k, p, out, scratch);
}

double adh_kernel_entry(const adh_kernel *k, size_t n, size_t j)
{
    return k->ops->entry(k, n, j);
}

double adh_kernel_diagonal(const adh_kernel *k, size_t n)
{
    return adh_kernel_entry(k, n, n);
}

size_t adh_kernel_bytes(const adh_kernel *k)
{
    return k->ops->bytes(k);
}

adh_kernel_storage adh_kernel_storage_of(const adh_kernel *k)
{
    return k->storage;
}

adh_kernel_type adh_kernel_kind(const adh_kernel *k)
{
    return k->type;
}

const char *adh_kernel_storage_name(adh_kernel_storage s)
{
    return s == ADH_STORAGE_HMAT ? "hmat" : s == ADH_STORAGE_H2 ? "h2" : "dense";
}

int adh_kernel_storage_parse(const char *name, adh_kernel_storage *s)
{
    if (strcmp(name, "dense") == 0)
        *s = ADH_STORAGE_DENSE;
    else if (strcmp(name, "hmat") == 0)
        *s = ADH_STORAGE_HMAT;
    else if (strcmp(name, "h2") == 0)
        *s = ADH_STORAGE_H2;
    else
        return ADH_EINVAL;
    return ADH_SUCCESS;
}

const char *adh_kernel_name(adh_kernel_type type)
{
    return type == ADH_KERNEL_RING ? "ring" : "paper";
}

int adh_kernel_parse(const char *name, adh_kernel_type *type)
{
    if (strcmp(name, "paper") == 0)
        *type = ADH_KERNEL_PAPER;
    else if (strcmp(name, "ring") == 0)
        *type = ADH_KERNEL_RING;
    else
        return ADH_EINVAL;
    return ADH_SUCCESS;
}
