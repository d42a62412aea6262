/* The H^2 product, written once over a 4-lane vector V and included by
 * h2.c once per instruction set (see there): H2_NAME(x) names this copy's
 * functions, H2_TARGET is its target attribute, H2_INLINE how its helpers
 * are inlined, and V_LOAD, V_STORE, V_ZERO, V_ADD, V_MUL, V_SCALE, V_HSUM
 * and V_HSUM4 its operations. Every copy does the same additions in the
 * same order, lane by lane, so all give the same numbers. Every
 * per-cluster row is P long (a multiple of 4), zero past p, so its loops
 * are whole vectors; with column weights (h->cw) the cells and the near
 * blocks are padded so too. Private to h2.c. */

/* x[0 .. m) += sum over r of a[r] row_r[0 .. m) (= where set: from zero),
 * row r at rows + r stride, m a multiple of 4, added row by row in every
 * lane. Lanes are held in registers across the rows (a store and reload
 * per row would chain them): 32 at a time, then 12, then 4, so that
 * enough chains of additions run side by side (two left the adder waiting
 * on their latency). Each lane's sum is the same however they are
 * grouped. */
H2_TARGET H2_INLINE void H2_NAME(axpyv)(double *x, int set, const double *a, const double *rows, size_t nr,
                                        size_t m, size_t stride)
{
#define H2_START(k) (set ? V_ZERO : V_LOAD(x + (k)))
    size_t k = 0;
    for (; k + 32 <= m; k += 32) {
        V s0 = H2_START(k), s1 = H2_START(k + 4), s2 = H2_START(k + 8), s3 = H2_START(k + 12);
        V s4 = H2_START(k + 16), s5 = H2_START(k + 20), s6 = H2_START(k + 24), s7 = H2_START(k + 28);
        for (size_t r = 0; r < nr; r++) {
            const double *row = rows + r * stride + k;
            s0 = V_ADD(s0, V_SCALE(a[r], V_LOAD(row)));
            s1 = V_ADD(s1, V_SCALE(a[r], V_LOAD(row + 4)));
            s2 = V_ADD(s2, V_SCALE(a[r], V_LOAD(row + 8)));
            s3 = V_ADD(s3, V_SCALE(a[r], V_LOAD(row + 12)));
            s4 = V_ADD(s4, V_SCALE(a[r], V_LOAD(row + 16)));
            s5 = V_ADD(s5, V_SCALE(a[r], V_LOAD(row + 20)));
            s6 = V_ADD(s6, V_SCALE(a[r], V_LOAD(row + 24)));
            s7 = V_ADD(s7, V_SCALE(a[r], V_LOAD(row + 28)));
        }
        V_STORE(x + k, s0), V_STORE(x + k + 4, s1), V_STORE(x + k + 8, s2), V_STORE(x + k + 12, s3);
        V_STORE(x + k + 16, s4), V_STORE(x + k + 20, s5), V_STORE(x + k + 24, s6), V_STORE(x + k + 28, s7);
    }
    for (; k + 12 <= m; k += 12) {
        V s0 = H2_START(k), s1 = H2_START(k + 4), s2 = H2_START(k + 8);
        for (size_t r = 0; r < nr; r++) {
            const double *row = rows + r * stride + k;
            s0 = V_ADD(s0, V_SCALE(a[r], V_LOAD(row)));
            s1 = V_ADD(s1, V_SCALE(a[r], V_LOAD(row + 4)));
            s2 = V_ADD(s2, V_SCALE(a[r], V_LOAD(row + 8)));
        }
        V_STORE(x + k, s0), V_STORE(x + k + 4, s1), V_STORE(x + k + 8, s2);
    }
    for (; k < m; k += 4) {
        V s0 = H2_START(k);
        for (size_t r = 0; r < nr; r++)
            s0 = V_ADD(s0, V_SCALE(a[r], V_LOAD(rows + r * stride + k)));
        V_STORE(x + k, s0);
    }
#undef H2_START
}

