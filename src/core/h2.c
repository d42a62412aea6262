#include "adhere/h2.h"
#include "adhere/status.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

/* An AVX2 copy of the product where GCC or clang builds for x86-64. AVX2
 * has no fused multiply-add (that is FMA's), so neither copy rounds
 * a * b + c once, and the copies agree to the last bit. */
#if defined(__GNUC__) && defined(__x86_64__)
#define H2_AVX2 1
#else
#define H2_AVX2 0
#endif

typedef struct h2_cluster {
    size_t i0, n;        /* cells i0 .. i0 + n - 1 */
    double lo, hi;       /* their interval */
    size_t parent;       /* the root is its own parent */
    size_t child[2];     /* 0: a leaf (the root is nobody's child) */
    size_t pi0;          /* with cw, a leaf's first cell in the padded
                            order: each leaf's cells, then zeros to a whole
                            vector */
    size_t uoff;         /* a leaf's basis rows: U + uoff, n x P */
    size_t toff;         /* its transfer: T + toff, P x P */
} h2_cluster;

/* A block of the near field: rows of one leaf against the columns of
 * neighbouring leaves, merged into one span where they are contiguous. */
typedef struct h2_near {
    size_t i0, ni;       /* rows */
    size_t j0, nj;       /* columns */
    size_t off;          /* the block in the near store, row-major */
    size_t ld;           /* its rows' stride: nj, or with cw the columns'
                            padded width (zeros in the pads) */
    size_t pi0, pj0;     /* with cw: the rows' and columns' padded starts */
    size_t own;          /* with cw: the rows' own leaf's padded width when
                            it is among the columns (first), else 0 */
} h2_near;

struct adh_h2 {
    size_t n;
    size_t p;            /* Chebyshev nodes per cluster */
    size_t P;            /* p rounded up to whole vectors: the stride of every
                            per-cluster row, zero past p */
    size_t ncl;
    h2_cluster *cl;      /* pre-order: a parent before its children */
    double *node;        /* ncl x p Chebyshev nodes (assembly only) */
    double *U;           /* n x P: L_a(x_i), the basis of cell i's leaf
                            (shared by equal leaves: h2_cluster.uoff) */
    double *S;           /* n x P: row i is column i's quadrature of its leaf's
                            L_b; U itself where cw is set */
    double *cw;          /* n column weights (adh_h2_problem.cw), or NULL */
    double *T;           /* ncl x P x P: T_c[b][b'] = L^parent_b'(node_c[b])
                            (shared by equal clusters: h2_cluster.toff) */
    size_t nU, nT;       /* the numbers U and T hold */
    size_t nfar;
    size_t (*far)[2];    /* cluster pairs (x before y), both directions */
    double *K;           /* nfar x P x P: k(node_x[a], node_y[b]) */
    size_t nnear;
    h2_near *near;       /* with cw, a pair of leaves once: its block serves
                            both (the columns past the rows' own, mirrored) */
    double *B;           /* the near field's exact entries */
    size_t nB;
    size_t npad;         /* with cw, the cells in the padded order */
    double *work;        /* moments and local expansions (2 ncl P), then
                            with cw the weighted sources and the mirrored
                            blocks' sums, padded (2 npad) */
    size_t nwork;
    int avx2;            /* the product's AVX2 copy runs here */
    pthread_mutex_t lock;
};

