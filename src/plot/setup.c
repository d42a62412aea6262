#include "plot/setup.h"

#include <math.h>

double adh_plot_setup_radius(const adh_plot_setup *s, size_t n)
{
    return s->r ? s->r[n] : ((double)n + 0.5) * s->dr;
}

void adh_plot_setup_fill(const adh_config *cfg, const adh_run_spec *run, const adh_grid *g, adh_plot_setup *s)
{
    const adh_output_options *o = &cfg->output;
    *s = (adh_plot_setup){
        .mat = run->mat,
        .figures = o->plots,
        .draw = o->plot,
        .title = o->title,
        .rigid = run->mode == ADH_MODE_RIGID,
        .equilibrium = run->mode == ADH_MODE_STATIC,
        .drive_speed = run->mode == ADH_MODE_TIME ? run->time.speed_out : o->drive_speed,
        .timed = run->mode == ADH_MODE_TIME,
        .sprung = run->mode != ADH_MODE_RIGID && isfinite(run->time.spring),
        .spring = run->time.spring,
        .Einf = run->mode == ADH_MODE_TIME && run->time.sls ? adh_config_einf(run) : NAN,
        .tau = run->time.tau,
        .step = run->proto.step,
        .nodes = g ? g->n : run->grid.use.nodes,
        .dr = g ? g->dr : adh_config_spacing(run),
        .r = g ? g->r : NULL,
        .style = o->gnuplot_style,
        .measured = o->measured,
        .cancel = run->relax.cancel,
    };
}
