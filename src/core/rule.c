#include "adhere/rule.h"

#include "adhere/status.h"

int adh_rule_check(const adh_rule_type *t)
{
    if (!t || !t->name || !t->alloc || !t->free || !t->set || !t->observe)
        return ADH_EINVAL;
    int stepped = !t->next && t->move && t->iterate && t->snap_alloc && t->snap_free && t->save && t->load && t->snap_state;
    int curve = t->next && !t->move;   /* iterate: its work before a point, in batches */
    return stepped || curve ? ADH_SUCCESS : ADH_EINVAL;
}
