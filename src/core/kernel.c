#include "adhere/kernel.h"
#include "adhere/status.h"

#include "adhere/h2.h"
#include "adhere/hmatrix.h"
#include "adhere/rings.h"

#include <gsl/gsl_cblas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_ellint.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct adh_kernel {
    adh_kernel_type type;
    size_t n;
    double dr;
    const double *r;   /* borrowed from the grid */
    double *w;         /* paper: symmetric k-matrix (times dr); ring: full influence matrix */
    adh_kernel_storage storage;
    const adh_grid *g; /* borrowed: hierarchical entries come from its edges */
    adh_hmatrix *h;    /* hmat-oss storage (w is then NULL) */
    adh_h2 *h2;        /* H^2 storage (w is then NULL) */
};

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

/* k(r,t) of eq 9 */
static double kernel_k(double r, double t)
{
    double lo = r < t ? r : t, hi = r < t ? t : r;
    double om = (hi - lo) * (hi + lo) / (hi * hi);
    return 4.0 / (M_PI * hi) * ellint_K(om);
}

/* The diagonal of eqs 19-21: the log singularity integrated over the cell,
 * returned as k_nn * dr (so that out_n gets k_nn * dr * r_n * p_n). */
static double paper_diagonal(double rn, double d)
{
    double im = (d / M_PI - d * d / (4.0 * M_PI * rn)) *
                (1.0 + log(16.0 * rn * rn / (rn * d - d * d / 4.0)));
    double ip = d / M_PI * log(16.0 * (rn + d / 2.0) * (rn + d / 2.0) / (rn * d + d * d / 4.0)) +
                4.0 * rn / M_PI * log((2.0 * rn + d) / (2.0 * rn + d / 2.0));
    return (ip + im) / rn;
}

adh_kernel *adh_kernel_alloc(const adh_grid *g, adh_kernel_type type)
{
    int status;
    return adh_kernel_alloc_cancel(g, type, NULL, &status);
}

adh_kernel *adh_kernel_alloc_cancel(const adh_grid *g, adh_kernel_type type,
                                    const volatile sig_atomic_t *cancel, int *status)
{
    /* GSL's default handler aborts; the core reports through status codes. */
    gsl_set_error_handler_off();
    *status = ADH_ENOMEM;
    /* The paper's diagonal (eqs 19-21) assumes equal cells around each node. */
    if (type == ADH_KERNEL_PAPER && g->graded) {
        *status = ADH_EINVAL;
        return NULL;
    }
    size_t n = g->n;
    adh_kernel *k = calloc(1, sizeof *k);
    if (!k)
        return NULL;
    k->type = type;
    k->n = n;
    k->dr = g->dr;
    k->r = g->r;
    k->g = g;
    k->w = malloc(n * n * sizeof *k->w);
    if (!k->w) {
        adh_kernel_free(k);
        return NULL;
    }
    double d = g->dr;
    if (type == ADH_KERNEL_PAPER) {
        /* Symmetric: fill the lower triangle (dsymv reads only that), mirror
         * for adh_kernel_entry. */
        for (size_t i = 0; i < n; i++) {
            if (cancel && *cancel) {
                adh_kernel_free(k);
                *status = ADH_EINTR;
                return NULL;
            }
            for (size_t j = 0; j < i; j++) {
                double v = d * kernel_k(g->r[i], g->r[j]);
                k->w[i * n + j] = v;
                k->w[j * n + i] = v;
            }
            k->w[i * n + i] = paper_diagonal(g->r[i], d);
        }
    } else {
        double *prev = malloc((n) * sizeof *prev);
        if (!prev) {
            adh_kernel_free(k);
            return NULL;
        }
        for (size_t i = 0; i < n; i++)
            prev[i] = 0.0; /* D(r, 0) = 0 */
        for (size_t j = 0; j < n; j++) {
            if (cancel && *cancel) {
                free(prev);
                adh_kernel_free(k);
                *status = ADH_EINTR;
                return NULL;
            }
            double b = g->graded ? g->edge[j + 1] : (double)(j + 1) * d;
            for (size_t i = 0; i < n; i++) {
                double db = adh_disk_integral(g->r[i], b);
                k->w[i * n + j] = db - prev[i];
                prev[i] = db;
            }
        }
        free(prev);
    }
    *status = ADH_SUCCESS;
    return k;
}

/* W_nj from the closed forms, as the dense matrices above hold it. */
static double formula_entry(const adh_kernel *k, size_t n, size_t j)
{
    const adh_grid *g = k->g;
    if (k->type == ADH_KERNEL_PAPER)
        return n == j ? paper_diagonal(g->r[n], k->dr) * g->r[j] : k->dr * kernel_k(g->r[n], g->r[j]) * g->r[j];
    double a = g->graded ? g->edge[j] : (double)j * k->dr;
    double b = g->graded ? g->edge[j + 1] : (double)(j + 1) * k->dr;
    return adh_disk_integral(g->r[n], b) - adh_disk_integral(g->r[n], a);
}

static double hmat_entry(void *ctx, size_t n, size_t j)
{
    return formula_entry(ctx, n, j);
}

/* The ring kernel's near field, a block at a time: consecutive columns
 * share their edges, so a row of nj entries takes nj + 1 disk integrals. */
static void h2_block(void *ctx, size_t i0, size_t ni, size_t j0, size_t nj, double *out)
{
    const adh_kernel *k = ctx;
    for (size_t i = 0; i < ni; i++) {
        if (k->type == ADH_KERNEL_PAPER) {
            for (size_t j = 0; j < nj; j++)
                out[i * nj + j] = formula_entry(k, i0 + i, j0 + j);
            continue;
        }
        double r = k->r[i0 + i], prev = adh_disk_integral(r, adh_rings_edge(k->g, j0));
        for (size_t j = 0; j < nj; j++) {
            double next = adh_disk_integral(r, adh_rings_edge(k->g, j0 + j + 1));
            out[i * nj + j] = next - prev;
            prev = next;
        }
    }
}

