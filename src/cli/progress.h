/* What a run on a terminal says while it works and when it is done: the
 * share of the planned steps (or runs) done and the time left at the pace
 * so far, and one closing line. */
#ifndef ADH_CLI_PROGRESS_H
#define ADH_CLI_PROGRESS_H

#include <stddef.h>

/* "35 %, about 40 s left" for done of total after elapsed seconds, at the
 * pace so far. Before anything is done, "0 %"; with no total, "N done". */
void cli_progress_text(size_t done, size_t total, double elapsed, char *buf, size_t len);
/* A duration as people read it: "12.3 s", "4 min 10 s", "1 h 5 min". */
void cli_progress_duration(double seconds, char *buf, size_t len);

/* "67 %, about 5 min 40 s left" (share of the cost done), or "67 %" when
 * left is unknown. */
void cli_progress_left(double frac, double left, char *buf, size_t len);

#endif
