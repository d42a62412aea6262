/* The H^2 product, written once over a 4-lane vector V and included by
 * h2.c once per instruction set (see there): H2_NAME(x) names this copy's
 * functions, H2_TARGET is its target attribute, and V_LOAD, V_STORE,
 * V_ZERO, V_ADD, V_MUL, V_SCALE and V_HSUM its operations. Every copy does
 * the same additions in the same order, lane by lane, so all give the same
 * numbers. Every per-cluster row is P long (a multiple of 4), zero past p,
 * so its loops are whole vectors. Private to h2.c. */

/* x[0 .. P) += sum over r of a[r] row_r[0 .. P), row r at rows + r P,
 * added row by row; eight lanes at a time are held in registers across
 * the rows (a store and reload per row would chain them). */
H2_TARGET static inline void H2_NAME(gemtv)(double *x, const double *a, const double *rows, size_t nr, size_t P)
{
    size_t k = 0;
    for (; k + 8 <= P; k += 8) {
        V s0 = V_LOAD(x + k), s1 = V_LOAD(x + k + 4);
        for (size_t r = 0; r < nr; r++) {
            s0 = V_ADD(s0, V_SCALE(a[r], V_LOAD(rows + r * P + k)));
            s1 = V_ADD(s1, V_SCALE(a[r], V_LOAD(rows + r * P + k + 4)));
        }
        V_STORE(x + k, s0);
        V_STORE(x + k + 4, s1);
    }
    if (k < P) {
        V s0 = V_LOAD(x + k);
        for (size_t r = 0; r < nr; r++)
            s0 = V_ADD(s0, V_SCALE(a[r], V_LOAD(rows + r * P + k)));
        V_STORE(x + k, s0);
    }
}

H2_TARGET static inline double H2_NAME(vdot)(const double *a, const double *b, size_t P)
{
    V s = V_MUL(V_LOAD(a), V_LOAD(b));
    for (size_t k = 4; k < P; k += 4)
        s = V_ADD(s, V_MUL(V_LOAD(a + k), V_LOAD(b + k)));
    return V_HSUM(s);
}

/* a[0 .. n) . b[0 .. n) for any n: two vector sums, a short product being
 * bound by the latency of its chain of additions */
H2_TARGET static inline double H2_NAME(dot)(const double *a, const double *b, size_t n)
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

H2_TARGET static void H2_NAME(product)(const adh_h2 *h, const double *v, double *y, double *work)
{
    size_t P = h->P, p = h->p, ncl = h->ncl;
    double *M = work, *L = work + ncl * P;
    memset(work, 0, 2 * ncl * P * sizeof *work);
    /* upward: the leaves' moments, then each child's into its parent
     * (reverse pre-order: a cluster is complete before it is passed on) */
    for (size_t c = 0; c < ncl; c++) {
        const h2_cluster *X = &h->cl[c];
        if (X->child[0] != 0)
            continue;
        H2_NAME(gemtv)(M + c * P, v + X->i0, h->S + X->i0 * P, X->n, P);
    }
    for (size_t c = ncl - 1; c >= 1; c--) {
        const double *T = h->T + c * P * P, *m = M + c * P;
        double *mp = M + h->cl[c].parent * P;
        H2_NAME(gemtv)(mp, m, T, p, P);
    }
    /* the far couplings, both ways in one pass (the kernel is symmetric) */
    for (size_t f = 0; f < h->nfar; f++) {
        const double *K = h->K + f * P * P;
        size_t x = h->far[f][0], yc = h->far[f][1];
        const double *mx = M + x * P, *my = M + yc * P;
        double *lx = L + x * P, *ly = L + yc * P;
        for (size_t a = 0; a < p; a++)
            lx[a] += H2_NAME(vdot)(K + a * P, my, P);
        H2_NAME(gemtv)(ly, mx, K, p, P);
    }
    /* downward: each parent's expansion into its children */
    for (size_t c = 1; c < ncl; c++) {
        const double *T = h->T + c * P * P, *lp = L + h->cl[c].parent * P;
        double *l = L + c * P;
        for (size_t k = 0; k < p; k++)
            l[k] += H2_NAME(vdot)(T + k * P, lp, P);
    }
    for (size_t c = 0; c < ncl; c++) {
        const h2_cluster *X = &h->cl[c];
        if (X->child[0] != 0)
            continue;
        const double *l = L + c * P;
        for (size_t i = X->i0; i < X->i0 + X->n; i++)
            y[i] = H2_NAME(vdot)(h->U + i * P, l, P);
    }
    for (size_t b = 0; b < h->nnear; b++) {
        const h2_near *nb = &h->near[b];
        const double *B = h->B + nb->off, *vy = v + nb->j0;
        for (size_t i = 0; i < nb->ni; i++)
            y[nb->i0 + i] += H2_NAME(dot)(B + i * nb->nj, vy, nb->nj);
    }
}
