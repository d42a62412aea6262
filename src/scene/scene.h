/* Scene files (INI, see adhere-scene(5)): material, grid, solver, protocol
 * and outputs of a run. */
#ifndef ADH_SCENE_SCENE_H
#define ADH_SCENE_SCENE_H

#include <stddef.h>

#include "scene/config.h"

/* Finds a scene: a path to a file, or the name of a shipped scene ("fig5")
 * looked up in the scenes/ of each adh_data_root in turn ($ADHERE_DATADIR,
 * share/adhere beside the executable, the install prefix). Writes the path found; 0, or -1 with why. */
int adh_scene_find(const char *name_or_path, char *path, size_t pathlen, char *why, size_t whylen);

/* Reads the scene named (as adh_scene_find finds it, its path in path) into
 * a new string *text (the caller frees it): up to 1 MiB, no NUL byte. 0,
 * or -1 with why. */
int adh_scene_read(const char *name_or_path, char *path, size_t pathlen, char **text, char *why, size_t whylen);

/* Applies the scene's values over cfg. 0, or -1 with "FILE:LINE: message". */
int adh_scene_load(const char *name_or_path, adh_config *cfg, char *why, size_t whylen);

/* The same from text already in memory (tests, fuzzing); name labels messages. */
int adh_scene_parse_string(const char *text, const char *name, adh_config *cfg, char *why, size_t whylen);

#endif
