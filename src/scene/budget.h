/* What a run may hold in memory, decided before anything is allocated,
 * for every grid (automatic or given with -N, --spacing, --grid): the
 * kernel's operator is chosen to fit (a dense N x N matrix up to
 * ADH_GRID_MAX_NODES nodes, H^2 past it unless --operator says otherwise),
 * and a run whose estimate exceeds the memory this process may use is
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

/* The nodes (uniform) or rings (graded) of cfg's grid. */
size_t adh_budget_nodes(const adh_config *cfg);

/* Estimated peak bytes of a run of cfg with `solvers` static curves solved
 * at once (0 for a relaxation alone; a sweep in mode static solves one per
 * thread): the kernel as cfg->storage holds it, each static solver's
 * matrices, and the program's own. */
double adh_budget_bytes(const adh_config *cfg, unsigned solvers);

/* The operator for cfg's grid: past ADH_GRID_MAX_NODES nodes a dense
 * kernel gives way to H^2 (O(N) memory, and faster there) unless the
 * operator was given. */
void adh_budget_operator(adh_config *cfg);

/* adh_budget_operator, then the estimate against the machine. 0, or -1
 * with a sentence naming the estimate, the memory there is, and what to
 * use instead. */
int adh_budget_check(adh_config *cfg, unsigned solvers, char *why, size_t whylen);

#endif
