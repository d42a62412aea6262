#include "cli/kcache.h"

#include <pthread.h>
#include <stdlib.h>

#include "adhere/status.h"
#include "util/ready.h"

typedef struct entry {
    adh_run_spec spec;       /* a run that builds this grid */
    adh_grid *grid;
    adh_kernel *kernel;
    int building;            /* a thread builds it now: the others wait */
    size_t refs;
    unsigned long used;      /* when it was last handed out */
} entry;

struct cli_kcache {
    pthread_mutex_t lock;
    pthread_cond_t built;
    entry *e;
    size_t n, cap, keep, nbuilt;
    unsigned long clock;
};

cli_kcache *cli_kcache_new(size_t keep)
{
    cli_kcache *c = calloc(1, sizeof *c);
    if (!c)
        return NULL;
    pthread_mutex_init(&c->lock, NULL);
    pthread_cond_init(&c->built, NULL);
    c->keep = keep ? keep : 1;
    return c;
}

void cli_kcache_free(cli_kcache *c)
{
    if (!c)
        return;
    for (size_t i = 0; i < c->n; i++) {
        adh_kernel_free(c->e[i].kernel);
        adh_grid_free(c->e[i].grid);
    }
    free(c->e);
    pthread_cond_destroy(&c->built);
    pthread_mutex_destroy(&c->lock);
    free(c);
}

size_t cli_kcache_built(const cli_kcache *c)
{
    return c->nbuilt;
}

/* Kernels no run uses, past keep, go: the least recently used first. */
static void trim(cli_kcache *c)
{
    for (;;) {
        size_t idle = 0, old = c->n;
        for (size_t i = 0; i < c->n; i++)
            if (!c->e[i].refs && !c->e[i].building) {
                idle++;
                if (old == c->n || c->e[i].used < c->e[old].used)
                    old = i;
            }
        if (idle <= c->keep || old == c->n)
            return;
        adh_kernel_free(c->e[old].kernel);
        adh_grid_free(c->e[old].grid);
        c->e[old] = c->e[--c->n];
    }
}

/* The entry for s, waiting while another thread builds it; NULL when
 * there is none yet. Under the lock. */
static entry *find(cli_kcache *c, const adh_run_spec *s)
{
    for (;;) {
        entry *e = NULL;
        for (size_t i = 0; i < c->n && !e; i++)
            if (adh_config_same_grid(&c->e[i].spec, s))
                e = &c->e[i];
        if (!e || !e->building)
            return e;
        pthread_cond_wait(&c->built, &c->lock);
    }
}

int cli_kcache_get(cli_kcache *c, const adh_run_spec *s, const adh_grid **g, const adh_kernel **k)
{
    pthread_mutex_lock(&c->lock);
    entry *e = find(c, s);
    if (e) {
        e->refs++;
        e->used = ++c->clock;
        *g = e->grid, *k = e->kernel;
        pthread_mutex_unlock(&c->lock);
        return ADH_SUCCESS;
    }
    if (c->n == c->cap) {
        size_t cap = c->cap ? 2 * c->cap : 8;
        entry *grown = realloc(c->e, cap * sizeof *grown);
        if (!grown) {
            pthread_mutex_unlock(&c->lock);
            return ADH_ENOMEM;
        }
        c->e = grown, c->cap = cap;
    }
    size_t at = c->n++;
    c->e[at] = (entry){ .spec = *s, .building = 1 };
    pthread_mutex_unlock(&c->lock);
    /* built outside the lock: a large kernel takes seconds, others may run meanwhile */
    int st = ADH_ENOMEM;
    adh_ready_phase("kernel");
    adh_grid *grid = adh_config_grid_alloc(s);
    adh_kernel *kern = grid ? adh_config_kernel_alloc(s, grid, &st) : NULL;
    pthread_mutex_lock(&c->lock);
    /* the array may have moved: find the entry being built for s again */
    for (at = 0; at < c->n && !(c->e[at].building && adh_config_same_grid(&c->e[at].spec, s)); at++)
        ;
    entry *mine = &c->e[at];
    if (!kern) {
        adh_grid_free(grid);
        *mine = c->e[--c->n];
    } else {
        mine->grid = grid, mine->kernel = kern;
        mine->building = 0;
        mine->refs = 1;
        mine->used = ++c->clock;
        c->nbuilt++;
        *g = grid, *k = kern;
        st = ADH_SUCCESS;
    }
    pthread_cond_broadcast(&c->built);
    trim(c);
    pthread_mutex_unlock(&c->lock);
    return st;
}

void cli_kcache_put(cli_kcache *c, const adh_kernel *k)
{
    if (!k)
        return;
    pthread_mutex_lock(&c->lock);
    for (size_t i = 0; i < c->n; i++)
        if (c->e[i].kernel == k && c->e[i].refs) {
            c->e[i].refs--;
            break;
        }
    trim(c);
    pthread_mutex_unlock(&c->lock);
}
