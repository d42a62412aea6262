/* The configuration by key: every key reads back what it holds, refuses
 * what it cannot hold without changing anything, and the configuration's
 * parts (one grid asked and chosen, the protocol every driver steps, a
 * sweep's runs) are what scenes and flags leave in them. */
#include <math.h>
#include <string.h>

#include "adhere/models.h"
#include "scene/config.h"
#include "scene/scene.h"
#include "tap.h"

static int set(adh_config *c, const char *key, const char *text)
{
    char why[512];
    return adh_config_set(c, key, text, why, sizeof why);
}

/* Every key's value as text sets it again to the same value: the text
 * adh_config_get writes is the one adh_config_set reads (numbers exactly). */
static void round_trip(const char *scene)
{
    static adh_config c, again;
    adh_config_default(&c);
    char why[512] = "";
    if (scene)
        ok(adh_scene_load(scene, &c, why, sizeof why) == 0, "%s loads %s", scene, why);
    int same = 1;
    const adh_config_key *k;
    for (size_t i = 0; (k = adh_config_key_at(i)); i++) {
        char text[4096], back[4096];
        again = c;
        adh_config_get(&c, k->key, text, sizeof text);
        int rc = adh_config_set(&again, k->key, text, why, sizeof why);
        adh_config_get(&again, k->key, back, sizeof back);
        /* an empty path is "not given": the one text no setter takes */
        if (!(rc == 0 && strcmp(text, back) == 0) && !(rc != 0 && text[0] == '\0')) {
            same = 0;
            printf("#   %s: '%s' read back as '%s' (%s)\n", k->key, text, back, rc ? why : "set");
        }
    }
    ok(same, "every key of %s reads back what it holds (%s)", scene ? scene : "the defaults", "get, set, get");
    /* and the run specification itself is the same */
    again = c;
    for (size_t i = 0; (k = adh_config_key_at(i)); i++) {
        char text[4096];
        adh_config_get(&c, k->key, text, sizeof text);
        if (text[0] && (k->where & ADH_KEY_RUN))
            adh_config_set(&again, k->key, text, why, sizeof why);
    }
    ok(again.spec.mat.E == c.spec.mat.E && again.spec.relax.eps == c.spec.relax.eps &&
       again.spec.proto.nturns == c.spec.proto.nturns && again.spec.proto.step == c.spec.proto.step &&
       !memcmp(again.spec.proto.turns, c.spec.proto.turns, sizeof c.spec.proto.turns) &&
       again.spec.proto.dwell == c.spec.proto.dwell && again.spec.proto.unload == c.spec.proto.unload,
       "setting every key of the run from its text gives %s's run again, to the last bit", scene ? scene : "the default");
}

/* A refused value changes nothing, and the sentence names the value. */
static void refusals(void)
{
    static adh_config c, before;
    adh_config_default(&c);
    before = c;
    const adh_config_key *k;
    int unchanged = 1, named = 1;
    for (size_t i = 0; (k = adh_config_key_at(i)); i++) {
        char why[512] = "", text[64];
        if (!strcmp(k->key, "scene.title"))
            continue;   /* any printable text is a title */
        /* a path (empty by default) takes any text but none */
        adh_config_get(&c, k->key, text, sizeof text);
        const char *bad = text[0] ? "1nm,,x" : "";
        if (adh_config_set(&c, k->key, bad, why, sizeof why) == 0) {
            printf("#   %s took '%s'\n", k->key, bad);
            named = 0;
        }
        unchanged &= memcmp(&c, &before, sizeof c) == 0;
        named &= why[0] != '\0';
    }
    ok(unchanged, "a key refusing '1nm,,x' (a path: '') leaves the whole configuration as it was");
    ok(named, "and says why, every key");
    char why[512];
    ok(adh_config_set(&c, "material.E", "5nm", why, sizeof why) != 0 && strstr(why, "'5nm' is a length"),
       "E = 5nm: %s", why);
    ok(adh_config_set(&c, "grid.growth", "1.2", why, sizeof why) != 0 && strstr(why, "1 to 1.1"), "growth 1.2: %s", why);
    ok(adh_config_set(&c, "protocol.turns", "-1nm,,-2nm", why, sizeof why) != 0 && strstr(why, "empty element"),
       "an empty element in a list: %s", why);
    ok(adh_config_set(&c, "material.sigma", "3", why, sizeof why) != 0 && strstr(why, "material.sigma"),
       "no key material.sigma: %s", why);
    ok(set(&c, "sweep.E", "1GPa,2GPa") == 0 && adh_config_set(&c, "sweep.sigma", "1", why, sizeof why) != 0 &&
       strstr(why, "both set the modulus"), "sigma and E do not go together (sigma sets E): %s", why);
}

