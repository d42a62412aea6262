/* Benchmark of the kernel's storage (issue "soft, strongly adhesive
 * spheres"): assembly time, bytes held and product time against N for the
 * dense matrix and the two hierarchical ones, hmat-oss's and the H^2
 * operator (ring kernel, uniform grid of 1.5 nm rings). Targets: the
 * hierarchical product at N = 10^4 within 10x the dense product at
 * N = 10^3; the hierarchical matrix at N = 10^5 under 200 MB. The
 * hierarchical product's error is measured against the dense one where the
 * dense matrix is built, else against exact rows (closed-form entries) at
 * sampled nodes.
 * First the paper's kernel on the paper's grid (N = 1000, the relaxation's
 * default there is h2): dense against h2, the two products timed in turn.
 * Arguments: the largest N built dense (default 10000: N^2 x 8 bytes, and
 * N^2 closed-form entries to assemble), the largest built by hmat-oss
 * (default 100000: 70 s to assemble there), then the sizes (default
 * 1000 3000 10000 30000 100000). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <time.h>

#include "adhere/kernel.h"

static double cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void openblas_set_num_threads(int);

/* Median CPU time of one product, over enough repeats to last ~0.3 s. */
static double product_time(const adh_kernel *k, const double *p, double *y, double *scr)
{
    double t[15];
    int reps = 1;
    double t0 = cpu();
    adh_kernel_apply(k, p, y, scr);
    double one = cpu() - t0;
    if (one > 0)
        reps = (int)fmin(15, fmax(3, 0.3 / one));
    for (int i = 0; i < reps; i++) {
        t0 = cpu();
        adh_kernel_apply(k, p, y, scr);
        t[i] = cpu() - t0;
    }
    for (int i = 1; i < reps; i++)
        for (int j = i; j > 0 && t[j] < t[j - 1]; j--) {
            double x = t[j];
            t[j] = t[j - 1], t[j - 1] = x;
        }
    return t[reps / 2];
}

static double peak_mb(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return (double)ru.ru_maxrss / 1024.0;
}

/* The hierarchical product's error: against the dense product yd when
 * there is one, else against exact rows (closed-form entries) at 20
 * sampled nodes, relative to the largest |y|. */
static double product_error(const adh_kernel *h, const adh_grid *g, const double *p, const double *yh, const double *yd)
{
    size_t n = g->n;
    double err = 0;
    if (yd) {
        double num = 0, den = 0;
        for (size_t i = 0; i < n; i++)
            num += (yh[i] - yd[i]) * (yh[i] - yd[i]), den += yd[i] * yd[i];
        return sqrt(num / den);
    }
    double ymax = 0;
    for (size_t i = 0; i < n; i++)
        ymax = fmax(ymax, fabs(yh[i]));
    for (size_t s = 0; s < 20; s++) {
        size_t i = (size_t)((double)s / 20.0 * (double)n);
        double y = 0;
        for (size_t j = 0; j < n; j++)
            y += adh_kernel_entry(h, i, j) * p[j];
        err = fmax(err, fabs(y - yh[i]) / ymax);
    }
    return err;
}

/* The paper's kernel at N = 1000: the dense product (dsymv) against the H^2
 * one, five rounds each timed in turn, medians: the ratio. */
static void paper_grid(void)
{
    size_t n = 1000;
    adh_grid *g = adh_grid_alloc(n, 1.5e-9);
    adh_kernel *k[2] = { NULL, NULL };
    double *p = malloc(3 * n * sizeof *p), *y = p + n, *scr = p + 2 * n, t[2][5];
    for (int s = 0; s < 2 && g; s++)
        k[s] = adh_kernel_alloc(g, &(adh_kernel_settings){ .storage = s ? ADH_STORAGE_H2 : ADH_STORAGE_DENSE }, NULL);
    if (!g || !p || !k[0] || !k[1]) {
        printf("paper kernel, N = 1000: failed to assemble\n");
        return;
    }
    for (size_t i = 0; i < n; i++) {
        double x = g->r[i] / (0.25 * g->rmax);
        p[i] = x < 1 ? -1.0 + 3.0 * exp(-(1 - x) * 50) : 2.0 * pow(x, -3.0);
    }
    for (int r = 0; r < 5; r++)
        for (int s = 0; s < 2; s++)
            t[s][r] = product_time(k[s], p, y, scr);
    for (int s = 0; s < 2; s++)
        for (int i = 1; i < 5; i++)
            for (int j = i; j > 0 && t[s][j] < t[s][j - 1]; j--) {
                double x = t[s][j];
                t[s][j] = t[s][j - 1], t[s][j - 1] = x;
            }
    printf("ratio: paper kernel product at N = 1000, dense / h2: %.2f (%.1f / %.1f us, medians of 5; h2 holds %.2f MB)\n\n",
           t[0][2] / t[1][2], 1e6 * t[0][2], 1e6 * t[1][2], adh_kernel_bytes(k[1]) / 1e6);
    adh_kernel_free(k[0]), adh_kernel_free(k[1]);
    adh_grid_free(g);
    free(p);
}