adh_h2_settings adh_h2_settings_default(void)
{
    /* Measured (docs/grids-and-operators.md), ring kernel,
     * uniform and graded grids: 12 nodes keep the product within ~5e-12 of
     * the dense one (14: ~1e-13, 10: ~1e-10), a thousandth of the 1e-8 its
     * tests ask (test_operator.c), and fill whole vectors (14 are padded to 16): the
     * product is ~20 % faster than with 14. eta a little above 1 makes
     * leaves two apart far on a uniform grid, whose halved sizes differ by a
     * cell (20 % less memory than eta = 1). Leaves of at most 32 cells
     * balance the near field against the couplings. */
    return (adh_h2_settings){ .order = 12, .eta = 1.2, .leaf = 32 };
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
        /* split at the edge nearest the middle of the interval: on a
         * uniform grid that halves the count; where rings grow it keeps a
         * cluster's width below its distance from the clusters left of it
         * (halving the count leaves a wide ring far out in a leaf whose
         * width exceeds its distance from all of them: no far block) */
        const double *e = b->pb->edge;
        double mid = 0.5 * (e[i0] + e[i0 + n]);
        size_t lo = i0 + 1, hi = i0 + n - 1;
        while (lo < hi) {
            size_t c = lo + (hi - lo) / 2;
            if (e[c] < mid)
                lo = c + 1;
            else
                hi = c;
        }
        if (lo > i0 + 1 && mid - e[lo - 1] < e[lo] - mid)
            lo--;
        size_t m = lo - i0;
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
        return ADH_SUCCESS;
    size_t c = *cap ? *cap : 64;
    while (c < need)
        c *= 2;
    void *x = realloc(*a, c * size);
    if (!x)
        return ADH_ENOMEM;
    *a = x;
    *cap = c;
    return ADH_SUCCESS;
}

static void add_far(h2_build *b, size_t x, size_t y)
{
    adh_h2 *h = b->h;
    size_t p = h->p, P = h->P;
    if (grow((void **)&h->far, &b->cap_far, h->nfar + 1, sizeof *h->far) != ADH_SUCCESS ||
        grow((void **)&h->K, &b->cap_K, h->nfar + 1, P * P * sizeof *h->K) != ADH_SUCCESS) {
        b->fail = 1;
        return;
    }
    double *K = h->K + h->nfar * P * P;
    memset(K, 0, P * P * sizeof *K);
    const double *nx = h->node + x * p, *ny = h->node + y * p;
    for (size_t a = 0; a < p; a++)
        for (size_t c = 0; c < p; c++)
            K[a * P + c] = b->pb->kernel(b->pb->ctx, nx[a], ny[c]);
    h->far[h->nfar][0] = x;
    h->far[h->nfar][1] = y;
    h->nfar++;
}

