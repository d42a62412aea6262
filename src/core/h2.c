#include "adhere/h2.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

typedef struct h2_cluster {
    size_t i0, n;        /* cells i0 .. i0 + n - 1 */
    double lo, hi;       /* their interval */
    size_t parent;       /* the root is its own parent */
    size_t child[2];     /* 0: a leaf (the root is nobody's child) */
} h2_cluster;

/* A block of the near field: rows of one leaf against the columns of
 * neighbouring leaves, merged into one span where they are contiguous. */
typedef struct h2_near {
    size_t i0, ni;       /* rows */
    size_t j0, nj;       /* columns */
    size_t off;          /* the block in the near store, row-major */
} h2_near;

struct adh_h2 {
    size_t n;
    size_t p;            /* Chebyshev nodes per cluster */
    size_t ncl;
    h2_cluster *cl;      /* pre-order: a parent before its children */
    double *node;        /* ncl x p Chebyshev nodes (assembly only) */
    double *U;           /* n x p: L_a(x_i), the basis of cell i's leaf */
    double *S;           /* per leaf x, p x n_x at row i0_x: column i's quadrature of L_b */
    double *T;           /* ncl x p x p: T_c[b][b'] = L^parent_b'(node_c[b]) */
    size_t nfar;
    size_t (*far)[2];    /* cluster pairs (x before y), both directions */
    double *K;           /* nfar x p x p: k(node_x[a], node_y[b]) */
    size_t nnear;
    h2_near *near;
    double *B;           /* the near field's exact entries */
    size_t nB;
    double *work;        /* 2 ncl p: moments and local expansions */
    pthread_mutex_t lock;
};

adh_h2_settings adh_h2_settings_default(void)
{
    /* Measured (README, "Graded grids and kernel operators"), ring kernel,
     * uniform and graded grids: 14 nodes keep the product within ~1e-12 of
     * the dense one (12: ~1e-11, 10: ~1e-10). eta a little above 1 makes
     * leaves two apart far on a uniform grid, whose halved sizes differ by a
     * cell (20 % less memory than eta = 1). Leaves of at most 32 cells
     * balance the near field against the couplings. */
    return (adh_h2_settings){ .order = 14, .eta = 1.2, .leaf = 32 };
}

static void cheb_nodes(double lo, double hi, size_t p, double *out)
{
    double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    for (size_t k = 0; k < p; k++)
        out[k] = mid + half * cos((2.0 * (double)k + 1.0) * M_PI / (2.0 * (double)p));
}

/* The p Lagrange polynomials of Chebyshev (first kind) nodes c at x, in
 * barycentric form (weights (-1)^k sin((2k+1) pi / 2p)): stable anywhere
 * in the interval. */
static void lagrange(const double *c, size_t p, double x, double *out)
{
    double sum = 0;
    for (size_t k = 0; k < p; k++) {
        if (x == c[k]) {
            for (size_t m = 0; m < p; m++)
                out[m] = m == k ? 1.0 : 0.0;
            return;
        }
        double w = sin((2.0 * (double)k + 1.0) * M_PI / (2.0 * (double)p)) * (k % 2 ? -1.0 : 1.0);
        out[k] = w / (x - c[k]);
        sum += out[k];
    }
    for (size_t k = 0; k < p; k++)
        out[k] /= sum;
}

typedef struct h2_build {
    adh_h2 *h;
    const adh_h2_problem *pb;
    const adh_h2_settings *s;
    size_t cap_far, cap_K, cap_near;
    int fail;
} h2_build;

static size_t build_tree(h2_build *b, size_t i0, size_t n, size_t parent)
{
    adh_h2 *h = b->h;
    size_t id = h->ncl++;
    h->cl[id] = (h2_cluster){ .i0 = i0, .n = n, .lo = b->pb->edge[i0], .hi = b->pb->edge[i0 + n], .parent = parent };
    if (n > (size_t)b->s->leaf) {
        size_t m = n / 2;
        size_t c0 = build_tree(b, i0, m, id);
        size_t c1 = build_tree(b, i0 + m, n - m, id);
        h->cl[id].child[0] = c0;
        h->cl[id].child[1] = c1;
    }
    return id;
}

static int grow(void **a, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap)
        return 0;
    size_t c = *cap ? *cap : 64;
    while (c < need)
        c *= 2;
    void *x = realloc(*a, c * size);
    if (!x)
        return -1;
    *a = x;
    *cap = c;
    return 0;
}

