/* A snapshot history of relaxation states for stepping back and forth
 * (vis-style undo: a state is restored by copying its snapshot, never by
 * recomputing it). Each entry pairs a state with the observation row that
 * was read off it, so the rows of the path so far form one contiguous array
 * that can be handed to writers as an adh_run's rows.
 *
 * The entries 0..cursor are the path so far; entries past the cursor can be
 * redone until the next push, which discards them. No I/O. */
#ifndef ADHERE_HISTORY_H
#define ADHERE_HISTORY_H

#include <stddef.h>
#include "adhere/observe.h"
#include "adhere/state.h"

typedef struct adh_history adh_history;

/* A history of states of n nodes each. NULL when out of memory. */
adh_history *adh_history_alloc(size_t n);
void adh_history_free(adh_history *h);

/* Appends a copy of s and its row after the cursor (dropping what could be
 * redone) and moves the cursor onto it. ADH_SUCCESS, ADH_EINVAL when s has
 * the wrong size, ADH_ENOMEM. */
int adh_history_push(adh_history *h, const adh_state *s, const adh_obs *row);

/* Move the cursor one entry back / forward. ADH_SUCCESS, or ADH_EINVAL when
 * there is nothing to undo (at the first entry or empty) / nothing to redo. */
int adh_history_undo(adh_history *h);
int adh_history_redo(adh_history *h);

/* Forget every entry. */
void adh_history_clear(adh_history *h);

/* Entries on the path so far (cursor + 1; 0 when empty), and entries that
 * could be redone. */
size_t adh_history_length(const adh_history *h);
size_t adh_history_redoable(const adh_history *h);

/* The entry at the cursor (NULL when empty); the snapshot is borrowed. */
const adh_state *adh_history_state(const adh_history *h);
const adh_obs *adh_history_row(const adh_history *h);

/* The snapshot of entry i of the path so far (0 the oldest); NULL when i is
 * not on the path. Borrowed, like adh_history_state(). */
const adh_state *adh_history_state_at(const adh_history *h, size_t i);

/* The rows of the path so far, oldest first, adh_history_length() of them
 * (borrowed; valid until the next push or free). */
const adh_obs *adh_history_rows(const adh_history *h);

#endif
