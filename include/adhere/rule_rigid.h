/* Rigid spheres' step rule, adh_rule_rigid (adhere/rule.h): eq 22 at every
 * drive position from the start down to adh_rule_rigid_end. */
#ifndef ADHERE_RULE_RIGID_H
#define ADHERE_RULE_RIGID_H

#include "adhere/params.h"
#include "adhere/protocol.h"
#include "adhere/rule.h"

/* The lowest drive position of a rigid-spheres run: the protocol's deepest
 * turn, but not below 0.7 z0, just past where eq 22's repulsion balances
 * its attraction (0.794 z0); below it the rigid force soon diverges. */
double adh_rule_rigid_end(const adh_material *m, const adh_protocol_settings *ps);

#endif
