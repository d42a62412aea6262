/* Measured curves (--data) made ready for a fit: every file's points in one
 * set, each labelled with its direction and whether it lies past its
 * segment's jump (in contact), and refused with FILE:LINE and the reason
 * when a fit could not use them. */
#ifndef ADH_SCENE_FITDATA_H
#define ADH_SCENE_FITDATA_H

#include <stddef.h>

#include "adhere/fitmodel.h"
#include "adhere/params.h"
#include "scene/measured.h"

/* The fewest points past the jumps a fit takes. */
#define ADH_FITDATA_MIN_CONTACT 5
/* A jump is a force step this many times the segment's median step. */
#define ADH_FITDATA_JUMP_RATIO 8.0

typedef struct adh_fitdata {
    adh_fit_data d;                /* points to the arrays below */
    double *x, *F;
    int *dir, *contact, *seg;
    const adh_measured **file;     /* the file of each point */
    size_t *line;                  /* and its line */
    size_t ncontact;
} adh_fitdata;

/* Gathers every file of the chain m into fd. nfree: free parameters of the
 * fit. start, offset, baseline: the start values, for the range checks
 * (positions within the model's reach, a force below the baseline, the
 * attraction within a factor 30 of the start's JKR pull-off). 0, or -1
 * with "FILE:LINE: reason" in why (nothing kept). */
int adh_fitdata_make(const adh_measured *m, size_t nfree, const adh_material *start, double offset, double baseline,
                     adh_fitdata *fd, char *why, size_t whylen);
void adh_fitdata_free(adh_fitdata *fd);

#endif
