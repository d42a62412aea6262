/* An undo history of a drive (vis-style: a state is restored by copying its
 * snapshot, never by recomputing it). Each entry is a snapshot of the drive
 * taken after a row: its relaxed state, where it was in the protocol and
 * how much of its run it had written, so undo puts the drive and its run
 * back exactly, and stepping on from there gives the rows it gave before.
 *
 * The entries 0..cursor are the path so far; entries past the cursor can be
 * redone until the next push, which discards them. The first entry is never
 * undone (the path's first row). No I/O. */
#ifndef ADHERE_HISTORY_H
#define ADHERE_HISTORY_H

#include <stddef.h>
#include "adhere/drive.h"
#include "adhere/state.h"

typedef struct adh_history adh_history;

/* An empty history. NULL when out of memory. */
adh_history *adh_history_alloc(void);
void adh_history_free(adh_history *h);

/* Appends a snapshot of d after the cursor (dropping what could be redone)
 * and moves the cursor onto it. ADH_SUCCESS or ADH_ENOMEM. */
int adh_history_push(adh_history *h, const adh_drive *d);

/* Move the cursor one entry back / forward and restore d there (redo puts
 * the entry's row back on d's run). ADH_SUCCESS; ADH_EINVAL when there is
 * nothing to undo (at the first entry or empty) / nothing to redo, or d is
 * on another grid. */
int adh_history_undo(adh_history *h, adh_drive *d);
int adh_history_redo(adh_history *h, adh_drive *d);
/* Restores d at the cursor's entry (drops a step under way).
 * ADH_SUCCESS, or ADH_EINVAL when empty or on another grid. */
int adh_history_restore(const adh_history *h, adh_drive *d);

/* Forget every entry. */
void adh_history_clear(adh_history *h);

/* Entries on the path so far (cursor + 1; 0 when empty), and entries that
 * could be redone. */
size_t adh_history_length(const adh_history *h);
size_t adh_history_redoable(const adh_history *h);

/* The relaxed state of entry i of the path so far (0 the oldest); NULL
 * when i is not on the path. Borrowed, valid until the next push. */
const adh_state *adh_history_state_at(const adh_history *h, size_t i);

#endif
