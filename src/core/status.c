#include "adhere/status.h"

const char *adh_strerror(int status)
{
    switch (status) {
    case ADH_SUCCESS: return "success";
    case ADH_CONTINUE: return "not finished";
    case ADH_EINVAL: return "invalid parameter";
    case ADH_ENOMEM: return "out of memory";
    case ADH_EMAXITER: return "iteration cap reached before convergence";
    case ADH_ENAN: return "the solution is no longer finite (NaN or infinity)";
    case ADH_EGRID: return "the grid is too short or too coarse for this state";
    case ADH_ESTALL: return "continuation could not make progress";
    case ADH_EINTR: return "stopped on request";
    case ADH_ESING: return "a matrix is singular";
    default: return "unknown status";
    }
}