static void add_far(h2_build *b, size_t x, size_t y)
{
    adh_h2 *h = b->h;
    size_t p = h->p;
    if (grow((void **)&h->far, &b->cap_far, h->nfar + 1, sizeof *h->far) ||
        grow((void **)&h->K, &b->cap_K, h->nfar + 1, p * p * sizeof *h->K)) {
        b->fail = 1;
        return;
    }
    double *K = h->K + h->nfar * p * p;
    const double *nx = h->node + x * p, *ny = h->node + y * p;
    for (size_t a = 0; a < p; a++)
        for (size_t c = 0; c < p; c++)
            K[a * p + c] = b->pb->kernel(b->pb->ctx, nx[a], ny[c]);
    h->far[h->nfar][0] = x;
    h->far[h->nfar][1] = y;
    h->nfar++;
}

/* Recorded here, merged and filled by near_fill once all are known. */
static void add_near(h2_build *b, size_t x, size_t y)
{
    adh_h2 *h = b->h;
    const h2_cluster *X = &h->cl[x], *Y = &h->cl[y];
    if (grow((void **)&h->near, &b->cap_near, h->nnear + 1, sizeof *h->near)) {
        b->fail = 1;
        return;
    }
    h->near[h->nnear++] = (h2_near){ .i0 = X->i0, .ni = X->n, .j0 = Y->i0, .nj = Y->n };
}

static int near_order(const void *pa, const void *pb)
{
    const h2_near *a = pa, *b = pb;
    if (a->i0 != b->i0)
        return a->i0 < b->i0 ? -1 : 1;
    return a->j0 < b->j0 ? -1 : a->j0 > b->j0;
}

/* Each leaf's near blocks, sorted by column and merged where they abut
 * (one longer row product instead of several short ones), then their
 * exact entries. */
static int near_fill(adh_h2 *h, const adh_h2_problem *pb)
{
    if (h->nnear == 0)
        return 0;
    qsort(h->near, h->nnear, sizeof *h->near, near_order);
    size_t m = 0;
    for (size_t b = 1; b < h->nnear; b++) {
        h2_near *last = &h->near[m], *next = &h->near[b];
        if (next->i0 == last->i0 && next->j0 == last->j0 + last->nj)
            last->nj += next->nj;
        else
            h->near[++m] = *next;
    }
    h->nnear = m + 1;
    h->nB = 0;
    for (size_t b = 0; b < h->nnear; b++) {
        h->near[b].off = h->nB;
        h->nB += h->near[b].ni * h->near[b].nj;
    }
    h2_near *shrunk = realloc(h->near, h->nnear * sizeof *h->near);
    if (shrunk)
        h->near = shrunk;
    h->B = malloc(h->nB * sizeof *h->B);
    if (!h->B)
        return -1;
    for (size_t b = 0; b < h->nnear; b++) {
        const h2_near *nb = &h->near[b];
        pb->block(pb->ctx, nb->i0, nb->ni, nb->j0, nb->nj, h->B + nb->off);
    }
    return 0;
}

/* The blocks of two disjoint clusters, x's cells before y's: one far
 * coupling when they are well separated, else their children's blocks (the
 * much wider one split alone, so graded cells pair sensibly). */
static void build_pair(h2_build *b, size_t x, size_t y)
{
    if (b->fail)
        return;
    const h2_cluster *X = &b->h->cl[x], *Y = &b->h->cl[y];
    double dx = X->hi - X->lo, dy = Y->hi - Y->lo, dist = Y->lo - X->hi;
    int lx = X->child[0] == 0, ly = Y->child[0] == 0;
    if (dist > 0 && fmax(dx, dy) <= b->s->eta * dist) {
        add_far(b, x, y);
    } else if (lx && ly) {
        add_near(b, x, y);
        add_near(b, y, x);
    } else if (lx || (!ly && dy > 2.0 * dx)) {
        size_t y0 = Y->child[0], y1 = Y->child[1];
        build_pair(b, x, y0);
        build_pair(b, x, y1);
    } else if (ly || dx > 2.0 * dy) {
        size_t x0 = X->child[0], x1 = X->child[1];
        build_pair(b, x0, y);
        build_pair(b, x1, y);
    } else {
        size_t x0 = X->child[0], x1 = X->child[1], y0 = Y->child[0], y1 = Y->child[1];
        build_pair(b, x0, y0);
        build_pair(b, x0, y1);
        build_pair(b, x1, y0);
        build_pair(b, x1, y1);
    }
}

