/* A measured force-position curve (--data FILE) to hold against the model:
 * two columns, the drive position and the force, in nm and nN unless a
 * header line names the units ("h0[um] F[uN]", "position (nm)  force (pN)").
 * '#' starts a comment; columns are separated by blanks, tabs or a comma. */
#ifndef ADH_SCENE_MEASURED_H
#define ADH_SCENE_MEASURED_H

#include <stddef.h>

/* A measured curve is refused past these (drawn, a million points already
 * take gnuplot seconds). */
#define ADH_MEASURED_MAX_POINTS 1000000
#define ADH_MEASURED_MAX_BYTES (64 << 20)

typedef struct adh_measured {
    size_t n;
    double *h0;   /* m */
    double *F;    /* N */
} adh_measured;

/* Reads path into m (SI units). 0, or -1 with "PATH:LINE: what is wrong and
 * what is wanted" in why (nothing allocated): a line that is not two
 * numbers, a number out of a double's range, a NUL byte, a line over 4094
 * characters, more than ADH_MEASURED_MAX_POINTS points or
 * ADH_MEASURED_MAX_BYTES bytes. */
int adh_measured_load(const char *path, adh_measured *m, char *why, size_t whylen);
void adh_measured_free(adh_measured *m);

#endif
