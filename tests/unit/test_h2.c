/* The H^2 operator on its own, with a kernel of its own: log|x - t| between
 * cells of growing widths (a graded line). The product against the dense
 * matrix of the same entries: its error falls with the interpolation order
 * (the far field is interpolated, the near field exact), concurrent
 * products agree with a lone one, the portable copy of the product with
 * the AVX2 one, and bad cells are refused. The same matrix held as a
 * symmetric one times column weights (adh_h2_problem.cw: its near field
 * once for both directions, padded to whole vectors) gives the same
 * product within rounding, on every CPU the same. */
#include <math.h>
#include <pthread.h>
#include <stdlib.h>

#include "adhere/h2.h"
#include "tap.h"

#define N 3000

static double edge[N + 1], x[N], w[N];

static double logk(void *ctx, double a, double b)
{
    return log(fabs(a - b));
}

/* entry (i, j): w_j log|x_i - x_j|, and w_j on the diagonal */
static double entry(size_t i, size_t j)
{
    return i == j ? w[j] : w[j] * log(fabs(x[i] - x[j]));
}

static void block(void *ctx, size_t i0, size_t ni, size_t j0, size_t nj, double *out)
{
    for (size_t i = 0; i < ni; i++)
        for (size_t j = 0; j < nj; j++)
            out[i * nj + j] = entry(i0 + i, j0 + j);
}

/* the symmetric part: log|x_i - x_j|, and 1 on the diagonal */
static void sym_block(void *ctx, size_t i0, size_t ni, size_t j0, size_t nj, double *out)
{
    for (size_t i = 0; i < ni; i++)
        for (size_t j = 0; j < nj; j++)
            out[i * nj + j] = i0 + i == j0 + j ? 1.0 : log(fabs(x[i0 + i] - x[j0 + j]));
}

/* The matrix as H diag(w), H symmetric, on the cells set now: against the
 * dense product and the weighted form's, its portable copy against its
 * AVX2 one; on cells of one width its bases are shared (less memory). */
static void symmetric(const char *cells, const adh_h2_problem *pb, const double *v, int equal)
{
    adh_h2_problem ps = *pb;
    ps.cw = w;
    ps.block = sym_block;
    ps.nq = 0;
    adh_h2_settings st = adh_h2_settings_default();
    st.order = 14;
    adh_h2 *h = adh_h2_alloc(&ps, &st), *hw = adh_h2_alloc(pb, &st);
    st.portable = 1;
    adh_h2 *hp = adh_h2_alloc(&ps, &st);
    double *y = malloc(4 * N * sizeof *y), *yp = y + N, *yw = y + 2 * N, *yd = y + 3 * N;
    if (!ok(h && hp && hw && y && adh_h2_apply(h, v, y) == 0 && adh_h2_apply(hp, v, yp) == 0 &&
                adh_h2_apply(hw, v, yw) == 0,
            "symmetric, %s: assembles and multiplies", cells))
        return;
    double num = 0, den = 0, dw = 0, big = 0;
    int same = 1;
    for (size_t i = 0; i < N; i++) {
        double acc = 0;
        for (size_t j = 0; j < N; j++)
            acc += entry(i, j) * v[j];
        yd[i] = acc;
        num += (y[i] - yd[i]) * (y[i] - yd[i]), den += yd[i] * yd[i];
        dw = fmax(dw, fabs(y[i] - yw[i]));
        big = fmax(big, fabs(yw[i]));
        same = same && y[i] == yp[i];
    }
    ok(sqrt(num / den) < 1e-10, "symmetric, %s, order 14: within 1e-10 of the dense product (%.1e)", cells,
       sqrt(num / den));
    ok(dw < 1e-13 * big, "symmetric, %s: the weighted form's product within rounding (%.1e of its largest)", cells,
       dw / big);
    ok(same, "symmetric, %s: the portable product equals the default one, digit for digit", cells);
    if (equal)
        ok(adh_h2_bytes(h) < adh_h2_bytes(hw) * 4 / 5, "symmetric, %s: holds %.2f MB, the weighted form %.2f MB",
           cells, adh_h2_bytes(h) / 1e6, adh_h2_bytes(hw) / 1e6);
    adh_h2_free(h), adh_h2_free(hp), adh_h2_free(hw), free(y);
}

typedef struct job {
    adh_h2 *h;
    const double *v;
    double *y;
    int rc;
} job;

static void *apply_many(void *arg)
{
    job *j = arg;
    for (int r = 0; r < 50 && j->rc == 0; r++)
        j->rc = adh_h2_apply(j->h, j->v, j->y);
    return NULL;
}