static void build_self(h2_build *b, size_t x)
{
    if (b->fail)
        return;
    const h2_cluster *X = &b->h->cl[x];
    if (X->child[0] == 0) {
        add_near(b, x, x);
        return;
    }
    size_t c0 = X->child[0], c1 = X->child[1];
    build_self(b, c0);
    build_self(b, c1);
    build_pair(b, c0, c1);
}

adh_h2 *adh_h2_alloc(const adh_h2_problem *pb, const adh_h2_settings *s)
{
    size_t n = pb->n, p = (size_t)s->order;
    if (n == 0 || s->order < 2 || s->leaf < 1 || !(s->eta > 0) || pb->nq == 0)
        return NULL;
    for (size_t i = 0; i < n; i++)
        if (!(pb->edge[i] < pb->edge[i + 1]))
            return NULL;
    adh_h2 *h = calloc(1, sizeof *h);
    if (!h)
        return NULL;
    h->n = n;
    h->p = p;
    h2_build b = { .h = h, .pb = pb, .s = s };
    h->cl = calloc(2 * n, sizeof *h->cl);
    double *lp = malloc(p * sizeof *lp);
    if (!h->cl || !lp)
        goto fail;
    build_tree(&b, 0, n, 0);
    h2_cluster *cl = realloc(h->cl, h->ncl * sizeof *h->cl);
    if (cl)
        h->cl = cl;
    size_t ncl = h->ncl;
    h->node = malloc(ncl * p * sizeof *h->node);
    h->T = calloc(ncl * p * p, sizeof *h->T);
    h->U = malloc(n * p * sizeof *h->U);
    h->S = calloc(n * p, sizeof *h->S);
    h->work = malloc(2 * ncl * p * sizeof *h->work);
    if (!h->node || !h->T || !h->U || !h->S || !h->work)
        goto fail;
    for (size_t c = 0; c < ncl; c++)
        cheb_nodes(h->cl[c].lo, h->cl[c].hi, p, h->node + c * p);
    /* The parent's polynomials are exactly those of degree < p on each
     * child: interpolating them there is exact, so the bases nest. */
    for (size_t c = 1; c < ncl; c++)
        for (size_t k = 0; k < p; k++)
            lagrange(h->node + h->cl[c].parent * p, p, h->node[c * p + k], h->T + (c * p + k) * p);
    for (size_t c = 0; c < ncl; c++) {
        const h2_cluster *X = &h->cl[c];
        if (X->child[0] != 0)
            continue;
        const double *nd = h->node + c * p;
        double *S = h->S + X->i0 * p;
        for (size_t i = X->i0; i < X->i0 + X->n; i++) {
            lagrange(nd, p, pb->x[i], h->U + i * p);
            for (size_t q = 0; q < pb->nq; q++) {
                lagrange(nd, p, pb->qt[i * pb->nq + q], lp);
                for (size_t k = 0; k < p; k++)
                    S[k * X->n + i - X->i0] += pb->qw[i * pb->nq + q] * lp[k];
            }
        }
    }
    build_self(&b, 0);
    if (b.fail || near_fill(h, pb) != 0)
        goto fail;
    free(h->node);
    h->node = NULL;
    /* the couplings grew by doubling: hand the slack back */
    if (h->nfar > 0) {
        double *K = realloc(h->K, h->nfar * p * p * sizeof *h->K);
        size_t(*far)[2] = realloc(h->far, h->nfar * sizeof *h->far);
        if (K)
            h->K = K;
        if (far)
            h->far = far;
    }
    if (pthread_mutex_init(&h->lock, NULL) != 0)
        goto fail;
    free(lp);
    return h;
fail:
    free(lp);
    free(h->cl), free(h->node), free(h->T), free(h->U), free(h->S), free(h->work);
    free(h->far), free(h->K), free(h->near), free(h->B);
    free(h);
    return NULL;
}

void adh_h2_free(adh_h2 *h)
{
    if (!h)
        return;
    pthread_mutex_destroy(&h->lock);
    free(h->cl), free(h->node), free(h->T), free(h->U), free(h->S), free(h->work);
    free(h->far), free(h->K), free(h->near), free(h->B);
    free(h);
}

/* Four partial sums: the product's short dot products are otherwise bound
 * by the latency of one chain of additions, not by memory. */
