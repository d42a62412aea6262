/* The reasons the tables and reports write -- summary.tsv's stop_reason,
 * sweep.tsv's status column (cli_studyrow_fill takes the same
 * cli_tables_stop_reason), --cost's report and cost.tsv, adhere fit's
 * report and fit.tsv -- name what gets past a stop in the words each key
 * was given in, as the terminal's refusals do: a scene's key by its name,
 * file and line, a flag by the flag, a swept key by its sweep. They named
 * the flags whoever set the keys ("(-N, --spacing)" to a scene's user).
 * The CLI's sources are compiled in (the CLI is no library). */
#include "cli/advice.c"
#include "cli/fitreport.c"
#include "cli/tables.c"

#include "adhere/status.h"
#include "scene/scene.h"
#include "tap.h"

#define EDGE "the contact radius a = 1.2 um reached the grid's edge (0.9 Rmax = 1.1 um): use more nodes or a larger spacing"

static adh_run edge_run(void)
{
    adh_run r;
    adh_run_init(&r);
    r.status = ADH_EGRID;
    snprintf(r.why, sizeof r.why, "%s", EDGE);
    r.fix = ADH_FIX_NODES | ADH_FIX_SPACING;
    return r;
}

/* The reason for run r under cfg ends with want (the advice). */
static void reason_is(const adh_config *cfg, const adh_run *r, const char *want, const char *what)
{
    char buf[CLI_TABLES_REASON_LEN];
    cli_tables_stop_reason(cfg, r, buf, sizeof buf);
    size_t n = strlen(buf), w = strlen(want);
    ok(n > w && !strcmp(buf + n - w, want) && !strncmp(buf, EDGE, strlen(EDGE)), "%s: '...%s' (%s)", what, want, buf);
}

/* The summary.tsv cli_tables_summary writes for run r of cfg: its
 * stop_reason line into line. */
static void summary_reason(const adh_config *cfg, const adh_run *r, char *line, size_t len)
{
    cli_tables t = { .cfg = cfg, .spec = &cfg->spec, .run = r, .partial = 1, .note = "stopped" };
    FILE *f = tmpfile();
    line[0] = '\0';
    if (!f)
        return;
    cli_tables_summary(f, &t);
    rewind(f);
    char buf[4096];
    while (fgets(buf, sizeof buf, f))
        if (!strncmp(buf, "stop_reason\t", 12))
            snprintf(line, len, "%s", buf);
    fclose(f);
}

