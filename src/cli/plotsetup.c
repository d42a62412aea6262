#include "cli/plotsetup.h"

void cli_plotsetup_fill(const adh_config *cfg, const adh_grid *g, adh_plot_setup *s)
{
    *s = (adh_plot_setup){
        .mat = cfg->mat,
        .figures = cfg->plots,
        .draw = cfg->plot,
        .title = cfg->title,
        .rigid = cfg->mode == ADH_MODE_RIGID,
        .equilibrium = cfg->mode == ADH_MODE_STATIC,
        .drive_speed = cfg->drive_speed,
        .step = cfg->proto.step,
        .nodes = g ? g->n : cfg->nodes,
        .dr = g ? g->dr : adh_config_spacing(cfg),
        .r = g ? g->r : NULL,
        .style = cfg->gnuplot_style,
        .measured = cfg->measured,
        .cancel = cfg->relax.cancel,
    };
}