static inline double dot(const double *a, const double *b, size_t n)
{
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    size_t i = 0;
    for (; i + 4 <= n; i += 4) {
        s0 += a[i] * b[i];
        s1 += a[i + 1] * b[i + 1];
        s2 += a[i + 2] * b[i + 2];
        s3 += a[i + 3] * b[i + 3];
    }
    for (; i < n; i++)
        s0 += a[i] * b[i];
    return (s0 + s1) + (s2 + s3);
}

/* The same down a column of a row-major matrix (stride sa). */
static inline double dot_stride(const double *a, size_t sa, const double *b, size_t n)
{
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    size_t i = 0;
    for (; i + 4 <= n; i += 4) {
        s0 += a[i * sa] * b[i];
        s1 += a[(i + 1) * sa] * b[i + 1];
        s2 += a[(i + 2) * sa] * b[i + 2];
        s3 += a[(i + 3) * sa] * b[i + 3];
    }
    for (; i < n; i++)
        s0 += a[i * sa] * b[i];
    return (s0 + s1) + (s2 + s3);
}

static void product(const adh_h2 *h, const double *v, double *y, double *work)
{
    size_t p = h->p, ncl = h->ncl;
    double *M = work, *L = work + ncl * p;
    memset(work, 0, 2 * ncl * p * sizeof *work);
    /* upward: the leaves' moments, then each child's into its parent
     * (reverse pre-order: a cluster is complete before it is passed on) */
    for (size_t c = 0; c < ncl; c++) {
        const h2_cluster *X = &h->cl[c];
        if (X->child[0] != 0)
            continue;
        for (size_t k = 0; k < p; k++)
            M[c * p + k] = dot(h->S + X->i0 * p + k * X->n, v + X->i0, X->n);
    }
    for (size_t c = ncl - 1; c >= 1; c--) {
        const double *T = h->T + c * p * p, *m = M + c * p;
        double *mp = M + h->cl[c].parent * p;
        for (size_t k = 0; k < p; k++)
            mp[k] += dot_stride(T + k, p, m, p);
    }
    /* the far couplings, both ways (the kernel is symmetric) */
    for (size_t f = 0; f < h->nfar; f++) {
        const double *K = h->K + f * p * p;
        size_t x = h->far[f][0], yc = h->far[f][1];
        const double *mx = M + x * p, *my = M + yc * p;
        double *lx = L + x * p, *ly = L + yc * p;
        for (size_t a = 0; a < p; a++) {
            lx[a] += dot(K + a * p, my, p);
            ly[a] += dot_stride(K + a, p, mx, p);
        }
    }
    /* downward: each parent's expansion into its children */
    for (size_t c = 1; c < ncl; c++) {
        const double *T = h->T + c * p * p, *lp = L + h->cl[c].parent * p;
        double *l = L + c * p;
        for (size_t k = 0; k < p; k++)
            l[k] += dot(T + k * p, lp, p);
    }
    for (size_t c = 0; c < ncl; c++) {
        const h2_cluster *X = &h->cl[c];
        if (X->child[0] != 0)
            continue;
        const double *l = L + c * p;
        for (size_t i = X->i0; i < X->i0 + X->n; i++)
            y[i] = dot(h->U + i * p, l, p);
    }
    for (size_t b = 0; b < h->nnear; b++) {
        const h2_near *nb = &h->near[b];
        const double *B = h->B + nb->off, *vy = v + nb->j0;
        for (size_t i = 0; i < nb->ni; i++)
            y[nb->i0 + i] += dot(B + i * nb->nj, vy, nb->nj);
    }
}

int adh_h2_apply(adh_h2 *h, const double *v, double *y)
{
    /* One workspace kept for the usual lone caller; a concurrent one gets
     * its own. */
    if (pthread_mutex_trylock(&h->lock) == 0) {
        product(h, v, y, h->work);
        pthread_mutex_unlock(&h->lock);
        return 0;
    }
    double *w = malloc(2 * h->ncl * h->p * sizeof *w);
    if (!w)
        return -1;
    product(h, v, y, w);
    free(w);
    return 0;
}

size_t adh_h2_bytes(const adh_h2 *h)
{
    size_t p = h->p, ncl = h->ncl;
    size_t numbers = h->nB + h->nfar * p * p + ncl * p * p + 2 * h->n * p + 2 * ncl * p;
    return numbers * sizeof(double) + ncl * sizeof *h->cl + h->nfar * sizeof *h->far + h->nnear * sizeof *h->near;
}