/* Recorded here, merged and filled by near_fill once all are known. */
static void add_near(h2_build *b, size_t x, size_t y)
{
    adh_h2 *h = b->h;
    const h2_cluster *X = &h->cl[x], *Y = &h->cl[y];
    if (grow((void **)&h->near, &b->cap_near, h->nnear + 1, sizeof *h->near) != ADH_SUCCESS) {
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
 * (one longer row product instead of several short ones). */
static void near_merge(adh_h2 *h)
{
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
    h2_near *shrunk = realloc(h->near, h->nnear * sizeof *h->near);
    if (shrunk)
        h->near = shrunk;
}

/* With cw, each leaf's cells padded with zeros to whole vectors, and each
 * block's columns so: its products have no short tails. pad[i] is cell
 * i's padded place. */
static void near_pad(adh_h2 *h, size_t *pad)
{
    h->npad = 0;
    for (size_t c = 0; c < h->ncl; c++) { /* pre-order: leaves left to right */
        h2_cluster *X = &h->cl[c];
        if (X->child[0] != 0)
            continue;
        X->pi0 = h->npad;
        for (size_t i = 0; i < X->n; i++)
            pad[X->i0 + i] = X->pi0 + i;
        h->npad += (X->n + 3) / 4 * 4;
    }
    for (size_t b = 0; b < h->nnear; b++) {
        h2_near *nb = &h->near[b];
        nb->pi0 = pad[nb->i0];
        nb->pj0 = pad[nb->j0];
        nb->ld = (pad[nb->j0 + nb->nj - 1] + 4) / 4 * 4 - nb->pj0;
        nb->own = nb->j0 == nb->i0 ? (nb->ni + 3) / 4 * 4 : 0;
    }
}

/* The near blocks' exact entries (and with cw their padded places). */
static int near_fill(adh_h2 *h, const adh_h2_problem *pb)
{
    if (h->nnear == 0) /* never: every leaf is near itself */
        return ADH_SUCCESS;
    near_merge(h);
    size_t *pad = malloc(h->n * sizeof *pad);
    if (!pad)
        return ADH_ENOMEM;
    for (size_t b = 0; b < h->nnear; b++)
        h->near[b].ld = h->near[b].nj;
    if (h->cw)
        near_pad(h, pad);
    h->nB = 0;
    for (size_t b = 0; b < h->nnear; b++) {
        h->near[b].off = h->nB;
        h->nB += (h->cw ? (h->near[b].ni + 3) / 4 * 4 : h->near[b].ni) * h->near[b].ld;
    }
    h->B = calloc(h->nB, sizeof *h->B);
    if (!h->B) {
        free(pad);
        return ADH_ENOMEM;
    }
    for (size_t b = 0; b < h->nnear; b++) {
        const h2_near *nb = &h->near[b];
        double *B = h->B + nb->off;
        pb->block(pb->ctx, nb->i0, nb->ni, nb->j0, nb->nj, B);
        if (nb->ld == nb->nj)
            continue;
        /* spread in place, last entry first: a place is never below its own */
        for (size_t k = nb->ni * nb->nj; k-- > 0;) {
            size_t i = k / nb->nj, j = k % nb->nj, to = i * nb->ld + pad[nb->j0 + j] - nb->pj0;
            double e = B[k];
            B[k] = 0;
            B[to] = e;
        }
    }
    free(pad);
    return ADH_SUCCESS;
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
        if (!b->h->cw)
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

/* Each cluster's Chebyshev nodes, its transfer into its parent and its
 * leaf's basis rows (and S), on its own interval: without cw. */
static int bases_fill(adh_h2 *h, const adh_h2_problem *pb, double *lp)
{
    size_t p = h->p, P = h->P;
    for (size_t c = 0; c < h->ncl; c++) {
        cheb_nodes(h->cl[c].lo, h->cl[c].hi, p, h->node + c * p);
        h->cl[c].toff = c * P * P;
        h->cl[c].uoff = h->cl[c].i0 * P;
    }
    /* The parent's polynomials are exactly those of degree < p on each
     * child: interpolating them there is exact, so the bases nest. */
    for (size_t c = 1; c < h->ncl; c++)
        for (size_t k = 0; k < p; k++)
            lagrange(h->node + h->cl[c].parent * p, p, h->node[c * p + k], h->T + (c * P + k) * P);
    for (size_t c = 0; c < h->ncl; c++) {
        const h2_cluster *X = &h->cl[c];
        if (X->child[0] != 0)
            continue;
        const double *nd = h->node + c * p;
        for (size_t i = X->i0; i < X->i0 + X->n; i++) {
            lagrange(nd, p, pb->x[i], h->U + i * P);
            for (size_t q = 0; q < pb->nq; q++) {
                lagrange(nd, p, pb->qt[i * pb->nq + q], lp);
                for (size_t k = 0; k < p; k++)
                    h->S[i * P + k] += pb->qw[i * pb->nq + q] * lp[k];
            }
        }
    }
    h->nU = h->n * P;
    h->nT = h->ncl * P * P;
    return 1;
}

/* Cells all of one width (to 1e-12) */
static int equal_cells(const adh_h2_problem *pb)
{
    double w = pb->edge[1] - pb->edge[0];
    for (size_t i = 1; i < pb->n; i++)
        if (fabs(pb->edge[i + 1] - pb->edge[i] - w) > 1e-12 * w)
            return 0;
    return 1;
}

/* With cw the transfers and bases are kept with their transposes (the
 * product runs both ways as sums of rows: h2_product.h) in pools: the
 * offset of the len numbers at m appended to pool (*used so far), or with
 * share of an equal copy among those kept (kept[0 .. *nkept): offset,
 * length). */
typedef struct h2_pool {
    double *a;
    size_t used, *kept, nkept;
    int share;
} h2_pool;

static size_t pool_keep(h2_pool *pl, const double *m, size_t len)
{
    for (size_t k = 0; k < pl->nkept && pl->share; k++)
        if (pl->kept[2 * k + 1] == len && memcmp(pl->a + pl->kept[2 * k], m, len * sizeof *m) == 0)
            return pl->kept[2 * k];
    memcpy(pl->a + pl->used, m, len * sizeof *m);
    pl->kept[2 * pl->nkept] = pl->used;
    pl->kept[2 * pl->nkept + 1] = len;
    pl->nkept++;
    pl->used += len;
    return pl->used - len;
}

/* m[P r .. P r + P) for r < rows, then its transpose after it: P rows of
 * ld (a multiple of 4, zeros past rows). */
static void transpose_after(double *m, size_t rows, size_t P, size_t ld)
{
    double *t = m + rows * P;
    memset(t, 0, P * ld * sizeof *t);
    for (size_t r = 0; r < rows; r++)
        for (size_t k = 0; k < P; k++)
            t[k * ld + r] = m[r * P + k];
}

/* The bases with cw: nodes in cell units from each cluster's first edge
 * where the cells are all of one width (share), else in length. Shared,
 * clusters of the same size and place in their parent get the same
 * numbers, kept once (a uniform grid has a few), so the product reads them
 * from the first level cache; a point at its cell's middle to 1e-12 is
 * taken there. The nodes in length, for the couplings, follow. */
static int bases_cw(adh_h2 *h, const adh_h2_problem *pb, int share)
{
    size_t p = h->p, P = h->P, n = h->n, maxn = 0;
    double w = (pb->edge[n] - pb->edge[0]) / (double)n;
    for (size_t c = 0; c < h->ncl; c++)
        maxn = h->cl[c].n > maxn ? h->cl[c].n : maxn;
    size_t mlen = (maxn + 3) / 4 * 4 * 2 * P + 2 * P * P;
    double *ln = malloc((h->ncl * p + mlen) * sizeof *ln), *m = ln + h->ncl * p;
    size_t *kept = malloc(4 * (h->ncl + 1) * sizeof *kept);
    h2_pool pT = { h->T, 0, kept, 0, share }, pU = { h->U, 0, kept + 2 * (h->ncl + 1), 0, share };
    if (!ln || !kept) {
        free(ln), free(kept);
        return 0;
    }
    for (size_t c = 0; c < h->ncl; c++) {
        const h2_cluster *X = &h->cl[c];
        cheb_nodes(share ? 0 : X->lo, share ? (double)X->n : X->hi, p, ln + c * p);
        for (size_t k = 0; k < p; k++)
            h->node[c * p + k] = share ? pb->edge[X->i0] + ln[c * p + k] * w : ln[c * p + k];
    }
    for (size_t c = 1; c < h->ncl; c++) {
        h2_cluster *X = &h->cl[c];
        double off = share ? (double)(X->i0 - h->cl[X->parent].i0) : 0;
        memset(m, 0, P * P * sizeof *m);
        for (size_t k = 0; k < p; k++)
            lagrange(ln + X->parent * p, p, off + ln[c * p + k], m + k * P);
        transpose_after(m, P, P, P);
        X->toff = pool_keep(&pT, m, 2 * P * P);
    }
    for (size_t c = 0; c < h->ncl; c++) {
        h2_cluster *X = &h->cl[c];
        if (X->child[0] != 0)
            continue;
        memset(m, 0, X->n * P * sizeof *m);
        for (size_t i = 0; i < X->n; i++) {
            double e = pb->edge[X->i0 + i], f = (pb->x[X->i0 + i] - e) / (pb->edge[X->i0 + i + 1] - e);
            double t = share ? (double)i + (fabs(f - 0.5) < 1e-12 ? 0.5 : f) : pb->x[X->i0 + i];
            lagrange(ln + c * p, p, t, m + i * P);
        }
        transpose_after(m, X->n, P, (X->n + 3) / 4 * 4);
        X->uoff = pool_keep(&pU, m, X->n * P + P * ((X->n + 3) / 4 * 4));
    }
    free(ln), free(kept);
    double *U = realloc(h->U, pU.used * sizeof *U), *T = realloc(h->T, pT.used * sizeof *T);
    if (U)
        h->U = h->S = U;
    if (T)
        h->T = T;
    h->nU = pU.used;
    h->nT = pT.used;
    return 1;
}

static void h2_release(adh_h2 *h)
{
    if (h->S != h->U)
        free(h->S);
    free(h->cl), free(h->node), free(h->T), free(h->U), free(h->cw), free(h->work);
    free(h->far), free(h->K), free(h->near), free(h->B);
    free(h);
}

adh_h2 *adh_h2_alloc(const adh_h2_problem *pb, const adh_h2_settings *s)
{
    size_t n = pb->n, p = (size_t)s->order;
    if (n == 0 || s->order < 2 || s->leaf < 1 || !(s->eta > 0) || (pb->nq == 0 && !pb->cw))
        return NULL;
    for (size_t i = 0; i < n; i++)
        if (!(pb->edge[i] < pb->edge[i + 1]))
            return NULL;
    adh_h2 *h = calloc(1, sizeof *h);
    if (!h)
        return NULL;
    h->n = n;
    h->p = p;
    h->P = (p + 3) / 4 * 4;
#if H2_AVX2
    h->avx2 = !s->portable && __builtin_cpu_supports("avx2");
#endif
    size_t P = h->P;
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
    /* with cw the transposes too, each leaf's padded to whole vectors */
    h->T = calloc((pb->cw ? 2 : 1) * ncl * P * P, sizeof *h->T);
    h->U = calloc(pb->cw ? 2 * n * P + 3 * ncl * P : n * P, sizeof *h->U);
    h->S = pb->cw ? h->U : calloc(n * P, sizeof *h->S);
    h->cw = pb->cw ? malloc(n * sizeof *h->cw) : NULL;
    if (!h->node || !h->T || !h->U || !h->S || (pb->cw && !h->cw))
        goto fail;
    if (pb->cw)
        memcpy(h->cw, pb->cw, n * sizeof *h->cw);
    if (!(pb->cw ? bases_cw(h, pb, equal_cells(pb)) : bases_fill(h, pb, lp)))
        goto fail;
    build_self(&b, 0);
    if (b.fail || near_fill(h, pb) != ADH_SUCCESS)
        goto fail;
    h->nwork = 2 * ncl * P + 2 * h->npad;
    h->work = malloc(h->nwork * sizeof *h->work);
    if (!h->work)
        goto fail;
    free(h->node);
    h->node = NULL;
    /* the couplings grew by doubling: hand the slack back */
    if (h->nfar > 0) {
        double *K = realloc(h->K, h->nfar * P * P * sizeof *h->K);
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
    h2_release(h);
    return NULL;
}

void adh_h2_free(adh_h2 *h)
{
    if (!h)
        return;
    pthread_mutex_destroy(&h->lock);
    h2_release(h);
}

/* The product, in 4-lane vectors of doubles (GCC's vector extension),
 * built twice: as pairs of SSE2 halves for any x86-64, and whole for AVX2,
 * chosen by the CPU at assembly (h->avx2). Elsewhere, the portable copy
 * alone. V_HSUM4 is four V_HSUMs in one vector, each its own additions. */
typedef double h2_v2 __attribute__((vector_size(2 * sizeof(double)), aligned(sizeof(double)), may_alias));
typedef double h2_v4 __attribute__((vector_size(4 * sizeof(double)), aligned(sizeof(double)), may_alias));
typedef struct h2_pair {
    h2_v2 lo, hi;
} h2_pair;

static inline h2_pair pair_load(const double *a)
{
    return (h2_pair){ *(const h2_v2 *)a, *(const h2_v2 *)(a + 2) };
}

static inline void pair_store(double *a, h2_pair v)
{
    *(h2_v2 *)a = v.lo;
    *(h2_v2 *)(a + 2) = v.hi;
}

static inline h2_pair pair_add(h2_pair a, h2_pair b)
{
    return (h2_pair){ a.lo + b.lo, a.hi + b.hi };
}

static inline h2_pair pair_mul(h2_pair a, h2_pair b)
{
    return (h2_pair){ a.lo * b.lo, a.hi * b.hi };
}

static inline h2_pair pair_scale(double s, h2_pair a)
{
    return (h2_pair){ s * a.lo, s * a.hi };
}

#define H2_INLINE static inline __attribute__((always_inline))
#define H2_NAME(x) x##_base
#define H2_TARGET
#define V h2_pair
#define V_LOAD(a) pair_load(a)
#define V_STORE(a, v) pair_store(a, v)
#define V_ZERO ((h2_pair){ { 0, 0 }, { 0, 0 } })
#define V_ADD(a, b) pair_add(a, b)
#define V_MUL(a, b) pair_mul(a, b)
#define V_SCALE(s, a) pair_scale(s, a)
#define V_HSUM(s) (((s).lo[0] + (s).lo[1]) + ((s).hi[0] + (s).hi[1]))
#define V_HSUM4(a, b, c, d) ((h2_pair){ { V_HSUM(a), V_HSUM(b) }, { V_HSUM(c), V_HSUM(d) } })
#include "h2_product.h"
#undef H2_NAME
#undef H2_TARGET
#undef V
#undef V_LOAD
#undef V_STORE
#undef V_ZERO
#undef V_ADD
#undef V_MUL
#undef V_SCALE
#undef V_HSUM
#undef V_HSUM4

#if H2_AVX2
typedef long long h2_i4 __attribute__((vector_size(4 * sizeof(long long))));
#if defined(__clang__)
#define H2_SHUFFLE(a, b, i, j, k, l) __builtin_shufflevector(a, b, i, j, k, l)
#else
#define H2_SHUFFLE(a, b, i, j, k, l) __builtin_shuffle(a, b, (h2_i4){ i, j, k, l })
#endif

/* V_HSUM of a, b, c and d, one vector, by two transpositions: lane k adds
 * (s0 + s1) + (s2 + s3) of the k-th, as V_HSUM does */
__attribute__((target("avx2"))) static inline h2_v4 hsum4_avx2(h2_v4 a, h2_v4 b, h2_v4 c, h2_v4 d)
{
    h2_v4 ab = H2_SHUFFLE(a, b, 0, 4, 2, 6) + H2_SHUFFLE(a, b, 1, 5, 3, 7);
    h2_v4 cd = H2_SHUFFLE(c, d, 0, 4, 2, 6) + H2_SHUFFLE(c, d, 1, 5, 3, 7);
    return H2_SHUFFLE(ab, cd, 0, 1, 4, 5) + H2_SHUFFLE(ab, cd, 2, 3, 6, 7);
}

#define H2_NAME(x) x##_avx2
#define H2_TARGET __attribute__((target("avx2")))
#define V h2_v4
#define V_LOAD(a) (*(const h2_v4 *)(a))
#define V_STORE(a, v) (*(h2_v4 *)(a) = (v))
#define V_ZERO ((h2_v4){ 0, 0, 0, 0 })
#define V_ADD(a, b) ((a) + (b))
#define V_MUL(a, b) ((a) * (b))
#define V_SCALE(s, a) ((s) * (a))
#define V_HSUM(s) (((s)[0] + (s)[1]) + ((s)[2] + (s)[3]))
#define V_HSUM4(a, b, c, d) hsum4_avx2(a, b, c, d)
#include "h2_product.h"
#endif

static void product(const adh_h2 *h, const double *v, double *y, double *work)
{
#if H2_AVX2
    if (h->avx2) {
        product_avx2(h, v, y, work);
        return;
    }
#endif
    product_base(h, v, y, work);
}

int adh_h2_apply(adh_h2 *h, const double *v, double *y)
{
    /* One workspace kept for the usual lone caller; a concurrent one gets
     * its own. */
    if (pthread_mutex_trylock(&h->lock) == 0) {
        product(h, v, y, h->work);
        pthread_mutex_unlock(&h->lock);
        return ADH_SUCCESS;
    }
    double *w = malloc(h->nwork * sizeof *w);
    if (!w)
        return ADH_ENOMEM;
    product(h, v, y, w);
    free(w);
    return ADH_SUCCESS;
}

size_t adh_h2_bytes(const adh_h2 *h)
{
    size_t P = h->P, ncl = h->ncl;
    size_t numbers = h->nB + h->nfar * P * P + h->nT + h->nU + (h->S != h->U ? h->n * P : 0) + (h->cw ? h->n : 0) +
                     h->nwork;
    return numbers * sizeof(double) + ncl * sizeof *h->cl + h->nfar * sizeof *h->far + h->nnear * sizeof *h->near;
}
