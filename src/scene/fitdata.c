#include "adhere/units.h"
#include "scene/fitdata.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/models.h"
#include "adhere/protocol.h"

void adh_fitdata_free(adh_fitdata *fd)
{
    free(fd->x);
    free(fd->F);
    free(fd->dir);
    free(fd->contact);
    free(fd->seg);
    free(fd->file);
    free(fd->line);
    memset(fd, 0, sizeof *fd);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The jump of segment s: the force step between neighbours that an
 * approach falls by (a retract rises by) most, if it stands out from the
 * segment's median step. The index of the point before it, or -1 with why. */
static long find_jump(const adh_measured *m, const adh_measured_segment *s, char *why, size_t whylen)
{
    if (s->n < 4) {
        snprintf(why, whylen, "%s:%zu: this %s segment has %zu points, at least 4 needed: a fit needs the jump and "
                 "points either side of it", m->path, m->line[s->first], adh_measured_dir_name(s->dir), s->n);
        return -1;
    }
    double *a = malloc((s->n - 1) * sizeof *a);
    if (!a) {
        snprintf(why, whylen, "out of memory");
        return -1;
    }
    long best = 0;
    double bestd = 0;
    for (size_t k = 0; k + 1 < s->n; k++) {
        size_t i = s->first + k;
        double d = (m->F[i + 1] - m->F[i]) * (s->dir > 0 ? -1 : 1);   /* > 0 the way the jump goes */
        a[k] = fabs(d);
        if (d > bestd) {
            bestd = d;
            best = (long)k;
        }
    }
    qsort(a, s->n - 1, sizeof *a, cmp_double);
    double med = a[(s->n - 1) / 2], most = a[s->n - 2];
    free(a);
    /* no step the jump's way over a median step of 0: a ratio would read
     * "0 nN is inf times the median step" (a force column of zeros) */
    if (!(bestd > 0) && !(med > 0)) {
        char what[128];
        if (most > 0)
            snprintf(what, sizeof what, "its force never steps %s and the median step is 0", s->dir > 0 ? "down" : "up");
        else
            snprintf(what, sizeof what, "its force is %s at every point: the curve has no force steps",
                     adh_qtext(m->F[s->first], ADH_Q_FORCE).s);
        snprintf(why, whylen, "%s:%zu-%zu: no jump in this %s segment: %s; a fit needs a jump %s contact, a force "
                 "step %s at least %g times the median step", m->path, m->line[s->first],
                 m->line[s->first + s->n - 1], adh_measured_dir_name(s->dir), what, s->dir > 0 ? "into" : "out of",
                 s->dir > 0 ? "down" : "up", ADH_FITDATA_JUMP_RATIO);
        return -1;
    }
    if (!(bestd > ADH_FITDATA_JUMP_RATIO * med)) {
        snprintf(why, whylen, "%s:%zu-%zu: no jump in this %s segment: its largest force step %s (%s) is %.2g "
                 "times the median step, not %g; a fit places the contact branch by the jump %s contact",
                 m->path, m->line[s->first], m->line[s->first + s->n - 1], adh_measured_dir_name(s->dir),
                 s->dir > 0 ? "down" : "up", adh_qtext(bestd, ADH_Q_FORCE).s, bestd / med, ADH_FITDATA_JUMP_RATIO,
                 s->dir > 0 ? "into" : "out of");
        return -1;
    }
    return (long)s->first + best;
}

static int alloc_points(adh_fitdata *fd, size_t n)
{
    fd->x = malloc(n * sizeof *fd->x);
    fd->F = malloc(n * sizeof *fd->F);
    fd->dir = malloc(n * sizeof *fd->dir);
    fd->contact = malloc(n * sizeof *fd->contact);
    fd->seg = malloc(n * sizeof *fd->seg);
    fd->file = malloc(n * sizeof *fd->file);
    fd->line = malloc(n * sizeof *fd->line);
    return fd->x && fd->F && fd->dir && fd->contact && fd->seg && fd->file && fd->line ? 0 : -1;
}

/* Every segment of every file, labelled. */
static int gather(const adh_measured *m, adh_fitdata *fd, char *why, size_t whylen)
{
    size_t n = 0;
    int nseg = 0;
    for (const adh_measured *f = m; f; f = f->next) {
        if (f->nonmonotonic_line) {
            snprintf(why, whylen, "%s:%zu: the position goes back within a segment (a turn of fewer than 3 points): "
                     "a fit needs each approach and retract monotonic", f->path, f->nonmonotonic_line);
            return -1;
        }
        for (size_t s = 0; s < f->nseg; s++) {
            const adh_measured_segment *sg = &f->seg[s];
            long jump = find_jump(f, sg, why, whylen);
            if (jump < 0)
                return -1;
            /* the turning point is the next segment's first */
            size_t last = s + 1 < f->nseg ? sg->n - 1 : sg->n;
            for (size_t k = 0; k < last; k++) {
                size_t i = sg->first + k;
                fd->x[n] = f->h0[i];
                fd->F[n] = f->F[i];
                fd->dir[n] = sg->dir;
                fd->contact[n] = sg->dir > 0 ? (long)i > jump : (long)i <= jump;
                fd->seg[n] = nseg;
                fd->file[n] = f;
                fd->line[n] = f->line[i];
                fd->ncontact += (size_t)fd->contact[n];
                n++;
            }
            nseg++;
        }
    }
    fd->d = (adh_fit_data){ .n = n, .x = fd->x, .F = fd->F, .dir = fd->dir, .contact = fd->contact, .seg = fd->seg };
    return 0;
}

/* Positions within the model's reach, an attraction (the force below the
 * baseline somewhere), near the start's adhesion. */
static int ranges(adh_fitdata *fd, const adh_material *start, double offset, double baseline, char *why, size_t whylen)
{
    double reach = adh_protocol_reach(start), fjkr = fabs(adh_jkr_pulloff(start));
    size_t imin = 0;
    /* the offset, not the header's unit, when one was given, an offset
     * would bring every position within reach and the one given does not:
     * the range allowed (with none given, the unit is the likelier slip) */
    double xlo = INFINITY, xhi = -INFINITY;
    for (size_t i = 0; i < fd->d.n; i++)
        xlo = fmin(xlo, fd->x[i]), xhi = fmax(xhi, fd->x[i]);
    if (offset != 0 && xhi - reach <= xlo + reach && !(offset >= xhi - reach && offset <= xlo + reach)) {
        snprintf(why, whylen, "--offset=%s is out of range: the positions less the offset must lie within the "
                 "model's reach (|h0| up to R/50 = %s at R = %s); for these positions (%s to %s) an offset from %s to "
                 "%s is allowed", adh_qtext_arg(offset, ADH_Q_LENGTH).s, adh_qtext(reach, ADH_Q_LENGTH).s,
                 adh_qtext(start->R, ADH_Q_LENGTH).s, adh_qtext(xlo, ADH_Q_LENGTH).s, adh_qtext(xhi, ADH_Q_LENGTH).s,
                 adh_qtext(xhi - reach, ADH_Q_LENGTH).s, adh_qtext(xlo + reach, ADH_Q_LENGTH).s);
        return -1;
    }
    for (size_t i = 0; i < fd->d.n; i++) {
        double h = fd->x[i] - offset;
        if (!(fabs(h) <= reach)) {
            snprintf(why, whylen, "%s:%zu: the position %s is beyond the model's reach (|h0| up to R/50 = %s "
                     "at R = %s): check the position's unit in the header", fd->file[i]->path, fd->line[i],
                     adh_qtext(h, ADH_Q_LENGTH).s, adh_qtext(reach, ADH_Q_LENGTH).s, adh_qtext(start->R, ADH_Q_LENGTH).s);
            return -1;
        }
        if (fd->F[i] < fd->F[imin])
            imin = i;
    }
    /* the model's force is the measured less the baseline: a curve with
     * none below it has no attraction, no pull-off to place the adhesion
     * by (a fit of A from it was 'unidentifiable'; of E alone, a model
     * with adhesion against a curve without) */
    double pull = fd->F[imin] - baseline;
    if (!(pull < 0)) {
        snprintf(why, whylen, "%s:%zu: no attraction in the data: the least force, %s, is not below the baseline (%s), "
                 "and a fit needs the curve's attractive part, its pull-off, to find the adhesion: check the force's "
                 "sign and unit in the header, or give the force far from contact as --baseline",
                 fd->file[imin]->path, fd->line[imin], adh_qtext(fd->F[imin], ADH_Q_FORCE).s,
                 adh_qtext(baseline, ADH_Q_FORCE).s);
        return -1;
    }
    if (!(fjkr > 0)) {   /* no adhesion at the start: no JKR pull-off, and no ratio to it ("inf times") */
        snprintf(why, whylen, "%s:%zu: the strongest attraction is %s, but the start values have no adhesion (A = %s: "
                 "no JKR pull-off to compare it with): start A above 0", fd->file[imin]->path, fd->line[imin],
                 adh_qtext(pull, ADH_Q_FORCE).s, adh_qtext(start->A, ADH_Q_ENERGY).s);
        return -1;
    }
    double ratio = fabs(pull) / fjkr;
    if (!(ratio > 1.0 / 30 && ratio < 30)) {
        snprintf(why, whylen, "%s:%zu: the strongest attraction, %s, is %.3g times the JKR pull-off at the start "
                 "values (%s): check the force's unit in the header, or start A and R nearer", fd->file[imin]->path,
                 fd->line[imin], adh_qtext(pull, ADH_Q_FORCE).s, ratio, adh_qtext(-fjkr, ADH_Q_FORCE).s);
        return -1;
    }
    return 0;
}

int adh_fitdata_make(const adh_measured *m, size_t nfree, const adh_material *start, double offset, double baseline,
                     adh_fitdata *fd, char *why, size_t whylen)
{
    memset(fd, 0, sizeof *fd);
    size_t n = 0;
    for (const adh_measured *f = m; f; f = f->next)
        n += f->n;
    if (!m || n == 0) {
        snprintf(why, whylen, "no measured points: give the curve with --data=FILE");
        return -1;
    }
    if (alloc_points(fd, n) != 0) {
        snprintf(why, whylen, "out of memory for %zu points", n);
        adh_fitdata_free(fd);
        return -1;
    }
    if (gather(m, fd, why, whylen) != 0 || ranges(fd, start, offset, baseline, why, whylen) != 0) {
        adh_fitdata_free(fd);
        return -1;
    }
    size_t need = nfree + 2 > ADH_FITDATA_MIN_CONTACT ? nfree + 2 : ADH_FITDATA_MIN_CONTACT;
    if (fd->ncontact < need) {
        snprintf(why, whylen, "%s:%zu: %zu point%s past the jump, in contact: a fit of %zu parameter%s needs at least "
                 "%zu there (load deeper, or sample more finely)", m->path, m->line[m->n - 1], fd->ncontact,
                 fd->ncontact == 1 ? "" : "s", nfree, nfree == 1 ? "" : "s", need);
        adh_fitdata_free(fd);
        return -1;
    }
    return 0;
}