/* Turns imply unloading; the grid asked for is kept beside the one chosen. */
static void parts(void)
{
    static adh_config c;
    adh_config_default(&c);
    ok(set(&c, "protocol.unload", "no") == 0 && set(&c, "protocol.turns", "-1nm,-2nm") == 0 && c.spec.proto.unload == 1 &&
       c.spec.proto.nturns == 2, "turns set unloading from them, as --turn and a scene's turns do");
    ok(set(&c, "protocol.turns", "none") == 0 && c.spec.proto.unload == 0 && c.spec.proto.nturns == 0,
       "turns none: loading to contact only");
    /* a soft material: the grid follows it, the grid asked for stays */
    adh_config_default(&c);
    char why[512];
    ok(set(&c, "material.E", "0.1GPa") == 0 && adh_config_grid(&c, why, sizeof why, NULL) == 0 && c.spec.grid.chosen &&
       c.spec.grid.use.graded && c.spec.grid.use.kernel == ADH_KERNEL_RING && !c.spec.grid.asked.graded &&
       c.spec.grid.asked.nodes == 1000 && isnan(c.spec.grid.asked.spacing),
       "E = 0.1 GPa: graded rings chosen (%zu), the uniform 1000 nodes asked for kept", c.spec.grid.use.nodes);
    ok(set(&c, "material.E", "0.3GPa") == 0 && adh_config_grid(&c, why, sizeof why, NULL) == 0 && !c.spec.grid.use.graded &&
       c.spec.grid.use.nodes == 1000, "back at 0.3 GPa: the paper's 1000 uniform nodes again (chosen from what was asked)");
    ok(set(&c, "grid.nodes", "300") == 0 && set(&c, "material.E", "0.1GPa") == 0 && adh_config_grid(&c, why, sizeof why, NULL) == 0 &&
       !c.spec.grid.chosen && c.spec.grid.use.nodes == 300 && !c.spec.grid.use.graded,
       "N given: the grid is the one asked for, whatever the material");
    ok(set(&c, "grid.nodes", "auto") == 0 && adh_config_grid_auto(&c.spec), "N = auto: it follows the material again");
}

/* The protocol every driver steps: the configuration's, with profile
 * positions spread along the path when the profile figure wants them. */
