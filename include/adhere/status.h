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
    ADH_EINTR = 7,       /* the caller's cancel flag was raised: stopped on request */
    ADH_ESING = 8        /* a matrix is singular as held (an exactly zero pivot) */
};

/* What a refusal asks to change, as bits of the `unsigned *fix` a check
 * fills beside its sentence (NULL: not wanted). The core's sentence names
 * quantities ("use more nodes or a larger spacing"), never a flag; each
 * driver adds its own words for the bits: flags in the CLI, fields and
 * keys in the TUI, keys in a scene. 0: no setting to name (the sentence
 * says what is allowed). */
enum adh_fix {
    ADH_FIX_TURNS = 1 << 0,        /* the turning points */
    ADH_FIX_RADIUS = 1 << 1,       /* the effective radius R */
    ADH_FIX_STEP = 1 << 2,         /* the drive step d */
    ADH_FIX_START = 1 << 9,        /* the first drive position */
    ADH_FIX_NODES = 1 << 3,        /* the number of grid nodes N */
    ADH_FIX_SPACING = 1 << 4,      /* the grid spacing */
    ADH_FIX_GRID_RADIUS = 1 << 5,  /* a graded grid's outer radius */
    ADH_FIX_FINE_BAND = 1 << 6,    /* a graded grid's fine band */
    ADH_FIX_FORCE = 1 << 7,        /* run a grid coarser than the resolved limit anyway (marked) */
    ADH_FIX_MODE = 1 << 8,         /* another step rule: the relaxation instead of the static curve */
    ADH_FIX_TIME_TOL = 1 << 10     /* the time integration's tolerance */
};

/* A short, constant, human description of a status code. */
const char *adh_strerror(int status);

#endif