static double h2_kernel(void *ctx, double r, double t)
{
    return kernel_k(r, t);
}

/* The H^2 operator: the far field of column j is the kernel against
 * column j's measure, t dt over ring j (Gauss-Legendre, exact for the
 * interpolating polynomials) or, for the paper's collocation, the point
 * r_j of weight dr r_j. */
static adh_h2 *h2_alloc(adh_kernel *k)
{
    const adh_grid *g = k->g;
    size_t n = g->n;
    adh_h2_settings hs = adh_h2_settings_default();
    size_t nq = k->type == ADH_KERNEL_PAPER ? 1 : (size_t)hs.order / 2 + 1;
    double *edge = malloc((n + 1) * sizeof *edge), *qt = malloc(2 * n * nq * sizeof *qt), *qw = qt + n * nq;
    gsl_integration_glfixed_table *gl = nq > 1 ? gsl_integration_glfixed_table_alloc(nq) : NULL;
    adh_h2 *h = NULL;
    if (!edge || !qt || (nq > 1 && !gl))
        goto done;
    for (size_t j = 0; j <= n; j++)
        edge[j] = adh_rings_edge(g, j);
    for (size_t j = 0; j < n; j++) {
        if (nq == 1) {
            qt[j] = g->r[j];
            qw[j] = k->dr * g->r[j];
            continue;
        }
        for (size_t q = 0; q < nq; q++) {
            double t, w;
            gsl_integration_glfixed_point(edge[j], edge[j + 1], q, &t, &w, gl);
            qt[j * nq + q] = t;
            qw[j * nq + q] = w * t;
        }
    }
    adh_h2_problem pb = { .n = n, .edge = edge, .x = g->r, .nq = nq, .qt = qt, .qw = qw,
                          .kernel = h2_kernel, .block = h2_block, .ctx = k };
    h = adh_h2_alloc(&pb, &hs);
done:
    if (gl)
        gsl_integration_glfixed_table_free(gl);
    free(edge), free(qt);
    return h;
}

adh_kernel *adh_kernel_alloc_stored(const adh_grid *g, adh_kernel_type type, adh_kernel_storage s)
{
    int status;
    return adh_kernel_alloc_stored_cancel(g, type, s, NULL, &status);
}

adh_kernel *adh_kernel_alloc_stored_cancel(const adh_grid *g, adh_kernel_type type, adh_kernel_storage s,
                                           const volatile sig_atomic_t *cancel, int *status)
{
    if (s == ADH_STORAGE_DENSE)
        return adh_kernel_alloc_cancel(g, type, cancel, status);
    gsl_set_error_handler_off();
    *status = ADH_EINVAL;
    if (type == ADH_KERNEL_PAPER && g->graded)
        return NULL;
    *status = ADH_ENOMEM;
    adh_kernel *k = calloc(1, sizeof *k);
    if (!k)
        return NULL;
    *k = (adh_kernel){ .type = type, .n = g->n, .dr = g->dr, .r = g->r, .storage = s, .g = g };
    if (s == ADH_STORAGE_H2) {
        k->h2 = h2_alloc(k);
    } else {
        adh_hmatrix_settings hs = adh_hmatrix_settings_default();
        k->h = adh_hmatrix_alloc(g->n, g->r, hmat_entry, k, &hs);
    }
    if (!k->h && !k->h2) {
        free(k);
        return NULL;
    }
    return k;
}

adh_kernel_storage adh_kernel_storage_of(const adh_kernel *k)
{
    return k->storage;
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

size_t adh_kernel_bytes(const adh_kernel *k)
{
    if (k->h2)
        return adh_h2_bytes(k->h2);
    return k->h ? adh_hmatrix_bytes(k->h) : k->n * k->n * sizeof *k->w;
}

double adh_kernel_diagonal(const adh_kernel *k, size_t n)
{
    return adh_kernel_entry(k, n, n);
}

void adh_kernel_free(adh_kernel *k)
{
    if (!k)
        return;
    adh_hmatrix_free(k->h);
    adh_h2_free(k->h2);
    free(k->w);
    free(k);
}

adh_kernel_type adh_kernel_kind(const adh_kernel *k)
{
    return k->type;
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

void adh_kernel_apply(const adh_kernel *k, const double *p, double *out, double *scratch)
{
    int n = (int)k->n;
    if (k->h2) {
        if (adh_h2_apply(k->h2, p, out) != 0)
            for (int i = 0; i < n; i++)
                out[i] = NAN;
        return;
    }
    if (k->h) {
        /* A failed product must not pass for a deformation. */
        if (adh_hmatrix_apply(k->h, p, out, scratch) != 0)
            for (int i = 0; i < n; i++)
                out[i] = NAN;
        return;
    }
    if (k->type == ADH_KERNEL_PAPER) {
        for (int i = 0; i < n; i++)
            scratch[i] = k->r[i] * p[i];
        cblas_dsymv(CblasRowMajor, CblasLower, n, 1.0, k->w, n, scratch, 1, 0.0, out, 1);
    } else {
        cblas_dgemv(CblasRowMajor, CblasNoTrans, n, n, 1.0, k->w, n, p, 1, 0.0, out, 1);
    }
}

double adh_kernel_entry(const adh_kernel *k, size_t n, size_t j)
{
    if (k->h || k->h2)
        return formula_entry(k, n, j);
    double w = k->w[n * k->n + j];
    return k->type == ADH_KERNEL_PAPER ? w * k->r[j] : w;
}