static void protocol(void)
{
    static adh_config c;
    adh_config_default(&c);
    set(&c, "protocol.dwell", "700");
    adh_protocol_settings ps = adh_config_protocol(&c);
    ok(ps.dwell == 700 && ps.unload && ps.nturns == 1 && ps.nprofiles == 6,
       "the default plots ask for profiles: 6 positions spread, the dwell and turns kept (%zu)", ps.nprofiles);
    double want[8];
    size_t n = adh_config_default_profiles(&c.spec.mat, &c.spec.proto, want, 6);
    ok(n == ps.nprofiles && !memcmp(want, ps.profiles, n * sizeof *want), "at adh_config_default_profiles' positions");
    ok(c.spec.proto.nprofiles == 0, "and the configuration itself still asks for none");
    ps = adh_config_protocol_for(&c, ADH_MODE_STATIC);
    ok(ps.nprofiles == 0, "the static curve's protocol has none added");
    set(&c, "output.profiles", "1nm,-1nm");
    ps = adh_config_protocol(&c);
    ok(ps.nprofiles == 2 && ps.profiles[0] == 1e-9, "positions asked are the ones stepped");
    set(&c, "output.profiles", "none");
    set(&c, "output.plots", "force");
    ok(adh_config_protocol(&c).nprofiles == 0, "no profile figure, no positions added");

    /* a sweep's run: the base's protocol, its own swept value */
    adh_config_default(&c);
    set(&c, "sweep.sigma", "1,10");
    adh_run_spec run;
    adh_config_sweep_run(&c, 1, &run);
    adh_derived d;
    adh_material_derive(&run.mat, &d);
    ok(fabs(d.sigma - 10) < 1e-9 && run.proto.nprofiles == adh_config_protocol(&c).nprofiles,
       "sweep run 2: sigma %g, the base's profile positions", d.sigma);
}

/* A study: keys swept as lists and ranges, their product in order, each
 * run the configuration with its values set, runs that differ only in
 * their turn on one drive. */
