#include "plot/rows.h"

void adh_rows_header(FILE *f)
{
    fputs("h0\tF\tdelta\thc\ta\tangle\titers\tbranch\tpath\tconverged\tstable\tF_rigid\tseconds\n", f);
}

void adh_rows_write(FILE *f, const adh_obs *o)
{
    fprintf(f, "%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%zu\t%+d\t%d\t%d\t%d\t%.17g\t%.6g\n",
            o->h0, o->F, o->delta, o->hc, o->a, o->angle, o->iters, o->branch, o->path,
            o->converged, o->stable, o->F_rigid, o->seconds);
}

void adh_rows_header_timed(FILE *f)
{
    fputs("t\tbase\t", f);
    adh_rows_header(f);
}

void adh_rows_write_timed(FILE *f, const adh_obs *o)
{
    fprintf(f, "%.17g\t%.17g\t", o->t, o->base);
    adh_rows_write(f, o);
}
