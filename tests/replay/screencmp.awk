# Compares a screen with its golden: text exactly, numbers within tolerance.
#   awk -f screencmp.awk [-v tolfile=cases/NAME.tol] EXPECTED GOT
# Exit 0 when they agree; else 1, with "#" lines saying where they differ.
#
# A line equal to the golden's passes. Otherwise both are cut into text and
# numbers ([-+]?digits[.digits][e[-+]digits]): the texts must be equal (runs
# of blanks count as one, since a number's width moves what follows it) and
# each number within its tolerance of the golden's:
#   - by default one unit in the golden's last printed digit (-219.3 takes
#     -219.2 .. -219.4; 1562 takes 1561 .. 1563): the digit a different BLAS
#     or optimisation level may round the other way;
#   - more where tolfile says so, one rule a line, "REGEX TOLERANCE" (blank
#     or tab between; # starts a comment): the numbers inside the stretch of
#     a golden line that the (awk, extended) REGEX first matches may be off
#     by TOLERANCE, either "N%" of the golden's value, or "N" in the printed
#     unit, or "*" (any number: a count that follows from floating-point
#     accidents, such as how many continuation points). The largest
#     tolerance that applies wins.
#   A rule whose TOLERANCE is "line" lets the whole line differ (a plot
#     row drawn from such numbers); use it sparingly, and say why above it.
function isnum(s) { return s ~ /^[-+]?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?$/ }
# the unit of the last printed digit of s
function ulp(s,    m, e, d) {
    e = 0
    if (match(s, /[eE][-+]?[0-9]+$/)) { e = substr(s, RSTART + 1) + 0; s = substr(s, 1, RSTART - 1) }
    d = index(s, ".") ? length(s) - index(s, ".") : 0
    return 10 ^ (e - d)
}
# splits line into parts[1..n]: text and numbers alternating; returns n.
# at[j]: where number j starts in the line.
function cut(line, parts, at,    n, pre, off) {
    n = 0; off = 0
    while (match(line, /[-+]?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?/)) {
        pre = substr(line, 1, RSTART - 1)
        gsub(/ +/, " ", pre)
        parts[++n] = pre
        parts[++n] = substr(line, RSTART, RLENGTH)
        at[n] = off + RSTART
        off += RSTART + RLENGTH - 1
        line = substr(line, RSTART + RLENGTH)
    }
    gsub(/ +/, " ", line)
    parts[++n] = line
    return n
}
function abs(x) { return x < 0 ? -x : x }
BEGIN {
    nrules = 0
    if (tolfile != "") {
        while ((getline r < tolfile) > 0) {
            if (r ~ /^[ \t]*(#|$)/) continue
            if (!match(r, /[ \t]+[^ \t]+[ \t]*$/)) { print "#   bad rule in " tolfile ": " r; bad_rules = 1; continue }
            tol = substr(r, RSTART); gsub(/[ \t]/, "", tol)
            re[++nrules] = substr(r, 1, RSTART - 1); tl[nrules] = tol
        }
    }
}
FILENAME == ARGV[1] { want[++nw] = $0; next }
{ got[++ng] = $0 }
END {
    fails = bad_rules
    if (nw != ng) { printf "#   %d lines, the golden has %d\n", ng, nw; fails++ }
    for (i = 1; i <= nw && i <= ng; i++) {
        if (want[i] == got[i]) continue
        wholeline = 0; nhit = 0
        for (k = 1; k <= nrules; k++)
            if (match(want[i], re[k])) {
                if (tl[k] == "line") wholeline = 1
                hit[++nhit] = k; from[nhit] = RSTART; to[nhit] = RSTART + RLENGTH
            }
        if (wholeline) continue
        nwp = cut(want[i], wp, wat); ngp = cut(got[i], gp, gat)
        why = ""
        if (nwp != ngp) why = "not the same text"
        for (j = 1; why == "" && j <= nwp; j++) {
            if (j % 2) { if (wp[j] != gp[j]) why = "text differs" ; continue }
            lim = ulp(wp[j]); w = wp[j] + 0; anyn = 0
            for (h = 1; h <= nhit; h++) {
                if (wat[j] < from[h] || wat[j] >= to[h]) continue
                t = tl[hit[h]]
                if (t == "*") anyn = 1
                else if (t ~ /%$/) { v = substr(t, 1, length(t) - 1) / 100 * abs(w); if (v > lim) lim = v }
                else if (t + 0 > lim) lim = t + 0
            }
            if (anyn) continue
            if (abs(gp[j] - w) > lim * (1 + 1e-9))
                why = sprintf("%s is more than %g from the golden's %s", gp[j], lim, wp[j])
        }
        if (why != "") {
            printf "#   line %d: %s\n#   - %s\n#   + %s\n", i, why, want[i], got[i]
            if (++fails >= 20) break
        }
    }
    exit fails > 0
}