static void studies(void)
{
    static adh_config c, before;
    char why[512];
    /* a run key sets nothing outside the run's specification: a run of a
     * study is the spec with its keys set (sweep.c copies the spec alone) */
    adh_config_default(&c);
    const adh_config_key *k;
    int alone = 1;
    for (size_t i = 0; (k = adh_config_key_at(i)); i++) {
        if (!(k->where & ADH_KEY_RUN))
            continue;
        char text[4096];
        before = c;
        adh_config_get(&c, k->key, text, sizeof text);
        adh_config_set(&c, k->key, text, why, sizeof why);
        before.spec = c.spec;
        if (memcmp(&before, &c, sizeof c) != 0) {
            printf("#   %s changed more than the spec\n", k->key);
            alone = 0;
        }
    }
    ok(alone, "every run key sets the run's specification and nothing else");

    adh_config_default(&c);
    ok(set(&c, "sweep.E", "10MPa .. 10GPa, log, 13") == 0 && c.sweep.naxes == 1 && adh_config_nruns(&c) == 13,
       "E = 10MPa .. 10GPa, log, 13: 13 runs");
    const adh_sweep_axis *a = &c.sweep.axis[0];
    double mid = adh_sweep_value(a, 6, NULL, 0);
    ok(adh_sweep_value(a, 0, NULL, 0) == 1e7 && adh_sweep_value(a, 12, NULL, 0) == 1e10 &&
       fabs(mid / 316227766.01683795 - 1) < 1e-15, "its ends exact, its middle 10^8.5 Pa (%.17g)", mid);
    adh_run_spec run;
    adh_config_sweep_run(&c, 6, &run);
    ok(run.mat.E == mid, "run 7's E is that value, to the last bit");
    ok(set(&c, "sweep.turns", "-1nm .. -2nm, 3") == 0 && adh_config_nruns(&c) == 39 &&
       fabs(adh_sweep_value(&c.sweep.axis[1], 1, NULL, 0) + 1.5e-9) < 1e-24, "turns = -1nm .. -2nm, 3 (linear): the product has 39 runs");
    size_t idx[ADH_SWEEP_MAX_AXES];
    adh_sweep_index(&c.sweep, 7, idx);
    adh_config_sweep_run(&c, 7, &run);
    ok(idx[0] == 2 && idx[1] == 1 && run.proto.nturns == 1 && run.proto.turns[0] == adh_sweep_value(&c.sweep.axis[1], 1, NULL, 0) && run.proto.unload &&
       run.mat.E == adh_sweep_value(a, 2, NULL, 0), "run 8 is E's third value and the second turn: the first key varies slowest");
    char text[256];
    adh_sweep_describe(&c.sweep, 7, text, sizeof text);
    ok(!strcmp(text, "E = 3.16228e+07, turns = -1.5e-09"), "described as %s", text);
    ok(adh_sweep_drives(&c) == 13, "the runs of one E share a drive: 13 drives");
    size_t runs[ADH_MAX_TURNS];
    size_t n = adh_sweep_drive_runs(&c, 2, runs);
    adh_config_sweep_run(&c, 6, &run);
    adh_run_spec drive;
    adh_sweep_drive_spec(&c, 2, &drive);
    ok(n == 3 && runs[0] == 6 && runs[1] == 7 && runs[2] == 8 && drive.proto.nturns == 3 && drive.mat.E == run.mat.E,
       "drive 3 steps runs 7, 8, 9: their three turns, their E");
    adh_sweep_get(&c, "turns", text, sizeof text);
    before = c;
    ok(set(&before, "sweep.turns", text) == 0 && !memcmp(&before.sweep, &c.sweep, sizeof c.sweep),
       "a range reads back from its text (%s)", text);
    ok(set(&c, "sweep.turns", "none") == 0 && c.sweep.naxes == 1 && adh_config_nruns(&c) == 13, "turns = none drops the key");

    /* physical time's sweeps are studies of its keys: the speed both ways,
     * the retraction's alone, the spring */
    adh_config_default(&c);
    ok(set(&c, "material.material", "sls") == 0 && set(&c, "protocol.speed", "1nm/s") == 0 &&
       set(&c, "sweep.speed_out", "1nm/s, 1mm/s") == 0 && !strcmp(c.sweep.axis[0].key, "protocol.speed_out"),
       "[sweep] speed_out sweeps protocol.speed_out");
    adh_config_sweep_run(&c, 1, &run);
    ok(run.mode == ADH_MODE_TIME && run.time.speed_out == 1e-3 && run.time.speed_in == 1e-9,
       "run 2 retracts at 1 mm/s, approaching at the scene's 1 nm/s");
    ok(set(&c, "sweep.speed_out", "none") == 0 && set(&c, "sweep.speed", "1um/s, 2um/s") == 0 &&
       !strcmp(c.sweep.axis[0].key, "protocol.speed"), "[sweep] speed sweeps protocol.speed");
    adh_config_sweep_run(&c, 1, &run);
    ok(run.time.speed_in == 2e-6 && run.time.speed_out == 2e-6, "run 2 moves at 2 um/s both ways");
    adh_config_default(&c);
    ok(set(&c, "scene.mode", "static") == 0 && set(&c, "sweep.spring", "0.1, 40") == 0 &&
       !strcmp(c.sweep.axis[0].key, "protocol.spring"), "[sweep] spring sweeps protocol.spring");
    adh_config_sweep_run(&c, 1, &run);
    ok(run.mode == ADH_MODE_STATIC && run.time.spring == 40 && (run.time.given & ADH_TIME_MODE),
       "run 2: k = 40 N/m on the static curve, the mode as given");
    ok(set(&c, "sweep.spring", "40, 0.1, 1") == 0 && adh_sweep_drives(&c) == 1,
       "springs swept on the static curve share one drive (the curve does not depend on k)");
    adh_sweep_drive_spec(&c, 0, &run);
    adh_run_spec soft;
    adh_config_sweep_run(&c, 1, &soft);
    adh_run_spec stiff;
    adh_config_sweep_run(&c, 0, &stiff);
    ok(run.time.spring == 0.1 && adh_config_start(&run) == adh_config_start(&soft) &&
       adh_config_start(&soft) > adh_config_start(&stiff),
       "the drive is the softest spring's, from its start outside every snap-in (%g m)", adh_config_start(&run));
    adh_config_default(&c);
    set(&c, "material.material", "sls");
    ok(set(&c, "sweep.spring", "40, 0.1") == 0 && adh_sweep_drives(&c) == 2, "in physical time each spring is a run of its own");
    ok(set(&c, "sweep.spring", "0, 1") != 0, "a spring of 0 N/m is refused as a swept value");

    adh_config_default(&c);
    ok(set(&c, "sweep.nodes", "100 .. 1000, log, 4") == 0 && adh_sweep_value(&c.sweep.axis[0], 1, NULL, 0) == 215,
       "a count's range is rounded: 100, 215, 464, 1000");
    ok(adh_config_set(&c, "sweep.nodes", "100 .. 103, 10", why, sizeof why) != 0 && strstr(why, "repeat"),
       "whole numbers that repeat are refused: %s", why);
    ok(set(&c, "sweep.material.A", "1e-20J, 2e-20J") == 0 && set(&c, "sweep.sigma", "3, 30") == 0 &&
       !strcmp(c.sweep.axis[1].name, "A"), "A by its key, sigma beside it");
    adh_config_sweep_run(&c, 3, &run);   /* run 4: the second A, the second sigma (nodes' first) */
    adh_derived d;
    adh_material_derive(&run.mat, &d);
    ok(run.mat.A == 2e-20 && fabs(d.sigma - 30) < 1e-12, "sigma sets E from the run's own A (sigma %.15g)", d.sigma);
    ok(adh_config_set(&c, "sweep.E", "1GPa,2GPa", why, sizeof why) != 0 && strstr(why, "both set the modulus"),
       "E beside sigma: %s", why);
    ok(adh_config_set(&c, "sweep.A", "1e-20J, 3, x", why, sizeof why) != 0 && c.sweep.axis[1].n == 2,
       "a value the key does not take refuses the list, the study unchanged: %s", why);
    ok(adh_config_set(&c, "sweep.dir", "a, b", why, sizeof why) != 0 && strstr(why, "no key of a run"),
       "an output key is not swept: %s", why);
    ok(adh_config_set(&c, "sweep.step", "1pm .. 1nm, 1000", why, sizeof why) == 0 &&
       adh_config_set(&c, "sweep.R", "1um .. 1mm, log, 100", why, sizeof why) != 0 && strstr(why, "100000"),
       "past 100000 runs: refused (%s)", why);
}

