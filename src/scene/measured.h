/* A measured force-position curve (--data FILE) to hold against the model,
 * as instruments write it: columns separated by tabs, commas, semicolons or
 * blanks; an optional header line naming the columns and their units
 * ("Separation (nm)<TAB>Force (nN)", "z (nm),F (nN)", "h0[um] F[uN]",
 * "force_pN", "h0/nm"); two columns, or more with the position and force
 * columns chosen by name or number. Without a header the two columns are
 * nm and nN. '#' starts a comment.
 *
 * The position is the drive position (larger = further apart): the points
 * split into segments where it turns, an approach where it falls, a retract
 * where it rises. */
#ifndef ADH_SCENE_MEASURED_H
#define ADH_SCENE_MEASURED_H

#include <stddef.h>

#define ADH_MEASURED_MAX_FILES 8
#define ADH_MEASURED_MAX_SEGMENTS 64
/* The longest line read, in bytes. */
#define ADH_MEASURED_MAX_LINE 4096
/* A measured curve is refused past these (drawn, a million points already
 * take gnuplot seconds). */
#define ADH_MEASURED_MAX_POINTS 1000000
#define ADH_MEASURED_MAX_BYTES (64 << 20)

typedef struct adh_measured_segment {
    size_t first, n;   /* points first .. first + n - 1 */
    int dir;           /* +1 approach (position falls), -1 retract (rises) */
} adh_measured_segment;

typedef struct adh_measured {
    size_t n;
    double *h0;        /* m */
    double *F;         /* N */
    size_t *line;      /* the file line of each point */
    size_t nseg;
    adh_measured_segment seg[ADH_MEASURED_MAX_SEGMENTS];
    /* The first line where the position goes back within a segment (a
     * segment of fewer than 3 points between two turns), 0 if none: drawn,
     * but no fit takes it. */
    size_t nonmonotonic_line;
    char path[4096];   /* as named */
    char name[128];    /* its base name, for a plot's key */
    char columns[160]; /* the columns read, as the header names them ("" without) */
    const struct adh_measured *next;   /* the next --data file, or NULL */
} adh_measured;

/* Reads path into m (SI units), refusing a NUL byte, a token that is not a
 * finite number of a double's range, a line over ADH_MEASURED_MAX_LINE
 * bytes, more than ADH_MEASURED_MAX_POINTS points or ADH_MEASURED_MAX_BYTES
 * bytes. columns: "" or NULL for the automatic
 * choice (the only two columns; with more, the header's position and
 * force columns by name), else "POS,FORCE", each a 1-based number or a
 * header name (case-insensitive, the unit left out, a unique prefix
 * will do). 0, or -1 with "PATH:LINE: what is wrong and what is wanted" in
 * why (nothing allocated). m->next is set to NULL. */
int adh_measured_load(const char *path, const char *columns, adh_measured *m, char *why, size_t whylen);
void adh_measured_free(adh_measured *m);

/* "approach" or "retract". */
const char *adh_measured_dir_name(int dir);

#endif