H2_TARGET H2_INLINE double H2_NAME(vdot)(const double *a, const double *b, size_t P)
{
    V s = V_MUL(V_LOAD(a), V_LOAD(b));
    for (size_t k = 4; k < P; k += 4)
        s = V_ADD(s, V_MUL(V_LOAD(a + k), V_LOAD(b + k)));
    return V_HSUM(s);
}

/* H2_NAME(vdot) of the rows a, a + P, a + 2P, a + 3P with b, each summed
 * in vdot's order: four chains side by side, the four sums one vector. */
H2_TARGET H2_INLINE V H2_NAME(vdot4)(const double *a, const double *b, size_t P)
{
    V b0 = V_LOAD(b);
    V s0 = V_MUL(V_LOAD(a), b0), s1 = V_MUL(V_LOAD(a + P), b0);
    V s2 = V_MUL(V_LOAD(a + 2 * P), b0), s3 = V_MUL(V_LOAD(a + 3 * P), b0);
    for (size_t k = 4; k < P; k += 4) {
        V bk = V_LOAD(b + k);
        s0 = V_ADD(s0, V_MUL(V_LOAD(a + k), bk));
        s1 = V_ADD(s1, V_MUL(V_LOAD(a + P + k), bk));
        s2 = V_ADD(s2, V_MUL(V_LOAD(a + 2 * P + k), bk));
        s3 = V_ADD(s3, V_MUL(V_LOAD(a + 3 * P + k), bk));
    }
    return V_HSUM4(s0, s1, s2, s3);
}

/* x[0 .. m) (+)= the m rows at a, P apart, each dotted with b: by fours */
H2_TARGET H2_INLINE void H2_NAME(vdots)(double *x, int add, const double *a, const double *b, size_t m, size_t P)
{
    size_t i = 0;
    for (; i + 4 <= m; i += 4) {
        V d = H2_NAME(vdot4)(a + i * P, b, P);
        if (add)
            d = V_ADD(V_LOAD(x + i), d);
        V_STORE(x + i, d);
    }
    for (; i < m; i++)
        x[i] = add ? x[i] + H2_NAME(vdot)(a + i * P, b, P) : H2_NAME(vdot)(a + i * P, b, P);
}

/* a[0 .. n) . b[0 .. n) for any n: two vector sums, a short product being
 * bound by the latency of its chain of additions */
H2_TARGET H2_INLINE double H2_NAME(dot)(const double *a, const double *b, size_t n)
{
    V s0 = V_ZERO, s1 = V_ZERO;
    size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        s0 = V_ADD(s0, V_MUL(V_LOAD(a + i), V_LOAD(b + i)));
        s1 = V_ADD(s1, V_MUL(V_LOAD(a + i + 4), V_LOAD(b + i + 4)));
    }
    if (i + 4 <= n) {
        s0 = V_ADD(s0, V_MUL(V_LOAD(a + i), V_LOAD(b + i)));
        i += 4;
    }
    double t = V_HSUM(V_ADD(s0, s1));
    for (; i < n; i++)
        t += a[i] * b[i];
    return t;
}

/* The rows a, a + ld, a + 2 ld, a + 3 ld dotted with b, n a multiple of
 * 4: four of H2_NAME(dot)'s sums, one vector. Named accumulators, not
 * arrays: an array of vectors is kept in memory. */
