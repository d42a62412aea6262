/* The figures a run can ask for (a scene's `plots`, --plots): bits of a
 * mask. The plot module draws the first three, the CLI the scene figures. */
#ifndef ADH_SCENE_FIGURES_H
#define ADH_SCENE_FIGURES_H

enum adh_plot_kind {
    ADH_PLOT_FORCE = 1u << 0,
    ADH_PLOT_PROFILE = 1u << 1,
    ADH_PLOT_CONTACT = 1u << 2,
    ADH_PLOT_ALL = 7u,             /* the plot module's three figures */
    /* Scene figures drawn by the CLI from force.tsv's columns: */
    ADH_PLOT_PRECONTACT = 1u << 3, /* Figure 1 inset: force before contact vs eq 22 at h0 and at h (eq 23) */
    ADH_PLOT_BULGE = 1u << 4       /* Figure 2: central bulge vs central gap, against eq 23 */
};

#endif
