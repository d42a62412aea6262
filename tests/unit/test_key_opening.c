/* adh_config_key_opening against the core's own sentences: each check that
 * opens its refusal with a setting's quantity and value (params.c,
 * protocol.c, drive.c, grid.c, relax.c, rings.c, visco_params.c) is made
 * to refuse a value a scene gave, and the sentence must come back opened
 * with the key and the value as typed, which a driver then says in its
 * words (the flag, or the scene's key and line). A sentence the table does
 * not know, a core reword, fails here. And what must stay the core's: a
 * key nobody set, a value the core derived that no key holds. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/drive.h"
#include "adhere/grid.h"
#include "adhere/params.h"
#include "adhere/protocol.h"
#include "adhere/relax.h"
#include "adhere/rule_visco.h"
#include "adhere/status.h"
#include "adhere/visco.h"
#include "scene/config.h"
#include "tap.h"

/* The first refusal of run s's checks, as a driver meets them. */
static void core_sentence(const adh_run_spec *s, char *msg, size_t len)
{
    adh_visco_rule_settings vs;
    adh_config_visco(s, &vs);
    msg[0] = '\0';
    if (adh_material_validate(&s->mat, msg, len) != ADH_SUCCESS ||
        adh_relax_settings_validate(&s->relax, msg, len) != ADH_SUCCESS ||
        adh_relax_max_iter_check((long)s->relax.max_iter, msg, len) != ADH_SUCCESS ||
        adh_protocol_dwell_check((long)s->proto.dwell, msg, len) != ADH_SUCCESS ||
        adh_grid_nodes_check((long)s->grid.use.nodes, msg, len) != ADH_SUCCESS ||
        adh_sls_validate(&vs.sls, msg, len) != ADH_SUCCESS || adh_visco_drive_validate(&vs.drive, msg, len) != ADH_SUCCESS ||
        adh_config_grid_check(s, msg, len) != 0)
        return;
    adh_grid uniform = adh_drive_uniform_grid(s->grid.use.nodes, adh_config_spacing(s));
    adh_grid *g = s->grid.use.graded ? adh_config_grid_alloc(s) : &uniform;
    if (!g)
        return;
    adh_drive_check(&s->mat, &s->relax, &s->proto, adh_config_grid_use(s), g, msg, len, NULL);
    if (g != &uniform)
        adh_grid_free(g);
}

/* Keys set as a scene sets them, line 4 and on: "key=text;key=text". */
static int scene_sets(adh_config *c, const char *keys)
{
    char buf[256], why[512];
    snprintf(buf, sizeof buf, "%s", keys);
    int line = 4;
    for (char *save, *kv = strtok_r(buf, ";", &save); kv; kv = strtok_r(NULL, ";", &save)) {
        char *eq = strchr(kv, '=');
        *eq = '\0';
        if (adh_config_set(c, kv, eq + 1, why, sizeof why) != 0) {
            printf("# %s: %s\n", kv, why);
            return -1;
        }
        adh_config_note_origin(c, kv, line++);
    }
    return 0;
}

/* A value past what a setter takes (the core refuses it again, as a
 * sweep's run or a future setter could give it): put in the spec itself. */
static void put(adh_config *c, const char *key, double v)
{
    adh_run_spec *s = &c->spec;
    if (!strcmp(key, "grid.nodes")) {
        s->grid.asked.nodes = s->grid.use.nodes = (size_t)v;
        s->grid.nodes_given = 1;
    } else if (!strcmp(key, "grid.growth")) {
        s->grid.asked.growth = s->grid.use.growth = v;
    } else if (!strcmp(key, "solver.momentum")) {
        s->relax.momentum = v;
    } else if (!strcmp(key, "solver.max_iter")) {
        s->relax.max_iter = (size_t)v;
    } else if (!strcmp(key, "protocol.dwell")) {
        s->proto.dwell = (size_t)v;
    } else if (!strcmp(key, "material.E0")) {
        s->mat.E = v;
    } else if (!strcmp(key, "material.Einf")) {
        s->time.Einf = v;
    } else if (!strcmp(key, "material.tau")) {
        s->time.tau = v;
    } else if (!strcmp(key, "protocol.spring")) {
        s->time.spring = v;
    } else if (!strcmp(key, "protocol.dwell_time")) {
        s->time.dwell = v;
    }
    adh_config_note_origin(c, key, 3);
}

/* keys set by a scene (and key put to v when key is not NULL): the core's
 * sentence, which opens with core, opens with want ("key = value") once
 * keyed, the rest of it (from " is ") kept. */
static void keyed(const char *keys, const char *key, double v, const char *core, const char *want)
{
    adh_config *c = malloc(sizeof *c);
    char msg[1024], out[1200];
    adh_config_default(c);
    snprintf(c->scene, sizeof c->scene, "a.scene");
    if (scene_sets(c, keys) != 0) {
        ok(0, "%s: the scene's keys set", keys);
        free(c);
        return;
    }
    if (key)
        put(c, key, v);
    core_sentence(&c->spec, msg, sizeof msg);
    const char *said = adh_config_key_opening(c, &c->spec, msg, out, sizeof out);
    size_t n = strlen(core), w = strlen(want);
    const char *rest = strstr(msg, " is ");
    ok(!strncmp(msg, core, n) && said && !strncmp(out, want, w) && rest && !strcmp(out + w, rest) &&
       !strncmp(said, want, strlen(said)),
       "%s%s%s: '%s' -> '%s'", keys, key ? " and " : "", key ? key : "", msg, out);
    free(c);
}