static void say_flag(const char *key, const char *value, char *buf, size_t len, void *ctx)
{
    snprintf(buf, len, "<%s%s%s>", key, value ? "|" : "", value ? value : "");
}

/* Sentences name keys; each driver says them in its words. */
static void reword(void)
{
    char out[256];
    adh_config_reword("grid.grid = graded is not allowed with grid.kernel = paper; use grid.kernel = ring.", say_flag,
                      NULL, out, sizeof out);
    ok(!strcmp(out, "<grid.grid|graded> is not allowed with <grid.kernel|paper>; use <grid.kernel|ring>."),
       "keys and their values go to the driver's words: %s", out);
    adh_config_reword("more grid.nodes or a larger grid.spacing, grid.radiusx", say_flag, NULL, out, sizeof out);
    ok(!strcmp(out, "more <grid.nodes> or a larger <grid.spacing>, grid.radiusx"),
       "a key without a value too, and not inside another word: %s", out);
    adh_config_reword("grid.nodes", say_flag, NULL, out, 6);
    ok(strlen(out) == 5, "cut at the buffer's end");
}

/* A stand-in for the CLI's checks: R from 1 um to 1 mm runs. */
static int r_in_range(adh_config *c, void *ctx)
{
    (void)ctx;
    return c->spec.mat.R >= 1e-6 && c->spec.mat.R <= 1e-3 ? 0 : -1;
}

/* A bare number teaches (issue 28, item 2): the units a screen shows each
 * key in, and the hint that names the ones that would run. */
