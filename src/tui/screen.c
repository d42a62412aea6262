#define NCURSES_WIDECHAR 1
#include "tui/screen.h"

#include <ctype.h>
#include <curses.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <wchar.h>
#include <wctype.h>

#include "adhere/models.h"
#include "adhere/status.h"
#include "adhere/units.h"
#include "plot/axes.h"
#include "plot/outdir.h"
#include "scene/measured.h"
#include "tui/actions.h"
#include "tui/replay.h"

/* Text at (y, x), clipped to w columns and to the screen. Every label is
 * one column per character (Greek letters included), so characters are
 * columns. */
static void put(int y, int x, int w, attr_t attr, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
/* Rows from clip_bottom down belong to another panel (the compact
 * parameters on a short screen): a panel drawn above stops there. */
static int clip_bottom = 1 << 30;

/* Where a line too long for w columns is cut: before the last clause
 * (", ", "; ", " (") that ends within them, so a narrow terminal loses
 * the line's last words whole ("path 2 states, 0 to redo", not "...;
 * start 16.9") and never shows a number without its unit; when no clause
 * ends in the second half of the line, before the last number there if w
 * would cut it or its unit ("approaching at 1 µ" of 1 µm/s), else w. */
static int clause_end(const wchar_t *s, int w)
{
    for (int c = w - 1; c >= w / 2; c--)
        if ((s[c] == L',' || s[c] == L';') && s[c + 1] == L' ')
            return c;
        else if (s[c] == L' ' && s[c + 1] == L'(' && c < w)
            return c;
    for (int c = w - 1; c >= w / 2; c--)
        if (s[c] == L' ' && (iswdigit((wint_t)s[c + 1]) || (s[c + 1] == L'-' && iswdigit((wint_t)s[c + 2])))) {
            int e = c + 1;
            while (s[e] && s[e] != L' ')   /* the number */
                e++;
            if (s[e] == L' ')              /* and the word after it, its unit */
                for (e++; s[e] && s[e] != L' ' && s[e] != L',' && s[e] != L';'; e++)
                    ;
            return e > w ? c : w;
        }
    return w;
}

static void put(int y, int x, int w, attr_t attr, const char *fmt, ...)
{
    char buf[1024];
    wchar_t wbuf[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    if (y < 0 || y >= LINES || y >= clip_bottom || x >= COLS || w <= 0)
        return;
    if (x + w > COLS)
        w = COLS - x;
    size_t n = mbstowcs(wbuf, buf, sizeof wbuf / sizeof wbuf[0] - 1);
    if (n == (size_t)-1) {   /* not UTF-8 after all: show bytes as they are */
        attron(attr);
        mvaddnstr(y, x, buf, w);
        attroff(attr);
        return;
    }
    attron(attr);
    size_t text = n;   /* without the blanks that pad it */
    while (text > 0 && wbuf[text - 1] == L' ')
        text--;
    mvaddnwstr(y, x, wbuf, (int)n < w ? (int)n : (int)text <= w ? w : clause_end(wbuf, w));
    attroff(attr);
}

/* The columns s takes (a Greek letter one, in two bytes). */
static size_t text_cols(const char *s)
{
    size_t cols = mbstowcs(NULL, s, 0);
    return cols == (size_t)-1 ? strlen(s) : cols;
}

/* s padded with blanks to w columns (s may hold 2-byte Greek letters, one
 * column each): printf's %-*s counts bytes. */
static const char *pad(const char *s, int w, char *buf, size_t len)
{
    size_t cols = text_cols(s);
    size_t l = strlen(s), blanks = (int)cols < w ? (size_t)(w - (int)cols) : 0;
    if (!len)
        return buf;
    if (l > len - 1)
        l = len - 1;
    if (blanks > len - 1 - l)
        blanks = len - 1 - l;
    memcpy(buf, s, l);
    memset(buf + l, ' ', blanks);
    buf[l + blanks] = '\0';
    return buf;
}

/* s padded to 12 columns of the terminal, not 12 bytes ("16.43 µm" is
 * 8 columns in 9 bytes); one line's worth, for the put() at hand */
static const char *col12(const char *s)
{
    static char buf[96];
    return pad(s, 12, buf, sizeof buf);
}


/* Whether the blank at p[i] stands between a number and its unit. */
static int unit_follows(const char *p, int i)
{
    unsigned char next = (unsigned char)p[i + 1];
    return i > 0 && isdigit((unsigned char)p[i - 1]) && (isalpha(next) || next >= 0x80);
}

/* text word-wrapped into at most maxlines lines of w columns from (y, x)
 * (draw 0: only counted); the lines it takes. Columns are characters (the
 * labels' Greek letters are one column each). */
static int wrap_text(int y, int x, int w, int maxlines, attr_t attr, const char *text, int draw)
{
    const char *p = text;
    int line = 0;
    for (; line < maxlines && *p; line++) {
        int len = (int)strlen(p), take = len;
        if (len > w) {
            /* at a blank, but not between a number and its unit
             * ("force -3.435" above "pN") where another blank will do */
            take = w;
            while (take > 0 && (p[take] != ' ' || unit_follows(p, take)))
                take--;
            for (int t = w; take == 0 && t > 0; t--)
                take = p[t] == ' ' ? t : 0;
            if (take == 0)
                take = w;
        }
        if (draw)
            put(y + line, x, w, attr, "%.*s", take, p);
        p += take;
        while (*p == ' ')
            p++;
    }
    return line;
}

static void put_wrapped(int y, int x, int w, int maxlines, attr_t attr, const char *text)
{
    wrap_text(y, x, w, maxlines, attr, text, 1);
}

static const char *gk(const tui_view *v, const char *utf8, const char *ascii)
{
    return v->utf8 ? utf8 : ascii;
}

/* A number's micro prefix as the micro sign where the terminal shows
 * UTF-8: "1.04 uN" -> "1.04 µN" (the messages are written in ASCII by a
 * layer that knows no terminal; the panels above write µ). Only a digit,
 * a blank, u and a unit (m N s J Pa) not followed by a letter: a quoted
 * value ('5um') or a word (" up") is left as it is. */
static void micro_text(const char *in, char *out, size_t len)
{
    size_t o = 0;
    for (size_t i = 0; in[i] && o + 3 < len; i++) {
        const char *u = in + i;
        size_t ul = u[0] == ' ' && u[1] == 'u' ? (u[2] == 'P' && u[3] == 'a' ? 2 : strchr("mNsJ", u[2]) && u[2] ? 1 : 0) : 0;
        if (ul && i > 0 && isdigit((unsigned char)in[i - 1]) && !isalpha((unsigned char)u[2 + ul])) {
            out[o++] = ' ', out[o++] = '\xc2', out[o++] = '\xb5';
            i++;   /* the u */
            continue;
        }
        out[o++] = in[i];
    }
    out[o] = '\0';
}

/* value in its unit, micro as the micro sign where the terminal shows
 * UTF-8 (the parameter panel beside it writes "10 µm"; "1 um/s" under it
 * read as another unit) */
static void q(const tui_view *v, double value, adh_quantity kind, char *buf, size_t len)
{
    if (!v->utf8) {
        adh_format_quantity(value, kind, 4, buf, len);
        return;
    }
    char raw[64];
    adh_format_quantity(value, kind, 4, raw, sizeof raw);
    micro_text(raw, buf, len);
}

static void draw_params(const tui_sim *s, const tui_view *v, int y, int x, int w)
{
    /* the key hints whole, or fewer of them with the bracket closed: cut
     * at a clause, the line ended '(Up/Down select, Enter edit' */
    char head[96];
    const char *ud = gk(v, "\xe2\x86\x91\xe2\x86\x93", "Up/Down");
    snprintf(head, sizeof head, " Parameters  (%s select, Enter edit, +/- x2)", ud);
    if ((int)text_cols(head) > w)
        snprintf(head, sizeof head, " Parameters  (%s select, Enter edit)", ud);
    if ((int)text_cols(head) > w)
        snprintf(head, sizeof head, " Parameters  (%s select)", ud);
    put(y, x, w, A_BOLD, "%s", head);
    for (int p = 0, row = 1; p < P_COUNT; p++) {
        if (!tui_sim_param_shown(s, (tui_param)p))
            continue;   /* physical time's fields only in it */
        char val[64];
        tui_sim_param_text(s, (tui_param)p, v->utf8, val, sizeof val);
        const tui_param_info *pi = &tui_params[p];
        int sel = p == v->sel;
        char lab[32];
        /* N and the spacing follow the material until one is set: the
         * grid --batch would choose (graded rings for soft contacts) */
        const char *how = "";
        const adh_grid_spec *g = tui_sim_grid(s);
        if (p == P_SPACING && (isnan(g->spacing) || adh_config_grid_auto(&s->cfg.spec)))
            how = g->graded ? ", graded" : ", auto";
        else if (p == P_N && g->graded)
            how = g->storage == ADH_STORAGE_H2 ? " (rings, H2)" : " (rings)";
        char pv[96], what[64];
        size_t nturns;
        tui_sim_turns(s, &nturns);
        const char *label = v->utf8 ? pi->label : pi->ascii;
        if (p == P_TURN && nturns > 1)   /* the field shows the list's ends */
            snprintf(what, sizeof what, "%zu turning points", nturns);
        else
            snprintf(what, sizeof what, "%s", pi->what);
        if (p == P_E && tui_sim_param_shown(s, P_EINF)) {   /* a solid's E is its relaxed modulus */
            label = "E0";
            snprintf(what, sizeof what, "relaxed modulus");
        }
        put(y + row++, x, w, sel ? A_REVERSE : A_NORMAL, "%s%s %s %s%s", sel ? " >" : "  ",
            pad(label, 5, lab, sizeof lab), pad(val, 12, pv, sizeof pv), what, how);
    }
}

/* The lines the panel's fields take. */
static int params_shown(const tui_sim *s)
{
    int n = 0;
    for (int p = 0; p < P_COUNT; p++)
        n += tui_sim_param_shown(s, (tui_param)p);
    return n;
}

/* The parameters in as few lines as the width allows ("E 300 MPa  A
 * 1e-19 J ..."), the selected one highlighted: a short screen keeps them in
 * view beside the state. Returns the lines it takes (or would take with
 * draw = 0). */
static int draw_params_compact(const tui_sim *s, const tui_view *v, int y, int x, int w, int draw)
{
    int line = 0, col = 0;
    for (int p = 0; p < P_COUNT; p++) {
        char val[64], item[96];
        if (!tui_sim_param_shown(s, (tui_param)p))
            continue;
        size_t nturns;
        tui_sim_turns(s, &nturns);
        tui_sim_param_text(s, (tui_param)p, v->utf8, val, sizeof val);
        if (p == P_TURN && nturns > 1)
            snprintf(item, sizeof item, "%s %s, %zu turns", tui_params[p].ascii, val, nturns);
        else
            snprintf(item, sizeof item, "%s %s", v->utf8 ? tui_params[p].label : tui_params[p].ascii, val);
        int len = (int)mbstowcs(NULL, item, 0);
        if (len < 0)
            len = (int)strlen(item);
        if (col > 0 && col + 2 + len > w) {
            line++;
            col = 0;
        }
        if (col > 0)
            col += 2;
        if (draw)
            put(y + line, x + col, w - col, p == v->sel ? A_REVERSE : A_NORMAL, "%s", item);
        col += len;
    }
    return line + 1;
}

/* What the parameters give before anything is solved, and what the closed
 * forms predict for a cycle: the numbers a solve is held against. */
static void draw_derived(const tui_sim *s, const tui_view *v, int y, int x, int w)
{
    const adh_derived *d = &s->der;
    const tui_models *m = &s->models;
    char g[64], es[64], jkr[64], dmt[64], md[64], ji[64], jo[64], hs[64];
    const char *pgr = gk(v, "\xcf\x80\xce\xb3R", "pi gamma R");
    double unit = M_PI * d->gamma * s->cfg.spec.mat.R;
    /* gamma is an energy per area: J/m^2, shown in mJ/m^2 where it lives */
    snprintf(g, sizeof g, "%.4g mJ/m%s", d->gamma * 1e3, gk(v, "\xc2\xb2", "^2"));
    q(v, d->Estar, ADH_Q_PRESSURE, es, sizeof es);
    q(v, d->F_jkr, ADH_Q_FORCE, jkr, sizeof jkr);
    q(v, d->F_dmt, ADH_Q_FORCE, dmt, sizeof dmt);
    q(v, m->md_pulloff, ADH_Q_FORCE, md, sizeof md);
    q(v, m->jump_in, ADH_Q_LENGTH, ji, sizeof ji);
    q(v, d->h_star, ADH_Q_LENGTH, hs, sizeof hs);
    q(v, m->md_jump_out, ADH_Q_LENGTH, jo, sizeof jo);
    put(y, x, w, A_BOLD, " Derived from the parameters; models");
    /* sigma, mu and gamma three blanks apart, fewer where the column is
     * narrower (ASCII's names are longer: at 100 columns the cut took
     * gamma's unit, "mJ/m^"), and mu left out before gamma's unit is */
    char line[192];
    const char *sg = gk(v, "\xcf\x83", "sigma"), *mu = gk(v, "\xce\xbc", "mu"), *ga = gk(v, "\xce\xb3", "gamma");
    for (int gap = 3; gap >= 1; gap--) {
        snprintf(line, sizeof line, "  %s %.4g%*s%s %.4g%*s%s %s", sg, d->sigma, gap, "", mu, d->mu, gap, "", ga, g);
        if ((int)text_cols(line) <= w)
            break;
    }
    if ((int)text_cols(line) > w)
        snprintf(line, sizeof line, "  %s %.4g  %s %s", sg, d->sigma, ga, g);
    put(y + 1, x, w, A_NORMAL, "%s", line);
    /* the grid's resolution of the contact edge, as E, A, z0, R, N or the
     * spacing change: the core's check (adh_grid_check), shown */
    const adh_grid_report *gr = &s->gridres;
    put(y + 2, x, w, gr->resolved ? A_NORMAL : A_BOLD, "  E* %s  %s/%s %.3g %s", es, gk(v, "\xe2\x84\x93", "l"),
        gk(v, "\xce\x94", "dr"), gr->edge_nodes, gr->resolved ? "resolved" : "UNRESOLVED");
    put(y + 3, x, w, A_NORMAL, "  pull-off JKR %s DMT %s", jkr, dmt);
    /* lambda beside the M-D pull-off, or after its jump-out where that
     * line is too narrow for it (ASCII's 'lambda' at 100 columns) */
    char mdl[128], lam[48];
    snprintf(mdl, sizeof mdl, "    M-D %s = %.3g %s", md, m->md_pulloff / -unit, pgr);
    snprintf(lam, sizeof lam, " (%s %.3g)", gk(v, "\xce\xbb", "lambda"), m->md_lambda);
    int below = (int)(text_cols(mdl) + text_cols(lam)) > w;
    put(y + 4, x, w, A_NORMAL, "%s%s", mdl, below ? "" : lam);
    /* eq 24 is a gap; the jump-in it gives (through eq 23) a drive position */
    put(y + 5, x, w, A_NORMAL, "  eq 24: gap h* %s, jump-in %s", hs, ji);
    put(y + 6, x, w, A_NORMAL, "  M-D jump-out %s%s", isnan(m->md_jump_out) ? "none" : jo, below ? lam : "");
}

/* Relaxation: the cycle on the path so far, the quantities an experiment
 * reports (adh_cycle_measure: no physics here). */
static void draw_cycle(const tui_sim *s, const tui_view *v, int y, int x, int w)
{
    adh_cycle c;
    tui_sim_cycle(s, &c);
    char a[64], b[64];
    double unit = M_PI * s->der.gamma * s->cfg.spec.mat.R;
    put(y, x, w, A_BOLD, " Cycle  (this path; models at the left)");
    if (isnan(c.max_load)) {
        put(y + 1, x, w, A_NORMAL, "  load, pull-off, jumps, hysteresis: step first");
        return;
    }
    q(v, c.max_load, ADH_Q_FORCE, a, sizeof a);
    q(v, c.a_turn, ADH_Q_LENGTH, b, sizeof b);
    if (c.unloading)
        put(y + 1, x, w, A_NORMAL, "  load   max %s; a %s at the turn", a, c.a_turn > 0 ? b : "0 nm");
    else
        put(y + 1, x, w, A_NORMAL, "  load   %s deepest so far, a %s", a, c.a_turn > 0 ? b : "0 nm");
    /* pull-off: the force minimum on unloading; jump-out: where the
     * surfaces separate (the tables' pulloff_F and jump_out_h0) */
    q(v, c.pulloff_F, ADH_Q_FORCE, a, sizeof a);
    q(v, c.pulloff_h0, ADH_Q_LENGTH, b, sizeof b);
    if (c.unloading)
        put(y + 2, x, w, A_NORMAL, "  pull-off %s = %.3g %s at %s", a, c.pulloff_F / -unit,
            gk(v, "\xcf\x80\xce\xb3R", "pi gamma R"), b);
    else
        put(y + 2, x, w, A_NORMAL, "  pull-off not unloaded yet");
    q(v, c.jump_in_h0, ADH_Q_LENGTH, a, sizeof a);
    q(v, c.jump_out_h0, ADH_Q_LENGTH, b, sizeof b);
    put(y + 3, x, w, A_NORMAL, "  jump-in %s, jump-out %s", isnan(c.jump_in_h0) ? "not yet" : a,
        isnan(c.jump_out_h0) ? "not yet" : b);
    if (c.unloading)
        put(y + 4, x, w, A_NORMAL, "  hysteresis %s (area between the branches)", adh_qtext(c.hysteresis, ADH_Q_WORK).s);
}

/* The rows both modes show for a solved point: position, force, central
 * deformation and gap, contact radius. Out of contact in relaxation the
 * force line also gives eq 22, the reference there. */
static void draw_point_rows(const adh_obs *o, int rigid_ref, const tui_view *v, int y, int x, int w)
{
    char a[64], b[64], lab[32];
    q(v, o->h0, ADH_Q_LENGTH, a, sizeof a);
    put(y + 1, x, w, A_NORMAL, "  h0     %s drive position", col12(a));
    q(v, o->F, ADH_Q_FORCE, a, sizeof a);
    q(v, o->F_rigid, ADH_Q_FORCE, b, sizeof b);
    if (rigid_ref && !(o->a > 0))
        put(y + 2, x, w, A_NORMAL, "  F      %s force (rigid spheres %s)", col12(a), b);
    else
        put(y + 2, x, w, A_NORMAL, "  F      %s force (positive repels)", col12(a));
    q(v, o->delta, ADH_Q_LENGTH, a, sizeof a);
    put(y + 3, x, w, A_NORMAL, "  %s %s central deformation", pad(gk(v, "\xce\xb4", "delta"), 6, lab, sizeof lab), col12(a));
    q(v, o->hc, ADH_Q_LENGTH, a, sizeof a);
    put(y + 4, x, w, A_NORMAL, "  gap    %s central gap h(0)", col12(a));
    q(v, o->a, ADH_Q_LENGTH, a, sizeof a);
    put(y + 5, x, w, A_NORMAL, "  a      %s contact radius%s", col12(a), o->a > 0 ? "" : " (not in contact)");
}

/* Static mode: the point shown, its stability, and what the curve computed
 * so far says (folds, jumps, pull-offs). */

/* A stopped solve ("the WHAT stopped: why") or the grid's warning, wrapped
 * in bold at y: 1 when one was shown. */
static int put_stopped(const tui_sim *s, int y, int x, int w, const char *what)
{
    char msg[TUI_SIM_WHY_LEN + 64], reason[600];
    int stopped = s->cstatus != ADH_CONTINUE && s->cstatus != ADH_SUCCESS;
    if (stopped)
        snprintf(msg, sizeof msg, "! the %s stopped: %s%s%s (x starts it again)", what, adh_strerror(s->cstatus),
                 *tui_sim_stop_reason(s, reason, sizeof reason) ? ": " : "", reason);
    else if (s->gridwarn[0])
        snprintf(msg, sizeof msg, "! %s", s->gridwarn);
    else
        return 0;
    put_wrapped(y, x, w, stopped ? 2 : 4, A_BOLD, msg);
    return 1;
}
static void draw_curve_state(const tui_sim *s, const tui_view *v, int y, int x, int w)
{
    const adh_obs *o = tui_sim_row(s);
    const adh_static_result *r = &s->sres;
    char a[64], b[64];
    put(y, x, w, A_BOLD, " State  (static equilibrium)");
    if (!o) {
        q(v, s->start, ADH_Q_LENGTH, a, sizeof a);
        q(v, tui_sim_curve_end(s), ADH_Q_LENGTH, b, sizeof b);
        put(y + 1, x, w, A_NORMAL, "  h0     %s start, not solved yet", col12(a));
        char msg[200], *sp = strchr(b, ' ');
        /* number and unit on one line: a no-break space where it can be */
        char end[72];
        if (sp && v->utf8)
            snprintf(end, sizeof end, "%.*s\xc2\xa0%s", (int)(sp - b), b, sp + 1);
        else
            snprintf(end, sizeof end, "%s", b);
        snprintf(msg, sizeof msg, "Press f to solve the first point, r to follow the equilibrium curve through "
                 "its folds down to h0 = %s; m returns to relaxation.", end);
        put_wrapped(y + 2, x + 2, w - 2, 3, A_NORMAL, msg);
    } else {
        draw_point_rows(o, 0, v, y, x, w);
        put(y + 6, x, w, o->stable ? A_NORMAL : A_BOLD, "  point  %zu of %zu, %s, %zu Newton iteration%s", s->ccur + 1,
            s->curve.nrows, o->stable ? "stable" : "UNSTABLE", o->iters, o->iters == 1 ? "" : "s");
        /* a complete curve's missing jump is none, not one to come */
        const char *missing = s->cstatus == ADH_SUCCESS ? "none" : "not yet";
        if (r->folds) {
            /* the physical folds, where an experiment jumps, apart from
             * those of the grid's lattice (the contact line crossing a node) */
            q(v, r->jump_in_h0, ADH_Q_LENGTH, a, sizeof a);
            if (isnan(r->jump_in_h0))
                snprintf(a, sizeof a, "%s", missing);
            q(v, r->jump_out_h0, ADH_Q_LENGTH, b, sizeof b);
            size_t physical = !isnan(r->jump_in_h0) + !isnan(r->jump_out_h0);
            size_t lattice = r->folds > physical ? r->folds - physical : 0;
            char more[48] = "";
            if (lattice)
                snprintf(more, sizeof more, ", +%zu lattice", lattice);
            put(y + 7, x, w, A_NORMAL, "  folds  jump-in %s, out %s%s", a, isnan(r->jump_out_h0) ? missing : b,
                more);
        } else {
            put(y + 7, x, w, A_NORMAL, "  folds  %s", s->cstatus == ADH_SUCCESS ? "none: no jumps" : "none yet");
        }
        q(v, r->pulloff_F, ADH_Q_FORCE, a, sizeof a);
        if (isnan(r->pulloff_F))   /* (past a start in contact, where the curve was not followed) */
            snprintf(a, sizeof a, "%s", s->cstatus == ADH_SUCCESS ? "not known" : "not yet");
        q(v, r->pulloff_F_disp, ADH_Q_FORCE, b, sizeof b);
        /* the pull-off is the force minimum; the force where the surfaces
         * leave at fixed h0 is the jump-out's (summary: pulloff_F_disp) */
        if (isnan(r->pulloff_F_disp))
            put(y + 8, x, w, A_NORMAL, "  pull-off %s; F at the jump-out %s", a, missing);
        else
            put(y + 8, x, w, A_NORMAL, "  pull-off %s; F at the jump-out %s", a, b);
    }
    put(y + 9, x, w, A_NORMAL, "  mode   static (m: relaxation), %s", v->activity);
    if (!put_stopped(s, y + 10, x + 2, w - 2, "curve") && o) {
        q(v, tui_sim_curve_end(s), ADH_Q_LENGTH, b, sizeof b);
        put(y + 10, x, w, A_NORMAL, "  curve  %s at h0 = %s", s->cstatus == ADH_SUCCESS ? "complete, ends" : "goes on to its end", b);
    }
}

/* Physical time: the point shown, its time, the base and its speed, and
 * what the cycle so far measured (jumps, pull-off, hysteresis). */
static void draw_time_state(const tui_sim *s, const tui_view *v, int y, int x, int w)
{
    const adh_obs *o = tui_sim_row(s);
    const adh_visco_result *r = &s->vres;
    const adh_time_settings *ts = &s->cfg.spec.time;
    char a[64], b[64];
    put(y, x, w, A_BOLD, " State  (physical time)");
    if (!o) {
        q(v, ts->speed_in, ADH_Q_SPEED, a, sizeof a);
        q(v, tui_sim_curve_end(s), ADH_Q_LENGTH, b, sizeof b);
        put(y + 1, x, w, A_NORMAL, "  t      0 s, the base at rest, the material %s", ts->sls ? "relaxed" : "elastic");
        put(y + 2, x, w, A_NORMAL, "  Press f for the first step in time, r to run the");
        put(y + 3, x, w, A_NORMAL, "  cycle: in at %s, out, back to h0 = %s.", a, b);
        if (!ts->sls)
            put(y + 4, x, w, A_NORMAL, "  Elastic: the static curve, solved at the first f.");
        put(y + 9, x, w, A_NORMAL, "  mode   physical time, %s", v->activity);
        return;
    }
    q(v, o->t, ADH_Q_TIME, a, sizeof a);
    q(v, s->cfg.spec.time.tau, ADH_Q_TIME, b, sizeof b);
    if (ts->sls)
        put(y + 1, x, w, A_NORMAL, "  t      %s step %zu of %zu, %s %s", col12(a), s->ccur + 1, s->curve.nrows,
            gk(v, "\xcf\x84", "tau"), b);
    else
        put(y + 1, x, w, A_NORMAL, "  t      %s point %zu of %zu, elastic", col12(a), s->ccur + 1, s->curve.nrows);
    q(v, o->base, ADH_Q_LENGTH, a, sizeof a);
    q(v, o->branch > 0 ? ts->speed_in : ts->speed_out, ADH_Q_SPEED, b, sizeof b);
    put(y + 2, x, w, A_NORMAL, "  base   %s %s at %s", col12(a), o->branch > 0 ? "approaching" : "retracting", b);
    q(v, o->h0, ADH_Q_LENGTH, a, sizeof a);
    q(v, o->F, ADH_Q_FORCE, b, sizeof b);
    put(y + 3, x, w, A_NORMAL, "  h0     %s F %s", col12(a), b);
    q(v, o->a, ADH_Q_LENGTH, a, sizeof a);
    q(v, o->delta, ADH_Q_LENGTH, b, sizeof b);
    put(y + 4, x, w, A_NORMAL, "  a      %s %s %s", col12(o->a > 0 ? a : "0 (apart)"), gk(v, "\xce\xb4", "delta"), b);
    q(v, r->jump_in_h0, ADH_Q_LENGTH, a, sizeof a);
    q(v, r->jump_out_h0, ADH_Q_LENGTH, b, sizeof b);
    put(y + 5, x, w, A_NORMAL, "  jumps  %zu; in %s, out %s", r->jumps, isnan(r->jump_in_h0) ? "not yet" : a,
        isnan(r->jump_out_h0) ? "not yet" : b);
    q(v, r->pulloff_F, ADH_Q_FORCE, a, sizeof a);
    q(v, r->pulloff_t, ADH_Q_TIME, b, sizeof b);
    if (isnan(r->pulloff_F))
        put(y + 6, x, w, A_NORMAL, "  pull   not unloaded yet");
    else
        put(y + 6, x, w, A_NORMAL, "  pull   %s at t = %s", a, b);
    put(y + 7, x, w, A_NORMAL, "  energy %s dissipated, hysteresis %s%s", adh_qtext(r->cycle.dissipated, ADH_Q_WORK).s,
        r->hysteresis > 0 ? adh_qtext(r->hysteresis, ADH_Q_WORK).s : "not yet",
        ts->sls || !(r->hysteresis > 0) ? "" : " (the jumps')");
    if (ts->sls)
        put(y + 8, x, w, A_NORMAL, "  steps  %zu Newton iterations on this one", o->iters);
    else
        put(y + 8, x, w, A_NORMAL, "  steps  none in time: the static curve's path");
    put(y + 9, x, w, A_NORMAL, "  mode   physical time, %s", v->activity);
    if (!put_stopped(s, y + 10, x + 2, w - 2, "run") && s->cstatus == ADH_SUCCESS && !tui_sim_redoable(s))
        put(y + 10, x, w, A_NORMAL, "  cycle  complete");
}

static void draw_state(const tui_sim *s, const tui_view *v, int y, int x, int w)
{
    if (tui_sim_mode(s) == ADH_MODE_TIME) {
        draw_time_state(s, v, y, x, w);
        return;
    }
    if (tui_sim_mode(s) == ADH_MODE_STATIC) {
        draw_curve_state(s, v, y, x, w);
        return;
    }
    const adh_obs *o = tui_sim_row(s);
    char a[64], b[320];   /* "%.2f s" of any double fits: never cut */
    size_t nrows;
    const adh_obs *rows = tui_sim_rows(s, &nrows);
    put(y, x, w, A_BOLD, " State");
    if (!o) {
        q(v, s->start, ADH_Q_LENGTH, a, sizeof a);
        put(y + 1, x, w, A_NORMAL, "  h0     %s start position, not solved yet", col12(a));
        put_wrapped(y + 2, x + 2, w - 2, 3, A_NORMAL, "Press f to approach by d, r to run to the turning "
                    "point, ? for every key. Edits change the numbers at the left at once; a solve starts only "
                    "when you step.");
    } else {
        draw_point_rows(o, 1, v, y, x, w);
        if (v->no_clock)
            snprintf(b, sizeof b, "time masked");
        else if (o->seconds < 1e-3)
            snprintf(b, sizeof b, "%.0f us", o->seconds * 1e6);
        else if (o->seconds < 1)
            snprintf(b, sizeof b, "%.1f ms", o->seconds * 1e3);
        else
            snprintf(b, sizeof b, "%.2f s", o->seconds);
        put(y + 6, x, w, A_NORMAL, "  step   %zu iteration%s, %s%s", o->iters, o->iters == 1 ? "" : "s", b,
            o->converged ? "" : ", NOT converged");
        /* with several turns, which one the branch goes to or comes from
         * (the turn field shows the whole list) */
        size_t nt;
        const double *turns = tui_sim_turns(s, &nt);
        char t[128] = "";
        if (nt > 1 && o->branch > 0 && !isnan(s->turn))
            snprintf(t, sizeof t, ", to %s", adh_qtext(s->turn, ADH_Q_LENGTH).s);
        else if (nt > 1 && o->path >= 1 && (size_t)o->path <= nt)
            snprintf(t, sizeof t, " from turn %d of %zu, %s", o->path, nt, adh_qtext(turns[o->path - 1], ADH_Q_LENGTH).s);
        if (o->branch > 0)
            put(y + 7, x, w, A_NORMAL, "  branch loading (approaching)%s", t);
        else if (*t)
            put(y + 7, x, w, A_NORMAL, "  branch unloading%s", t);
        else
            put(y + 7, x, w, A_NORMAL, "  branch unloading (retracting), path %d", o->path);
    }
    put(y + 8, x, w, A_NORMAL, "  mode   relaxation (m: static), %s", v->activity);
    size_t bad = 0;
    for (size_t i = 0; i < nrows; i++)
        bad += !rows[i].converged;
    q(v, s->start, ADH_Q_LENGTH, a, sizeof a);
    put(y + 9, x, w, A_NORMAL, "  path   %zu state%s, %zu to redo; start %s", nrows, nrows == 1 ? "" : "s",
        tui_sim_redoable(s), a);
    if (s->warn[0])
        put(y + 10, x, w, A_BOLD, "  ! %s", s->warn);
    else if (bad)
        put(y + 10, x, w, A_BOLD, "  ! %zu step%s on this path did not converge", bad, bad == 1 ? "" : "s");
    else if (s->gridwarn[0]) {
        char msg[TUI_SIM_WHY_LEN + 4];
        snprintf(msg, sizeof msg, "! %s", s->gridwarn);
        put_wrapped(y + 10, x + 2, w - 2, 2, A_BOLD, msg);
    }
}

/* The preview's column of position h0 (past the axis: the last). */
static int preview_col(double h0, double xmin, double xmax, int pw)
{
    int c = (int)lround((h0 - xmin) / (xmax - xmin) * (pw - 1));
    return c < 0 ? 0 : c > pw - 1 ? pw - 1 : c;
}

/* The position axis's right end: a soft spring's snap-out lands where the
 * base is, a millimetre out, and the whole contact then sat in one column
 * (as force.png's did): force.png's end, past the last row or measured
 * point where the force reaches 1 % of its span, when that is under a
 * tenth of the rows' span; else xmax. */
static double preview_right(const adh_obs *rows, size_t n, const adh_measured *meas, double span, double xmin,
                            double xmax)
{
    double active = xmin;
    for (size_t i = 0; i < n; i++)
        if (fabs(rows[i].F) >= 0.01 * span && rows[i].h0 > active)
            active = rows[i].h0;
    for (const adh_measured *m = meas; m; m = m->next)
        for (size_t i = 0; i < m->n; i++)
            active = fmax(active, m->h0[i]);
    double right = adh_plot_active_right(active, xmin, xmax);
    return right - xmin < 0.1 * (xmax - xmin) ? right : xmax;
}

/* The force-position curve so far, drawn with characters: '+' loading,
 * 'o' unloading, '@' the current state, '-' the zero-force line; in static
 * mode '*' a stable point of the equilibrium curve and '.' an unstable one. */
static void draw_preview(const tui_sim *s, const tui_view *v, int y0, int x0, int h, int w)
{
    size_t n;
    const adh_obs *rows = tui_sim_rows(s, &n);
    const adh_obs *cur = tui_sim_row(s);
    if (h < 3 || w < 30)
        return;
    /* short of rows (24 lines): the plot's rows, its range in the heading */
    int compact = h < 5;
    int stat = tui_sim_mode(s) == ADH_MODE_STATIC;
    const adh_measured *meas = v->measured && v->measured->n ? v->measured : NULL;
    /* through a spring h0 is where the sphere is, the base drives it (h0 =
     * base + F/k), as force.png's axis says; the relaxation (m from the
     * static curve keeps the key) has none */
    const char *pos = tui_sim_curve_mode(s) && isfinite(s->cfg.spec.time.spring) ? "sphere" : "drive";
    if (stat)
        put(y0, x0, w, A_BOLD, " %s%s%s  * stable  . unstable  @ now%s", compact ? "Equilibrium F against h0" :
            "Equilibrium force F against ", compact ? "" : pos, compact ? "" : " position h0 ", meas ? "  x measured" : "");
    else
        put(y0, x0, w, A_BOLD, " %s%s%s  + loading  o unloading  @ now%s", compact ? "F against h0" : "Force F against ",
            compact ? "" : pos, compact ? "" : " position h0 ", meas ? "  x measured" : "");
    const int lab = 11;
    int pw = w - lab - 1, ph = h - (compact ? 1 : 2);
    if (n == 0 && !meas) {
        put(y0 + ph / 2, x0 + lab, pw, A_NORMAL, "%s", stat ? "(the equilibrium curve appears here as it is solved)"
                                                          : "(the force-position curve appears here as you step)");
        return;
    }
    double xmin = INFINITY, xmax = -INFINITY, ymin = 0, ymax = 0;
    for (size_t i = 0; i < n; i++) {
        xmin = fmin(xmin, rows[i].h0);
        xmax = fmax(xmax, rows[i].h0);
        ymin = fmin(ymin, rows[i].F);
        ymax = fmax(ymax, rows[i].F);
    }
    for (const adh_measured *m = meas; m; m = m->next)   /* every --data file */
    for (size_t i = 0; i < m->n; i++) {
        xmin = fmin(xmin, m->h0[i]);
        xmax = fmax(xmax, m->h0[i]);
        ymin = fmin(ymin, m->F[i]);
        ymax = fmax(ymax, m->F[i]);
    }
    if (xmax - xmin < s->cfg.spec.proto.step) {
        xmin -= s->cfg.spec.proto.step;
        xmax += s->cfg.spec.proto.step;
    }
    if (ymax - ymin <= 0) {
        ymax = 1e-12;
        ymin = -1e-12;
    }
    double xall = xmax;   /* what lies past the axis's end is drawn in its last column */
    xmax = preview_right(rows, n, meas, ymax - ymin, xmin, xmax);
    char *grid = malloc((size_t)(pw * ph));
    if (!grid)
        return;
    memset(grid, ' ', (size_t)(pw * ph));
    int zero = (int)lround(ymax / (ymax - ymin) * (ph - 1));
    for (int c = 0; c < pw; c++)
        grid[zero * pw + c] = '-';
    /* the measurement under the computed path: where they meet, the model shows */
    for (const adh_measured *m = meas; m; m = m->next)
    for (size_t i = 0; i < m->n; i++) {
        int c = preview_col(m->h0[i], xmin, xmax, pw);
        int r = (int)lround((ymax - m->F[i]) / (ymax - ymin) * (ph - 1));
        grid[r * pw + c] = 'x';
    }
    /* loading first, so unloading shows where they meet; in static mode
     * unstable first, so the stable states (what an experiment sees) show */
    for (int pass = 0; pass < 2; pass++)
        for (size_t i = 0; i < n; i++) {
            int first = stat ? !rows[i].stable : rows[i].branch > 0;
            if ((pass == 0) != first)
                continue;
            int c = preview_col(rows[i].h0, xmin, xmax, pw);
            int r = (int)lround((ymax - rows[i].F) / (ymax - ymin) * (ph - 1));
            grid[r * pw + c] = stat ? (first ? '.' : '*') : first ? '+' : 'o';
        }
    if (cur) {
        int c = preview_col(cur->h0, xmin, xmax, pw);
        int r = (int)lround((ymax - cur->F) / (ymax - ymin) * (ph - 1));
        grid[r * pw + c] = '@';
    }
    char lbl[64];
    for (int r = 0; r < ph; r++) {
        lbl[0] = '\0';
        if (r == 0)
            q(v, ymax, ADH_Q_FORCE, lbl, sizeof lbl);
        else if (r == ph - 1)
            q(v, ymin, ADH_Q_FORCE, lbl, sizeof lbl);
        else if (r == zero)
            snprintf(lbl, sizeof lbl, "0");
        put(y0 + 1 + r, x0, lab, A_NORMAL, "%*s", lab - 1, lbl);
        put(y0 + 1 + r, x0 + lab - 1, 1, A_NORMAL, "|");
        put(y0 + 1 + r, x0 + lab, pw, A_NORMAL, "%.*s", pw, grid + r * pw);
    }
    free(grid);
    char lo[64], end[64], all[64], hi[160];
    q(v, xmin, ADH_Q_LENGTH, lo, sizeof lo);
    q(v, xmax, ADH_Q_LENGTH, end, sizeof end);
    q(v, xall, ADH_Q_LENGTH, all, sizeof all);
    snprintf(hi, sizeof hi, "%s%s%s", end, xall > xmax ? ", then to " : "", xall > xmax ? all : "");   /* the last column holds the rest */
    if (compact) {   /* the position axis in words, at the heading's end */
        char range[160];
        snprintf(range, sizeof range, "h0 %s to %s ", lo, hi);
        int rl = (int)strlen(range);
        if (rl < w - 40)
            put(y0, x0 + w - rl, rl, A_NORMAL, "%s", range);
        return;
    }
    int y = y0 + 1 + ph;
    /* the axis's labels never run into each other: the middle one goes
     * (or shortens) where the ends leave no room for it */
    int lol = (int)strlen(lo), hil = (int)strlen(hi);
    put(y, x0 + lab, pw, A_NORMAL, "%s", lo);
    const char *mid = pw - lol - hil >= 32 ? "h0 (approach <- -> retract)" : pw - lol - hil >= 6 ? "h0" : "";
    int ml = (int)strlen(mid), mx = lab + pw / 2 - (ml + 1) / 2;
    if (mx < lab + lol + 1)
        mx = lab + lol + 1;
    if (ml)
        put(y, x0 + mx, ml, A_NORMAL, "%s", mid);
    put(y, x0 + lab + pw - hil, hil, A_NORMAL, "%s", hi);
    (void)v;
}

static void status_text(const tui_view *v, char *st, size_t len)
{
    char raw[1200];
    snprintf(raw, sizeof raw, "%s%s", v->status_error ? "error: " : "", v->status);
    if (v->utf8)
        micro_text(raw, st, len);
    else
        snprintf(st, len, "%s", raw);
}

/* The rows the status line takes above the key hints: at least one. */
static int status_rows(const tui_view *v, int W, int H)
{
    if (!v->status || !v->status[0])
        return 1;
    char st[1200];
    status_text(v, st, sizeof st);
    /* a short screen keeps its rows for the state and the parameters */
    int n = wrap_text(0, 0, W, H >= 24 ? 3 : 1, 0, st, 0);
    return n > 1 ? n : 1;
}

void tui_draw(const tui_sim *s, const tui_view *v)
{
    erase();
    int W = COLS, H = LINES;
    put(0, 0, W, A_REVERSE, "%-*s", W, " adhere: two elastic spheres held by a Lennard-Jones surface force");
    put(0, W - 17 > 0 ? W - 17 : 0, 17, A_REVERSE, "  ? help  q quit ");
    int stat = tui_sim_curve_mode(s);
    /* below the fields: nine of them (physical time's can take one more) */
    int dy = params_shown(s) > 9 ? params_shown(s) - 9 : 0;
    if (W >= 80) {
        int lw = W / 2 - 2 < 44 ? W / 2 - 2 : 44;
        draw_params(s, v, 1, 0, lw);
        draw_derived(s, v, 11 + dy, 0, lw);
        draw_state(s, v, 1, lw + 1, W - lw - 1);
        if (!stat)
            draw_cycle(s, v, 13, lw + 1, W - lw - 1);
        /* the preview in the rows left: whole from 25 lines (more with
         * physical time's fields), its plot alone at 23 and 24, else a
         * word on how to see it */
        /* above the status line, however many rows it wraps to: a plot
         * row under it would lose its axis label */
        int ph = H - 1 - status_rows(v, W, H) - 18 - dy;
        if (ph >= 3)
            draw_preview(s, v, 18 + dy, 0, ph, W);
        else if (H - 2 - 18 - dy >= 1)
            put(18 + dy, 0, W, A_NORMAL, " (the force preview needs %d lines: a taller window shows it)", 23 + dy);
    } else if (v->params_first && H < 40) {
        /* Narrow and short, a parameter being worked on: the parameters
         * and what they give come first. */
        draw_params(s, v, 1, 0, W);
        draw_derived(s, v, 11 + dy, 0, W);
        draw_state(s, v, 17 + dy, 0, W);
    } else {
        /* Narrow: one column, the state first, then the cycle and the
         * models while there is room; the parameters stay in view in
         * their compact form at the bottom. */
        int np = draw_params_compact(s, v, 0, 0, W, 0);
        /* under the title however few the rows (20x5 in physical time
         * drew the parameters over it: pb was 0) */
        int pb = H - 2 - np > 1 ? H - 2 - np : 1, y = stat ? 15 : 13;
        clip_bottom = pb;
        draw_state(s, v, 1, 0, W);
        if (!stat) {
            draw_cycle(s, v, y, 0, W);
            y += 6;
        }
        if (pb - y >= 6 + 5) {
            draw_derived(s, v, y, 0, W);
            y += 7;
        }
        clip_bottom = 1 << 30;
        if (pb - y >= 5)
            draw_preview(s, v, y, 0, pb - y, W);
        draw_params_compact(s, v, pb, 0, W, 1);
    }
    /* the status line in plain words, wrapped upwards over what is above it
     * when it does not fit (an error's advice comes last), then the prompt
     * or the key hints */
    if (v->status && v->status[0]) {
        char st[1200];
        status_text(v, st, sizeof st);
        int n = status_rows(v, W, H);
        for (int y = H - 1 - n; y < H - 1; y++)
            put(y, 0, W, A_NORMAL, "%-*s", W, "");
        wrap_text(H - 1 - n, 0, W, n, v->status_error ? A_BOLD : A_NORMAL, st, 1);
    }
    if (v->prompt)
        put(H - 1, 0, W, A_REVERSE, "%-*s", W, v->prompt);
    else if (v->count)
        put(H - 1, 0, W, A_REVERSE, "%-*s", W, "");
    else if (tui_sim_mode(s) == ADH_MODE_TIME)
        put(H - 1, 0, W, A_REVERSE, "%-*s", W,
            " f next  b back  r run  u/U back/fwd  x reset  p plots  : cmd  ? help  q quit");
    else if (tui_sim_mode(s) == ADH_MODE_STATIC)
        put(H - 1, 0, W, A_REVERSE, "%-*s", W,
            " f next  b back  r run  u/U back/fwd  x reset  m relax  p plots  : cmd  ? help  q quit");
    else
        put(H - 1, 0, W, A_REVERSE, "%-*s", W,
            " f in  b out  r run  u undo  U redo  x reset  p plots  : command  ? help  q quit");
    if (v->count)
        put(H - 1, 0, W, A_REVERSE, " count %ld: f, b, u, U, + or - repeats that many times; Esc cancels", v->count);
}

/* Appends "  KEY      what" to lines, the description wrapped at blanks to
 * fit w columns, continuation lines indented under it. */
enum { HELP_LINE = 512 };   /* bytes of a help line: the widest terminal's row is cut by put() */

static int help_entry(char lines[][HELP_LINE], int n, int max, int w, const char *key, const char *what)
{
    const int indent = 19;
    int room = w - indent > 20 ? w - indent : 20;
    if (room > HELP_LINE - 70)   /* after a key column of up to 3 + 63 bytes */
        room = HELP_LINE - 70;
    const char *p = what;
    int first = 1;
    while (*p && n < max) {
        int len = (int)strlen(p);
        int take = len;
        if (len > room) {
            take = room;
            while (take > 0 && p[take] != ' ')
                take--;
            if (take == 0)
                take = room;
        }
        /* key column, then take bytes of the text (take <= room fits) */
        int col = snprintf(lines[n], HELP_LINE, "  %-16.63s ", first ? key : "");
        memcpy(lines[n] + col, p, (size_t)take);
        lines[n++][col + take] = '\0';
        first = 0;
        p += take;
        while (*p == ' ')
            p++;
    }
    return n;
}

int tui_draw_help(const tui_view *v)
{
    erase();
    int W = COLS, H = LINES;
    char name[32], msg[1024];
    /* Lines first, so the screen can start anywhere in them. */
    enum { MAX = 160 };
    static char lines[MAX][HELP_LINE];
    int n = 0;
    /* One line per action, its keys together, with the first key's words:
     * the aliases' own lines ("as f") would only repeat it. */
    for (const tui_key_binding *b = tui_key_table; b->action != ACT_NONE; b++) {
        int seen = 0;
        for (const tui_key_binding *e = tui_key_table; e < b; e++)
            seen |= e->action == b->action;
        if (seen)
            continue;
        char keys[64] = "";
        for (const tui_key_binding *e = b; e->action != ACT_NONE; e++)
            if (e->action == b->action) {
                tui_replay_key_name(e->key, name, sizeof name);
                size_t l = strlen(keys), m = strlen(name);
                if (l + 1 + m < sizeof keys) {   /* a key that does not fit is left out whole */
                    if (l)
                        keys[l++] = ' ';
                    memcpy(keys + l, name, m + 1);
                }
            }
        n = help_entry(lines, n, MAX, W, keys, b->what);
    }
    n = help_entry(lines, n, MAX, W, "1-9", "digits make a count for the next key: 10f steps ten times, 3j moves down three");
    if (n < MAX)
        snprintf(lines[n++], HELP_LINE, " ");
    n = help_entry(lines, n, MAX, W, ":set", "NAME VALUE sets a parameter: E A z0 R eps d N spacing turn, or any "
                   "key of the run as a scene writes it (protocol.dwell, grid.fine_band); values take units: 2GPa "
                   "0.4nm 1e-19J 10um; a bare number is in the unit the screen shows (nm for a position)");
    snprintf(msg, sizeof msg, "changing E, A, z0, R, %s, d, N or the spacing starts a new path from the "
             "start; turn only moves where r stops loading, and takes a list (1nm,0nm,-2nm): r follows each "
             "turn, shallowest first, as --batch does", gk(v, "\xce\xb5", "eps"));
    n = help_entry(lines, n, MAX, W, "", msg);
    if (n < MAX)
        snprintf(lines[n++], HELP_LINE, " ");
    snprintf(msg, sizeof msg, "m switches to the equilibrium curve, solved point by point by Newton's method and "
             "continuation through its folds: f (or r) solves the next point, b and u walk back over points "
             "already solved (the curve is the same whichever way the drive moves: nothing is solved again), "
             "U and f walk forward again. Changing E, A, z0, R, d, N, the spacing or turn starts the curve "
             "again; %s does not touch it. Each mode keeps its path or curve across m.", gk(v, "\xce\xb5", "eps"));
    n = help_entry(lines, n, MAX, W, "static", msg);
    put(0, 0, W, A_REVERSE, "%-*s", W, " adhere keys  (PgUp/PgDn scroll, any other key returns)");
    int top = v->help_top;
    if (top > n - 1)
        top = n - 1;
    if (top < 0)
        top = 0;
    for (int i = 0; i + top < n && 1 + i < H; i++)
        put(1 + i, 0, W, A_NORMAL, "%s", lines[i + top]);
    return n;
}

/* adh_outfile_write's writer: the screen as it stands, one text line a row. */
static int screen_text(FILE *f, const void *ctx)
{
    (void)ctx;
    mbstate_t mbs;
    char line[8192];
    for (int y = 0; y < LINES; y++) {
        size_t len = 0, keep = 0;
        for (int x = 0; x < COLS; x++) {
            cchar_t cc;
            wchar_t wch[CCHARW_MAX + 1];
            attr_t attr;
            short pair;
            if (mvwin_wch(curscr, y, x, &cc) == ERR || getcchar(&cc, wch, &attr, &pair, NULL) == ERR)
                wch[0] = L' ', wch[1] = 0;
            for (int k = 0; wch[k] && k < CCHARW_MAX; k++) {
                char mb[MB_LEN_MAX];
                memset(&mbs, 0, sizeof mbs);
                size_t m = wcrtomb(mb, wch[k], &mbs);
                if (m == (size_t)-1) {
                    mb[0] = '?';
                    m = 1;
                }
                if (len + m < sizeof line) {
                    memcpy(line + len, mb, m);
                    len += m;
                }
            }
            if (wch[0] != L' ')
                keep = len;
        }
        fprintf(f, "%.*s\n", (int)keep, line);
    }
    return 0;
}

int tui_dump_screen(const char *path, char *why, size_t whylen)
{
    int e = adh_outfile_write(path, screen_text, NULL);
    char reason[1024];
    if (e)
        snprintf(why, whylen, "cannot write the screen to %s: %s", path, adh_outfile_reason(path, e, reason, sizeof reason));
    return e ? -1 : 0;
}
