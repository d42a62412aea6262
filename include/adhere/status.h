/* Status codes shared by every core module, GSL style: 0 is success,
 * ADH_CONTINUE means "not finished, call again" and is not an error. */
#ifndef ADHERE_STATUS_H
#define ADHERE_STATUS_H

enum adh_status {
    ADH_SUCCESS = 0,
    ADH_CONTINUE = -2,   /* iterate again: not converged / protocol not finished */
    ADH_EINVAL = 1,      /* a parameter outside its allowed range */
    ADH_ENOMEM = 2,      /* allocation failed */
    ADH_EMAXITER = 3,    /* iteration cap reached before convergence */
    ADH_ENAN = 4,        /* a NaN or infinity appeared in the solution */
    ADH_EGRID = 5,       /* the grid is too short or too coarse for the state */
    ADH_ESTALL = 6,      /* continuation could not make progress */
    ADH_EINTR = 7        /* the caller's cancel flag was raised: stopped on request */
};

/* A short, constant, human description of a status code. */
const char *adh_strerror(int status);

#endif