static void units_and_hints(void)
{
    double f = 0;
    const adh_config_key *E = adh_config_key_find("material.E"), *R = adh_config_key_find("material.R");
    const char *u = adh_config_key_unit(E, 3e8, &f);
    ok(u && !strcmp(u, "MPa") && f == 1e6, "E = 300 MPa is shown in MPa (%s, %g)", u ? u : "-", f);
    u = adh_config_key_unit(E, 5e9, &f);
    ok(u && !strcmp(u, "GPa") && f == 1e9, "E = 5 GPa in GPa (%s)", u ? u : "-");
    u = adh_config_key_unit(E, 2e4, &f);
    ok(u && !strcmp(u, "kPa"), "E = 20 kPa in kPa, the smallest (%s)", u ? u : "-");
    u = adh_config_key_unit(R, 1.5e-2, &f);
    ok(u && !strcmp(u, "mm") && f == 1e-3, "R = 1.5 cm in mm (%s)", u ? u : "-");
    u = adh_config_key_unit(R, 10e-6, &f);
    ok(u && !strcmp(u, "um") && fabs(f - 1e-6) < 1e-21, "R = 10 um in um (%s)", u ? u : "-");
    ok(!adh_config_key_unit(adh_config_key_find("material.A"), 1e-19, &f), "A has no unit but SI's J");

    static adh_config c;
    char why[512], hint[512];
    adh_config_default(&c);
    adh_config_set(&c, "material.R", "10", why, sizeof why);
    adh_config_note_given(&c, "material.R", "10", "--radius");
    ok(adh_config_unit_hint(&c, r_in_range, NULL, hint, sizeof hint) == 1 &&
       !strcmp(hint, "R = 10 m is out of range; did you mean --radius=10um?"), "-R 10: %s", hint);
    adh_config_set(&c, "material.R", "0.5", why, sizeof why);
    adh_config_note_given(&c, "material.R", "0.5", "s.scene");
    ok(adh_config_unit_hint(&c, r_in_range, NULL, hint, sizeof hint) == 1 &&
       !strcmp(hint, "R = 500 mm is out of range; did you mean R = 0.5mm in s.scene?"), "a scene's R = 0.5: %s", hint);
    adh_config_set(&c, "material.R", "5000", why, sizeof why);
    adh_config_note_given(&c, "material.R", "5000", "--radius");
    ok(adh_config_unit_hint(&c, r_in_range, NULL, hint, sizeof hint) == 0 && !hint[0],
       "5000 is out of range in every unit: no hint");
    adh_config_note_given(&c, "material.R", "5000um", "--radius");
    ok(c.ngiven == 0 && adh_config_unit_hint(&c, r_in_range, NULL, hint, sizeof hint) == 0,
       "given again with a unit, the bare value is forgotten");
    adh_config_note_given(&c, "protocol.turns", "0", "--turn");
    ok(adh_config_unit_hint(&c, r_in_range, NULL, hint, sizeof hint) == 0, "a zero is zero in any unit: no hint");
    adh_config_note_given(&c, "grid.nodes", "100", "-N");
    ok(c.ngiven == 1, "a count is no quantity: not remembered (%zu)", c.ngiven);

    const adh_config_key *k = adh_config_key_suggest("protocol", "turn");
    ok(k && !strcmp(k->key, "protocol.turns"), "[protocol] turn: turns (%s)", k ? k->key : "none");
    k = adh_config_key_suggest("protocol", "E");
    ok(k && !strcmp(k->key, "material.E"), "[protocol] E: material.E (%s)", k ? k->key : "none");
    k = adh_config_key_suggest("material", "z");
    ok(!k, "[material] z: nothing near enough for a one-letter name (%s)", k ? k->key : "none");
    ok(adh_config_name_distance("Turns", "turn") == 1, "names compare without case");
}

int main(void)
{
    round_trip(NULL);
    round_trip("fig5");
    round_trip("fig7");
    refusals();
    parts();
    protocol();
    studies();
    reword();
    units_and_hints();
    return tap_done();
}
