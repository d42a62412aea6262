/* force-base.png: the force against the instrument's base (the piezo), the
 * curve an AFM or SFA user reads off, beside force.png's force against the
 * sphere's position h0 = base + F/k. */
#ifndef ADH_PLOT_FORCEBASE_H
#define ADH_PLOT_FORCEBASE_H

#include <stddef.h>

#include "adhere/run.h"
#include "plot/session.h"
#include "plot/setup.h"

/* Whether s's run has a base apart from h0: a finite spring, on the static
 * curve or in physical time. Without one base = h0 and force-base.png
 * would be force.png again: it is not drawn. */
int adh_forcebase_wanted(const adh_plot_setup *s);

/* Draws force-base.png of run (under s's spring) through ses, headed by
 * heading (a gnuplot string expression), its data forcebase.dat (columns
 * base, F, h0; one dataset per curve, then the snap points).
 * The static curve (s->equilibrium) is followed as the base moves: in from
 * its start, out from its deepest point; where the base would turn back
 * (a fold, dF/dh0 = k) the sphere jumps at that base to the curve's next
 * point with the same base (between rows, linearly), the snap a vertical
 * segment. A run in physical time has its rows drawn as they are (a jump
 * is two rows at one time and base). 0, or -1 with why. */
int adh_forcebase_figure(adh_session *ses, const adh_plot_setup *s, const adh_run *run, const char *heading,
                         char *why, size_t whylen);

#endif
