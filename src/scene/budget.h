/* What a run may hold in memory, decided before anything is allocated,
 * for every grid (automatic or given with -N, --spacing, --grid), whose
 * operator the configuration chose to fit (a dense N x N matrix up to
 * ADH_GRID_MAX_NODES nodes, H^2 past it unless --operator says otherwise):
 * a run whose estimate exceeds the memory this process may use is
 * refused with the estimate and what to use instead. The coefficients are
 * measured (docs/security.md, "Memory"). */
#ifndef ADH_SCENE_BUDGET_H
#define ADH_SCENE_BUDGET_H

#include <stddef.h>

#include "scene/config.h"

/* Bytes this process may still allocate: the least of the machine's
 * available memory (/proc/meminfo's MemAvailable, else sysconf), the
 * address-space and data limits (ulimit -v, -d) less what is in use, and
 * the cgroup's memory limit. */
double adh_budget_machine_bytes(void);

/* Estimated peak bytes of a run with `solvers` static curves solved at
 * once (0 for a relaxation alone; a sweep in mode static solves one per
 * thread): the kernel as its grid's operator holds it, each static
 * solver's matrices, and the program's own. */
double adh_budget_bytes(const adh_run_spec *run, unsigned solvers);

/* The static solvers `jobs` runs of run's mode hold at once, for
 * adh_budget_bytes: one a job in static mode and in physical time (where a
 * viscoelastic path holds its preconditioner and the landing its LU), none
 * for a relaxation but its static reference's (reference 1). A single run
 * and a study count alike. */
unsigned adh_budget_solvers(const adh_run_spec *run, unsigned jobs, int reference);

/* Whether need bytes fit, with `threads` threads computing: need within
 * the memory there is, and need and the address space the threads map
 * beside it (the BLAS's working buffer each) within ulimit -v and -d. *have
 * the bytes there are for need; *address_bound (may be NULL) 1 when the
 * address-space limit is the lesser. */
int adh_budget_fits(double need, unsigned threads, double *have, int *address_bound);

/* The estimate against the machine (the operator is the grid's:
 * adh_config_choose_grid gives a large dense one up for H^2). 0, or -1
 * with a sentence naming the estimate, the memory there is, and what to
 * use instead (keys: adh_config_reword). */
int adh_budget_check(const adh_run_spec *run, unsigned solvers, char *why, size_t whylen);

/* adh_budget_check for a run on `threads` threads at once (a sweep's); the
 * above counts max(solvers, 1). */
int adh_budget_check_threads(const adh_run_spec *run, unsigned solvers, unsigned threads, char *why,
                             size_t whylen);

/* The steps of run's protocol: loading to the deepest turn and unloading
 * from each back to the start (the plan's count, give or take a step). */
double adh_budget_path_steps(const adh_run_spec *run);

/* An interactive path keeps every state for undo: run's whole protocol
 * kept so (kept steps already are), beside the run's own estimate, against
 * the memory there is. 0, or -1 with a sentence naming the path, what it
 * would keep and what to change (keys: adh_config_reword). */
int adh_budget_check_path(const adh_run_spec *run, size_t kept, char *why, size_t whylen);

#endif