int main(int argc, char **argv)
{
    openblas_set_num_threads(1); /* the targets are for one core */
    size_t dense_max = argc > 1 ? (size_t)atol(argv[1]) : 10000;
    size_t hmat_max = argc > 2 ? (size_t)atol(argv[2]) : 100000;
    size_t def[] = { 1000, 3000, 10000, 30000, 100000 }, nn = argc > 3 ? (size_t)argc - 3 : 5;
    const adh_kernel_storage fast[] = { ADH_STORAGE_HMAT, ADH_STORAGE_H2 };
    double dense_1000 = NAN, at_10000[2] = { NAN, NAN }, mb_100000[2] = { NAN, NAN };
    paper_grid();
    printf("kernel storage: ring kernel, uniform 1.5 nm rings, one thread, CPU seconds\n");
    printf("%8s %6s %10s %12s %12s %10s\n", "N", "store", "assemble_s", "product_ms", "MB", "rel_err");
    for (size_t a = 0; a < nn; a++) {
        size_t n = argc > 3 ? (size_t)atol(argv[a + 3]) : def[a];
        adh_grid *g = adh_grid_alloc(n, 1.5e-9);
        double *p = malloc(4 * n * sizeof *p), *yd = p + n, *yh = p + 2 * n, *scr = p + 3 * n;
        if (!g || !p)
            return 1;
        /* a contact-like pressure: compressive core, adhesive edge, LJ tail */
        for (size_t i = 0; i < n; i++) {
            double x = g->r[i] / (0.05 * g->rmax);
            p[i] = x < 1 ? -1.0 + 3.0 * exp(-(1 - x) * 50) : 2.0 * pow(x, -3.0);
        }
        adh_kernel *d = NULL;
        if (n <= dense_max) {
            double t0 = cpu();
            d = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_RING }, NULL);
            double ta = cpu() - t0;
            if (d) {
                double tp = product_time(d, p, yd, scr);
                if (n == 1000)
                    dense_1000 = tp;
                printf("%8zu %6s %10.2f %12.4f %12.1f %10s\n", n, "dense", ta, 1e3 * tp, adh_kernel_bytes(d) / 1e6, "-");
            }
        } else {
            printf("%8zu %6s %10s %12s %12.1f %10s  (skipped: above %zu, N^2 x 8 bytes)\n", n, "dense", "-", "-",
                   (double)n * (double)n * 8 / 1e6, "-", dense_max);
        }
        fflush(stdout);
        for (int s = 0; s < 2; s++) {
            const char *name = adh_kernel_storage_name(fast[s]);
            if (fast[s] == ADH_STORAGE_HMAT && n > hmat_max) {
                printf("%8zu %6s %10s %12s %12s %10s  (skipped: above %zu)\n", n, name, "-", "-", "-", "-", hmat_max);
                continue;
            }
            double t0 = cpu();
            adh_kernel_settings ks = { .type = ADH_KERNEL_RING, .storage = fast[s] };
            adh_kernel *h = adh_kernel_alloc(g, &ks, NULL);
            double ta = cpu() - t0;
            if (!h) {
                printf("%8zu %6s failed to assemble\n", n, name);
                return 1;
            }
            double tp = product_time(h, p, yh, scr);
            double err = product_error(h, g, p, yh, d ? yd : NULL);
            if (n == 10000)
                at_10000[s] = tp;
            if (n == 100000)
                mb_100000[s] = adh_kernel_bytes(h) / 1e6;
            printf("%8zu %6s %10.2f %12.4f %12.1f %10.1e\n", n, name, ta, 1e3 * tp, adh_kernel_bytes(h) / 1e6, err);
            fflush(stdout);
            adh_kernel_free(h);
        }
        adh_kernel_free(d);
        adh_grid_free(g);
        free(p);
    }
    printf("peak resident memory of this run: %.0f MB\n", peak_mb());
    for (int s = 0; s < 2; s++) {
        const char *name = adh_kernel_storage_name(fast[s]);
        if (isfinite(dense_1000) && isfinite(at_10000[s]))
            printf("target: %s product at N=1e4 / dense at N=1e3 = %.1f (target <= 10): %s\n", name,
                   at_10000[s] / dense_1000, at_10000[s] / dense_1000 <= 10 ? "met" : "not met");
        if (isfinite(mb_100000[s]))
            printf("target: %s matrix at N=1e5 holds %.0f MB (target < 200): %s\n", name, mb_100000[s],
                   mb_100000[s] < 200 ? "met" : "not met");
    }
    return 0;
}
