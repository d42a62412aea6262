/* The screen's start check keeps its grid and kernel (tui/sim.c compiled
 * here, its session's kernel count read): a standard linear solid's start
 * is checked at every edit, twice (the edit, then the grid's warning),
 * and on the kernel of the run's grid; before, each check built that
 * kernel again (1.8 s an edit at N = 3000). Now one kernel a grid: an edit
 * that leaves the grid builds none, one that changes it builds one, the
 * curve's first step takes the check's kernel, and the check borrows the
 * curve's. Its verdicts are a fresh check's (adh_config_start_check, which
 * builds its own kernel every time). */
#include <string.h>

#include "tui/sim.c"   /* the screen's session, as the program links it */

#include "adhere/status.h"
#include "tap.h"

static int set(adh_config *c, const char *key, const char *text)
{
    char why[512];
    return adh_config_set(c, key, text, why, sizeof why);
}

/* The fresh check's verdict on the screen's configuration. */
static int fresh(const tui_sim *s)
{
    char why[1024];
    unsigned fix;
    return adh_config_start_check(&s->cfg, 0, why, sizeof why, &fix);
}

/* An edit on the screen, as :set makes it: 0 taken, -1 refused. */
static int edit(tui_sim *s, const char *key, const char *text)
{
    char why[1024];
    return tui_sim_set_key(s, key, text, why, sizeof why);
}

/* Steps the curve (f) until the step is done. */
static int step(tui_sim *s)
{
    char why[1024];
    if (tui_sim_begin(s, +1, why, sizeof why) != 0)
        return -1;
    tui_work w;
    while ((w = tui_sim_work(s, 64, why, sizeof why)) == TUI_WORK_BUSY)
        ;
    return w == TUI_WORK_STEPPED ? 0 : -1;
}

int main(void)
{
    adh_config c;
    adh_config_default(&c);
    /* a solid in physical time on 200 uniform nodes 5 nm apart, from 20 nm */
    if (set(&c, "material.material", "sls") || set(&c, "grid.nodes", "200") || set(&c, "grid.spacing", "5nm") ||
        set(&c, "protocol.start", "20nm")) {
        ok(0, "the solid's configuration is taken");
        return tap_done();
    }
    tui_sim s;
    char why[1024] = "";
    ok(tui_sim_init(&s, &c, why, sizeof why) == 0, "the screen opens on it (%s)", why);
    ok(tui_sim_kernels_built(&s) == 1, "opening checks the start twice on one kernel (%zu built)",
       tui_sim_kernels_built(&s));

    ok(edit(&s, "material.tau", "2ms") == 0 && edit(&s, "material.Einf", "2GPa") == 0 &&
       edit(&s, "protocol.start", "25nm") == 0 && edit(&s, "protocol.speed", "2um/s") == 0,
       "four edits of the solid, the start and the drive are taken");
    ok(tui_sim_kernels_built(&s) == 1, "and build no kernel: the grid is the same (%zu built; 10 when each check built its own)",
       tui_sim_kernels_built(&s));
    ok(fresh(&s) == ADH_SUCCESS, "a fresh check takes that start too");

    ok(edit(&s, "protocol.start", "0.4nm") == -1 && fresh(&s) == ADH_SUCCESS,
       "a start inside the snap-in is refused (the start before it kept, which a fresh check takes)");
    adh_config bad = s.cfg;
    ok(set(&bad, "protocol.start", "0.4nm") == 0, "the same start set on a copy");
    unsigned fix;
    ok(adh_config_start_check(&bad, 0, why, sizeof why, &fix) == ADH_EINVAL && (fix & ADH_FIX_START),
       "and a fresh check refuses it too, naming the start");
    ok(tui_sim_kernels_built(&s) == 1, "the refusal built none either (%zu built)", tui_sim_kernels_built(&s));

    ok(edit(&s, "grid.nodes", "250") == 0, "N = 250 is taken");
    ok(tui_sim_kernels_built(&s) == 2, "a new grid: one kernel for its two checks (%zu built)",
       tui_sim_kernels_built(&s));

    ok(step(&s) == 0, "the curve's first step in physical time");
    ok(tui_sim_kernels_built(&s) == 2 && s.sk != NULL && !s.startk.k,
       "takes the start check's kernel: none built (%zu built)", tui_sim_kernels_built(&s));
    /* (each edit before its ok: the message's count is read after it) */
    int rc = edit(&s, "material.tau", "3ms");
    ok(rc == 0 && tui_sim_kernels_built(&s) == 2 && !s.startk.k && s.sk,
       "an edit after it checks on the curve's kernel, lent: none built (%zu built)", tui_sim_kernels_built(&s));
    rc = step(&s);
    ok(rc == 0 && tui_sim_kernels_built(&s) == 2, "and the curve steps on (the same grid: %zu built)",
       tui_sim_kernels_built(&s));

    rc = edit(&s, "grid.nodes", "200");
    ok(rc == 0 && tui_sim_kernels_built(&s) == 3, "back to N = 200: its kernel again, one (%zu built)",
       tui_sim_kernels_built(&s));
    rc = edit(&s, "protocol.start", "auto");
    ok(rc == 0 && !s.startk.k && tui_sim_kernels_built(&s) == 3,
       "the automatic start has nothing to check: no kernel is held for it (%zu built)", tui_sim_kernels_built(&s));
    tui_sim_free(&s);
    return tap_done();
}