H2_TARGET H2_INLINE V H2_NAME(dot4v)(const double *a, size_t ld, const double *b, size_t n)
{
    const double *a1 = a + ld, *a2 = a1 + ld, *a3 = a2 + ld;
    V p0 = V_ZERO, q0 = V_ZERO, p1 = V_ZERO, q1 = V_ZERO, p2 = V_ZERO, q2 = V_ZERO, p3 = V_ZERO, q3 = V_ZERO;
    size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        V b0 = V_LOAD(b + i), b1 = V_LOAD(b + i + 4);
        p0 = V_ADD(p0, V_MUL(V_LOAD(a + i), b0));
        q0 = V_ADD(q0, V_MUL(V_LOAD(a + i + 4), b1));
        p1 = V_ADD(p1, V_MUL(V_LOAD(a1 + i), b0));
        q1 = V_ADD(q1, V_MUL(V_LOAD(a1 + i + 4), b1));
        p2 = V_ADD(p2, V_MUL(V_LOAD(a2 + i), b0));
        q2 = V_ADD(q2, V_MUL(V_LOAD(a2 + i + 4), b1));
        p3 = V_ADD(p3, V_MUL(V_LOAD(a3 + i), b0));
        q3 = V_ADD(q3, V_MUL(V_LOAD(a3 + i + 4), b1));
    }
    if (i < n) {
        V b0 = V_LOAD(b + i);
        p0 = V_ADD(p0, V_MUL(V_LOAD(a + i), b0));
        p1 = V_ADD(p1, V_MUL(V_LOAD(a1 + i), b0));
        p2 = V_ADD(p2, V_MUL(V_LOAD(a2 + i), b0));
        p3 = V_ADD(p3, V_MUL(V_LOAD(a3 + i), b0));
    }
    return V_HSUM4(V_ADD(p0, q0), V_ADD(p1, q1), V_ADD(p2, q2), V_ADD(p3, q3));
}

/* out[0 .. 4) = the rows a, a + n, a + 2n, a + 3n dotted with b, each
 * summed as H2_NAME(dot) sums it, the same additions in the same order:
 * dot4v's over the whole vectors (its lane k is V_HSUM of the k-th row's
 * two chains, as dot's), then the last n mod 4 one at a time. */
H2_TARGET H2_INLINE void H2_NAME(dot4)(const double *a, const double *b, size_t n, double *out)
{
    size_t n4 = n / 4 * 4;
    V_STORE(out, H2_NAME(dot4v)(a, n, b, n4));
    for (size_t i = n4; i < n; i++) {
        out[0] += a[i] * b[i];
        out[1] += a[n + i] * b[i];
        out[2] += a[2 * n + i] * b[i];
        out[3] += a[3 * n + i] * b[i];
    }
}

/* y += the near field's product, each block's rows dotted with v */
H2_TARGET static void H2_NAME(near)(const adh_h2 *h, const double *v, double *y)
{
    for (size_t b = 0; b < h->nnear; b++) {
        const h2_near *nb = &h->near[b];
        const double *B = h->B + nb->off, *vy = v + nb->j0;
        size_t i = 0;
        for (; i + 4 <= nb->ni; i += 4) {
            double d[4];
            H2_NAME(dot4)(B + i * nb->nj, vy, nb->nj, d);
            for (size_t r = 0; r < 4; r++)
                y[nb->i0 + i + r] += d[r];
        }
        for (; i < nb->ni; i++)
            y[nb->i0 + i] += H2_NAME(dot)(B + i * nb->nj, vy, nb->nj);
    }
}

/* yt += the near field's product with column weights (h->cw): v (weighted
 * already), yt and the blocks' rows and columns padded (h2_near), so every
 * product is of whole vectors. A block's columns past its rows' own leaf
 * are a pair of leaves held once: they add their transpose too, the block
 * read again from the first level cache (one pass doing both was slower:
 * each column's sum then waits on the last four rows' store). */
H2_TARGET static void H2_NAME(near_sym)(const adh_h2 *h, const double *v, double *yt)
{
    for (size_t b = 0; b < h->nnear; b++) {
        const h2_near *nb = &h->near[b];
        const double *B = h->B + nb->off, *vy = v + nb->pj0;
        for (size_t i = 0; i < nb->ni; i += 4) {
            double *t = yt + nb->pi0 + i;
            V_STORE(t, V_ADD(V_LOAD(t), H2_NAME(dot4v)(B + i * nb->ld, nb->ld, vy, nb->ld)));
        }
        if (nb->own < nb->ld)
            H2_NAME(axpyv)(yt + nb->pj0 + nb->own, 0, v + nb->pi0, B + nb->own, nb->ni, nb->ld - nb->own, nb->ld);
    }
}

