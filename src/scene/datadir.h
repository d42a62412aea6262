/* Where the shipped data (scenes/, gnuplot/) is, so that a built tree still
 * works after it is moved and an installed adhere finds its prefix. */
#ifndef ADH_SCENE_DATADIR_H
#define ADH_SCENE_DATADIR_H

#include <stddef.h>

/* The i-th place shipped data may be, in order: 0 $ADHERE_DATADIR (when set
 * and not empty); 1 share/adhere beside the running executable, found
 * through /proc/self/exe (an uninstalled tree, wherever it was built or
 * moved); 2 the install prefix's datadir, ADH_DATADIR (PREFIX/share/adhere).
 * Writes it to buf; 0, or -1 when that place does not apply or i > 2. */
int adh_data_root(int i, char *buf, size_t len);

/* The first root holding the directory sub ("gnuplot", "scenes"): writes
 * ROOT/sub to buf. 0, or -1 when none holds it. */
int adh_data_dir(const char *sub, char *buf, size_t len);

/* $ADHERE_DATADIR, when set and not empty, names a directory: 0, or -1
 * with why naming it (a misspelt one was passed over in silence, and the
 * built-in places used instead). */
int adh_data_env_check(char *why, size_t whylen);

#endif