/* The sentence stays the core's. */
static void kept(const char *keys, const char *sentence, const char *what)
{
    adh_config *c = malloc(sizeof *c);
    char msg[1024], out[1200];
    adh_config_default(c);
    scene_sets(c, keys);
    if (sentence)
        snprintf(msg, sizeof msg, "%s", sentence);
    else
        core_sentence(&c->spec, msg, sizeof msg);
    const char *said = adh_config_key_opening(c, &c->spec, msg, out, sizeof out);
    ok(!said && !strcmp(out, msg) && msg[0], "%s: '%s' kept", what, out);
    free(c);
}

int main(void)
{
    /* adh_material_validate */
    keyed("material.E=1e20", NULL, 0, "E (modulus) = 1e+20 Pa", "material.E = 1e+20Pa");
    /* E0, the same value under the solid's name: its key where it was given */
    keyed("", "material.E0", 2e13, "E (modulus) = 20 TPa", "material.E0 = 20TPa");
    keyed("material.A=0", NULL, 0, "A (Hamaker constant) = 0 J", "material.A = 0J");
    keyed("material.z0=-0.5nm", NULL, 0, "z0 (equilibrium separation) = -500 pm", "material.z0 = -500pm");
    keyed("material.R=0", NULL, 0, "R (effective radius) = 0 nm", "material.R = 0nm");
    /* adh_protocol_check */
    keyed("material.z0=100nm;material.R=10um", NULL, 0, "R = 10 um is too small", "material.R = 10um");
    keyed("protocol.start=-1nm", NULL, 0, "start = -1 nm", "protocol.start = -1nm");
    keyed("protocol.step=100nm", NULL, 0, "step d = 100 nm", "protocol.step = 100nm");
    keyed("grid.spacing=2", NULL, 0, "grid spacing 2 m", "grid.spacing = 2m");
    keyed("", "protocol.dwell", 1e9, "dwell = 1000000000 iterations", "protocol.dwell = 1000000000");
    /* adh_drive_check's own, adh_grid_nodes_check */
    keyed("grid.spacing=-1nm", NULL, 0, "spacing = -1 nm", "grid.spacing = -1nm");
    keyed("solver.eps=1e-30", NULL, 0, "eps = 1e-30 m", "solver.eps = 1e-30m");
    keyed("", "grid.nodes", 5, "N = 5 nodes", "grid.nodes = 5");
    /* adh_relax_settings_validate, adh_relax_max_iter_check */
    keyed("solver.eps=2um", NULL, 0, "eps = 2 um", "solver.eps = 2um");
    keyed("", "solver.momentum", 2, "momentum = 2", "solver.momentum = 2");
    keyed("", "solver.max_iter", 0, "max-iter = 0", "solver.max_iter = 0");
    /* adh_rings_spec_validate, adh_rings_check */
    const char *graded = "grid.grid=graded;grid.kernel=ring;";
    char keys[200];
    snprintf(keys, sizeof keys, "%sgrid.fine_band=200nm;grid.radius=100nm", graded);
    keyed(keys, NULL, 0, "grid radius 100 nm", "grid.radius = 100nm");
    snprintf(keys, sizeof keys, "%sgrid.spacing=1nm;grid.fine_band=10nm", graded);
    keyed(keys, NULL, 0, "fine band radius 10 nm", "grid.fine_band = 10nm");
    snprintf(keys, sizeof keys, "%sgrid.spacing=-1nm", graded);
    keyed(keys, NULL, 0, "fine ring width -1 nm", "grid.spacing = -1nm");
    keyed(graded, "grid.growth", 2, "ring growth ratio 2", "grid.growth = 2");
    /* adh_sls_validate, adh_visco_drive_validate: a solid's keys */
    const char *sls = "material.material=sls;scene.mode=time";
    keyed(sls, "material.E0", 2e12, "E0 = 2e+12 Pa", "material.E0 = 2e+12Pa");
    keyed(sls, "material.Einf", 5e12, "Einf = 5e+12 Pa", "material.Einf = 5e+12Pa");
    keyed(sls, "material.tau", 1e9, "tau = 1e+09 s", "material.tau = 1e+09s");
    keyed(sls, "protocol.dwell_time", 1e9, "dwell = 1e+09 s", "protocol.dwell_time = 1e+09s");
    keyed(sls, "protocol.spring", 1e9, "spring k = 1e+09 N/m", "protocol.spring = 1e+09N/m");

    /* nobody set eps: its default is no setting the user gave */
    kept("", "eps = 1 pm is below what double precision can reach with deformations up to 5.5 nm", "eps nobody set");
    /* a uniform grid's radius is N x spacing, not the graded grid's key */
    kept("grid.radius=1um;grid.spacing=0.5nm", NULL, "a uniform grid's Rmax beside grid.radius");
    /* Einf = auto (10 E0) names no value the key holds */
    adh_config *c = malloc(sizeof *c);
    char msg[512], out[600];
    adh_config_default(c);
    scene_sets(c, "material.material=sls;scene.mode=time;material.E0=600GPa;material.Einf=auto");
    core_sentence(&c->spec, msg, sizeof msg);
    ok(!adh_config_key_opening(c, &c->spec, msg, out, sizeof out) && !strncmp(out, "Einf = 6e+12 Pa", 15),
       "Einf = auto, 10 E0 past 1 TPa: '%s' kept", out);
    free(c);
    /* a sentence that opens with no setting */
    kept("protocol.step=1nm", "the surfaces never came into contact", "no opening");
    return tap_done();
}