int main(void)
{
    char why[512];
    adh_config scene;
    adh_config_default(&scene);
    int rc = adh_scene_parse_string("[grid]\nnodes = 200\nspacing = 5nm\n", "a.scene", &scene, why, sizeof why);
    snprintf(scene.scene, sizeof scene.scene, "a.scene");   /* as adh_scene_load names it */
    ok(rc == 0, "the scene parses (%s)", rc ? why : "");
    adh_run r = edge_run();

    /* the scene's grid: its keys, file and line */
    reason_is(&scene, &r, " (nodes at a.scene:2, spacing at line 3)", "the scene's N and spacing");
    /* the same settings by flags: the flags */
    adh_config byflag;
    adh_config_default(&byflag);
    adh_config_note_origin(&byflag, "grid.nodes", 0);
    adh_config_note_origin(&byflag, "grid.spacing", 0);
    reason_is(&byflag, &r, " (-N, --spacing)", "-N and --spacing on the line");
    /* a radius swept by --sweep=R=...: the sweep, not -R */
    adh_config swept;
    adh_config_default(&swept);
    adh_config_note_origin(&swept, "sweep.R", 0);
    adh_run rr = edge_run();
    rr.fix = ADH_FIX_RADIUS;
    reason_is(&swept, &rr, " (--sweep=R)", "R swept by --sweep=R=...");

    /* a --cost run's N is one of --cost-nodes: cost.tsv's reason names
     * that (it said -N, or a scene's nodes, neither of which --cost reads);
     * the spacing it scales is the configuration's */
    char cost[CLI_TABLES_REASON_LEN];
    adh_config plain;
    adh_config_default(&plain);
    cli_tables_stop_reason_for(&plain, CLI_ADVICE_COST, &r, cost, sizeof cost);
    ok(!strcmp(cost, EDGE " (--cost-nodes, --spacing)"), "a --cost run's reason: --cost-nodes (%s)", cost);
    adh_config costsp;
    adh_config_default(&costsp);
    rc = adh_scene_parse_string("[grid]\nspacing = 5nm\n", "a.scene", &costsp, why, sizeof why);
    snprintf(costsp.scene, sizeof costsp.scene, "a.scene");
    cli_tables_stop_reason_for(&costsp, CLI_ADVICE_COST, &r, cost, sizeof cost);
    ok(rc == 0 && !strcmp(cost, EDGE " (--cost-nodes, spacing at a.scene:2)"),
       "... and the scene's spacing beside it (%s)", cost);

    /* summary.tsv's stop_reason line: the scene's words */
    char line[4096];
    summary_reason(&scene, &r, line, sizeof line);
    ok(strstr(line, EDGE " (nodes at a.scene:2, spacing at line 3)\n") && !strstr(line, "-N"),
       "summary.tsv's stop_reason names the scene's keys (%s)", line);
    /* a scene named with a tab and a newline: no control byte in the
     * table's field, the advice's name included */
    adh_config odd;
    adh_config_default(&odd);
    rc = adh_scene_parse_string("[grid]\nnodes = 200\n", "a\tb\nc.scene", &odd, why, sizeof why);
    snprintf(odd.scene, sizeof odd.scene, "a\tb\nc.scene");
    summary_reason(&odd, &r, line, sizeof line);
    size_t ctl = 0;
    for (const char *p = line; *p && *p != '\n'; p++)
        ctl += (unsigned char)*p < 0x20 && p > line + 11;
    ok(rc == 0 && strstr(line, "nodes at a b c.scene:2") && ctl == 0,
       "a scene name's tab and newline are spaces in summary.tsv's field (%s)", line);

    /* STATUS: REASON (the stderr line, events.tsv's # PARTIAL, a study's
     * runs) */
    char stopped[CLI_TABLES_STOPPED_LEN];
    cli_tables_stopped(&scene, &r, ADH_EGRID, stopped, sizeof stopped);
    ok(strstr(stopped, ": " EDGE " (nodes at a.scene:2, spacing at line 3)") && !strstr(stopped, "-N"),
       "the stop's line names the scene's keys (%s)", stopped);

    /* the fit's report: its last failed evaluation's grid advice */
    adh_fit_result res;
    memset(&res, 0, sizeof res);
    res.failed = 1;
    res.model_status = ADH_EGRID;
    snprintf(res.model_why, sizeof res.model_why, "%s", EDGE);
    res.model_fix = ADH_FIX_NODES | ADH_FIX_SPACING | ADH_FIX_TURNS;
    cli_fit_model_stop(&scene, &res, 0, stopped, sizeof stopped);
    ok(strstr(stopped, EDGE " (nodes at a.scene:2, spacing at line 3)") && !strstr(stopped, "-N"),
       "the fit's report names the scene's grid keys (%s)", stopped);
    cli_fit_model_stop(&byflag, &res, 0, stopped, sizeof stopped);
    ok(strstr(stopped, EDGE " (-N, --spacing)"), "... and a flag user's flags (%s)", stopped);

    /* a scene 1.3 KB deep in directories: summary.tsv's reason names its
     * keys with the file whole (the advice was dropped whole: its list
     * held 1200 bytes, a word 1100, and the path was cut at 1000) */
    static char deep[PATH_MAX];
    size_t d = 0;
    for (int i = 0; i < 5; i++) {
        deep[d++] = '/';
        memset(deep + d, 'k' + i, 250);
        d += 250;
    }
    snprintf(deep + d, sizeof deep - d, "/r.scene");
    adh_config far;
    adh_config_default(&far);
    rc = adh_scene_parse_string("[grid]\nnodes = 200\nspacing = 5nm\n", deep, &far, why, sizeof why);
    snprintf(far.scene, sizeof far.scene, "%s", deep);
    char want[PATH_MAX + 256], reason[CLI_TABLES_REASON_LEN];
    snprintf(want, sizeof want, EDGE " (nodes at %s:2, spacing at line 3)", deep);
    cli_tables_stop_reason(&far, &r, reason, sizeof reason);
    ok(rc == 0 && !strcmp(reason, want), "a deep scene's reason: the sentence and its advice whole (%zu bytes of %zu)",
       strlen(reason), strlen(want));
    summary_reason(&far, &r, line, sizeof line);
    ok(!strncmp(line, "stop_reason\t", 12) && !strncmp(line + 12, want, strlen(want)) && line[12 + strlen(want)] == '\n',
       "... and summary.tsv's stop_reason says it whole");

    /* where the caller's room is short the scene's name is cut in its
     * middle ("…"), the file's own name and the lines kept; never the
     * advice dropped */
    char small[600];
    cli_tables_stop_reason(&far, &r, small, sizeof small);
    const char *head = " (nodes at /kkkk", *end = "oooo/r.scene:2, spacing at line 3)";
    size_t sn = strlen(small);
    ok(!strncmp(small, EDGE, strlen(EDGE)) && !strncmp(small + strlen(EDGE), head, strlen(head)) &&
       strstr(small, "\xe2\x80\xa6") && sn > strlen(end) && !strcmp(small + sn - strlen(end), end) &&
       sn < sizeof small,
       "a short room: the path cut in its middle, the advice kept (%s)", small);
    /* a room too short for even the cut name: the list's end cut, seen */
    char tiny[sizeof EDGE + 24];
    cli_tables_stop_reason(&far, &r, tiny, sizeof tiny);
    ok(!strncmp(tiny, EDGE " (nodes at ", strlen(EDGE) + 11) && strstr(tiny, "\xe2\x80\xa6)"),
       "a tiny room: the advice begun and cut where it shows (%s)", tiny);
    /* the path cut alone: at most max bytes, its end kept, whole below max */
    char cut[64];
    cli_advice_path(deep, 40, cut, sizeof cut);
    ok(strlen(cut) == 40 && !strncmp(cut, "/kkkkkkkkkk", 11) && !strcmp(cut + 40 - 8, "/r.scene"),
       "cli_advice_path cuts a long path's middle (%s)", cut);
    cli_advice_path("a/b.scene", 40, cut, sizeof cut);
    ok(!strcmp(cut, "a/b.scene"), "... and leaves a short one whole (%s)", cut);
    return tap_done();
}
