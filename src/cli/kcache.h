/* The kernels of a study's runs, shared read-only between its threads: one
 * for each distinct grid (adh_config_same_grid), built when a run first
 * needs it, kept while a run uses it and, past the cache's size, freed
 * when none does (the least recently used first). A study whose runs share
 * one grid builds one kernel, as a sweep always did. */
#ifndef ADH_CLI_KCACHE_H
#define ADH_CLI_KCACHE_H

#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "scene/config.h"

typedef struct cli_kcache cli_kcache;

/* A cache that keeps up to keep kernels no run uses. NULL: out of memory. */
cli_kcache *cli_kcache_new(size_t keep);
void cli_kcache_free(cli_kcache *c);

/* The grid and kernel of run spec s (built now, or shared): 0, or an adh
 * status (ADH_EINTR: the cancel flag came while building; ADH_ENOMEM).
 * Each successful get is paired with a put. */
int cli_kcache_get(cli_kcache *c, const adh_run_spec *s, const adh_grid **g, const adh_kernel **k);
void cli_kcache_put(cli_kcache *c, const adh_kernel *k);
/* Kernels built so far. */
size_t cli_kcache_built(const cli_kcache *c);

#endif