H2_TARGET static void H2_NAME(product)(const adh_h2 *h, const double *v, double *y, double *work)
{
    size_t P = h->P, p = h->p, ncl = h->ncl;
    double *M = work, *L = work + ncl * P, *vp = L + ncl * P, *yt = vp + h->npad;
    memset(work, 0, 2 * ncl * P * sizeof *work);
    /* with column weights, the weighted sources in the padded order (the
     * matrix left is symmetric), zeros in the pads; yt is set by the
     * leaves' expansions (below) */
    for (size_t c = 0; c < ncl && h->cw; c++) {
        const h2_cluster *X = &h->cl[c];
        size_t i = 0;
        for (; i < X->n && X->child[0] == 0; i++)
            vp[X->pi0 + i] = h->cw[X->i0 + i] * v[X->i0 + i];
        for (; i % 4 && X->child[0] == 0; i++)
            vp[X->pi0 + i] = 0;
    }
    /* upward: the leaves' moments, then each child's into its parent
     * (reverse pre-order: a cluster is complete before it is passed on) */
    for (size_t c = 0; c < ncl; c++) {
        const h2_cluster *X = &h->cl[c];
        if (X->child[0] != 0)
            continue;
        if (h->cw)
            H2_NAME(axpyv)(M + c * P, 0, vp + X->pi0, h->U + X->uoff, X->n, P, P);
        else
            H2_NAME(axpyv)(M + c * P, 0, v + X->i0, h->S + X->i0 * P, X->n, P, P);
    }
    for (size_t c = ncl - 1; c >= 1; c--) {
        const double *T = h->T + h->cl[c].toff, *m = M + c * P;
        double *mp = M + h->cl[c].parent * P;
        H2_NAME(axpyv)(mp, 0, m, T, p, P, P);
    }
    /* the far couplings, both ways in one pass (the kernel is symmetric) */
    for (size_t f = 0; f < h->nfar; f++) {
        const double *K = h->K + f * P * P;
        size_t x = h->far[f][0], yc = h->far[f][1];
        const double *mx = M + x * P, *my = M + yc * P;
        double *lx = L + x * P, *ly = L + yc * P;
        H2_NAME(vdots)(lx, 1, K, my, p, P);
        H2_NAME(axpyv)(ly, 0, mx, K, p, P, P);
    }
    /* downward: each parent's expansion into its children */
    for (size_t c = 1; c < ncl; c++) {
        const double *T = h->T + h->cl[c].toff, *lp = L + h->cl[c].parent * P;
        double *l = L + c * P;
        if (h->cw) /* the transpose's rows */
            H2_NAME(axpyv)(l, 0, lp, T + P * P, p, P, P);
        else
            H2_NAME(vdots)(l, 1, T, lp, p, P);
    }
    if (!h->cw) {
        for (size_t c = 0; c < ncl; c++) {
            const h2_cluster *X = &h->cl[c];
            if (X->child[0] == 0)
                H2_NAME(vdots)(y + X->i0, 0, h->U + X->uoff, L + c * P, X->n, P);
        }
        H2_NAME(near)(h, v, y);
        return;
    }
    /* with cw, into yt: the leaves' expansions as sums of the bases'
     * transposed rows, then the near field */
    for (size_t c = 0; c < ncl; c++) {
        const h2_cluster *X = &h->cl[c];
        size_t np = (X->n + 3) / 4 * 4;
        if (X->child[0] == 0)
            H2_NAME(axpyv)(yt + X->pi0, 1, L + c * P, h->U + X->uoff + X->n * P, p, np, np);
    }
    H2_NAME(near_sym)(h, vp, yt);
    for (size_t c = 0; c < ncl; c++) {
        const h2_cluster *X = &h->cl[c];
        for (size_t i = 0; i < X->n && X->child[0] == 0; i++)
            y[X->i0 + i] = yt[X->pi0 + i];
    }
}
