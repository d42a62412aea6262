/* A measured force-position curve (--data FILE) to hold against the model:
 * two columns, the drive position and the force, in nm and nN unless a
 * header line names the units ("h0[um] F[uN]", "position (nm)  force (pN)").
 * '#' starts a comment; columns are separated by blanks, tabs or a comma. */
#ifndef ADH_SCENE_MEASURED_H
#define ADH_SCENE_MEASURED_H

#include <stddef.h>

typedef struct adh_measured {
    size_t n;
    double *h0;   /* m */
    double *F;    /* N */
} adh_measured;

/* Reads path into m (SI units). 0, or -1 with "PATH:LINE: what is wrong and
 * what is wanted" in why (nothing allocated). */
int adh_measured_load(const char *path, adh_measured *m, char *why, size_t whylen);
void adh_measured_free(adh_measured *m);

#endif
