/* One equilibrium at a given h0 by the static curve's corrector alone
 * (adhere/static.h's adh_static_solve_at): the Newton-Krylov iteration of
 * static_newton.c with its preconditioner, on a problem that may change
 * from one call to the next (its compliance and extra gap), h0 held by
 * the bordering row. A caller whose every solve is a new static problem
 * (a viscoelastic time step, adhere/visco.h) reuses the solver's
 * preconditioner and workspace without tracing a curve. */
#include "static.h"

#include <string.h>

#include "adhere/status.h"

int adh_static_solve_at(adh_static *w, double c, const double *e, const double *v, double h0, double tol,
                        const adh_state **x)
{
    size_t n = w->n;
    if (!(c > 0) || !(tol >= 0))
        return ADH_EINVAL;
    w->c2E = c;
    w->m.E = 2.0 / c;
    static_shape(w, e);
    if (tol > 0)
        w->s.tol = tol;
    memcpy(w->trial->u, v, n * sizeof *v);
    w->trial->h0 = h0;
    memcpy(w->nw.upred, v, n * sizeof *v);
    w->nw.h0pred = h0;
    /* a new attempt: a preconditioner set in an earlier one may be
     * refreshed when the Krylov solve slows */
    w->nw.attempt++;
    static_row row = { .kind = STATIC_ROW_PLANE, .nu = w->nw.zero, .nh = 1.0 };
    size_t its = 0;
    int rc = static_correct(w, &row, &its);
    if (x)
        *x = w->trial;
    return rc;
}
