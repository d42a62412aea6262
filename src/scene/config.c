#include "scene/config.h"

#include <math.h>
#include <string.h>

#include "adhere/grid.h"

void adh_config_default(adh_config *c)
{
    memset(c, 0, sizeof *c);
    c->mat = adh_material_default();
    c->mat.E = 3e8; /* Figure 4: sigma = 7.50, the paper's hysteresis showcase */
    c->nodes = 1000;
    c->spacing = NAN;
    c->kernel = ADH_KERNEL_PAPER;
    c->relax = adh_relax_settings_default();
    c->proto = adh_protocol_settings_default();
    c->mode = ADH_MODE_RELAX;
    c->plot = 1;
    c->plots = ADH_PLOT_ALL;
    c->drive_speed = 1e-6;
    c->cols = 100;
    c->rows = 32;
}

double adh_config_spacing(const adh_config *c)
{
    return isnan(c->spacing) ? adh_grid_default_rmax(&c->mat) / (double)c->nodes : c->spacing;
}