int main(void)
{
    /* a fine band, then cells 1.02 times wider each */
    edge[0] = 0;
    for (size_t i = 0; i < N; i++) {
        double width = i < N / 3 ? 1.0 : pow(1.02, (double)(i - N / 3));
        edge[i + 1] = edge[i] + width;
        x[i] = 0.5 * (edge[i] + edge[i + 1]);
        w[i] = width;
    }
    double *v = malloc(4 * N * sizeof *v), *yd = v + N, *yh = v + 2 * N, *yt = v + 3 * N;
    unsigned long s = 7;
    for (size_t i = 0; i < N; i++) {
        s = s * 6364136223846793005UL + 1442695040888963407UL;
        v[i] = (double)(s >> 11) / 9007199254740992.0 - 0.5;
    }
    for (size_t i = 0; i < N; i++) {
        double acc = 0;
        for (size_t j = 0; j < N; j++)
            acc += entry(i, j) * v[j];
        yd[i] = acc;
    }
    adh_h2_problem pb = { .n = N, .edge = edge, .x = x, .nq = 1, .qt = x, .qw = w, .kernel = logk, .block = block };
    int orders[] = { 4, 8, 14 };
    double err[3];
    adh_h2 *h14 = NULL;
    for (int o = 0; o < 3; o++) {
        adh_h2_settings st = adh_h2_settings_default();
        st.order = orders[o];
        adh_h2 *h = adh_h2_alloc(&pb, &st);
        if (!ok(h != NULL, "order %d: assembles", orders[o]))
            return tap_done();
        ok(adh_h2_apply(h, v, yh) == 0, "order %d: product", orders[o]);
        double num = 0, den = 0;
        for (size_t i = 0; i < N; i++)
            num += (yh[i] - yd[i]) * (yh[i] - yd[i]), den += yd[i] * yd[i];
        err[o] = sqrt(num / den);
        printf("# order %d: relative error %.2e, %.2f MB\n", orders[o], err[o], adh_h2_bytes(h) / 1e6);
        if (orders[o] == 14)
            h14 = h;
        else
            adh_h2_free(h);
    }
    ok(err[1] < err[0] / 10 && err[2] < err[1] / 10, "the error falls with the order: %.1e, %.1e, %.1e", err[0], err[1], err[2]);
    ok(err[2] < 1e-10, "order 14 within 1e-10 of the dense product (%.1e)", err[2]);
    ok(adh_h2_bytes(h14) < (size_t)N * N * sizeof(double) / 5, "holds %.2f MB where dense holds %.2f MB",
       adh_h2_bytes(h14) / 1e6, (double)N * N * 8 / 1e6);

    /* two threads at once (when they overlap, one works in the kept
     * workspace and the other in its own): both give the lone product,
     * digit for digit */
    adh_h2_apply(h14, v, yh);
    double *y2 = malloc(N * sizeof *y2);
    job a = { h14, v, yt, 0 }, b = { h14, v, y2, 0 };
    pthread_t ta, tb;
    int started = pthread_create(&ta, NULL, apply_many, &a) == 0 && pthread_create(&tb, NULL, apply_many, &b) == 0;
    if (started) {
        pthread_join(ta, NULL);
        pthread_join(tb, NULL);
    }
    int same = started && a.rc == 0 && b.rc == 0;
    for (size_t i = 0; i < N && same; i++)
        same = yt[i] == yh[i] && y2[i] == yh[i];
    ok(same, "concurrent products equal the lone one");

    /* the portable copy of the product (pairs of SSE2 halves) and the AVX2
     * one where this CPU runs it: the same additions in the same order */
    adh_h2_settings sp = adh_h2_settings_default();
    sp.order = 14; /* padded to 16: the padding's zeros take part too */
    sp.portable = 1;
    adh_h2 *hp = adh_h2_alloc(&pb, &sp);
    int equal = hp && adh_h2_apply(hp, v, yt) == 0;
    for (size_t i = 0; i < N && equal; i++)
        equal = yt[i] == yh[i];
    ok(equal, "the portable product equals the default one, digit for digit");
    adh_h2_free(hp);
    symmetric("graded cells", &pb, v, 0);
    adh_h2_free(h14);

    for (size_t i = 0; i < N; i++) { /* cells of one width */
        edge[i + 1] = (double)(i + 1);
        x[i] = (double)i + 0.5;
        w[i] = 1.0;
    }
    symmetric("equal cells", &pb, v, 1);

    edge[5] = edge[4];
    adh_h2_settings st = adh_h2_settings_default();
    ok(adh_h2_alloc(&pb, &st) == NULL, "an empty cell is refused");
    edge[5] = edge[4] + 1;
    st.order = 1;
    ok(adh_h2_alloc(&pb, &st) == NULL, "order 1 is refused");
    free(v), free(y2);
    return tap_done();
}
