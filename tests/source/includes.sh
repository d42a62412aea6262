#!/bin/sh
# The include graph: no circle between modules, and no arrow from a lower
# layer to a higher one (core < scene < plot < util < tui < cli; util is
# the drivers' small shared helpers, below them). Read from the
# #include "..." lines of src/ and include/, nothing compiled.
#
# A module is a layer and a base name: include/adhere/X.h and src/core/X.c
# are core/X, src/tui/sim.[ch] is tui/sim. An #include "adhere/X.h" points
# at core/X, "D/X.h" at D/X, a bare "X.h" at X in the including file's own
# directory. A module including itself (X.c its X.h) is no arrow.
#
# The analysis is checked first on a planted tree (a circle of three, an
# arrow up), so a test that finds nothing has shown it could.
. "$(dirname "$0")/../cli/lib.sh"
cd "${ADHERE_SRC:-.}"

# Arrows still to be removed by work under way elsewhere, as "FROM TO"
# lines: each must still be there (a stale entry fails: remove it), and
# the graph without them must pass. Empty: the test is strict.
KNOWN=${ADH_INCLUDES_KNOWN-""}

# edges ROOT: "FROM TO" for every #include "..." of ROOT's src/ and include/.
edges() {
    find "$1/src" "$1/include" -type f \( -name '*.c' -o -name '*.h' \) | sort |
        while IFS= read -r f; do
            sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$f" |
                awk -v f="${f#"$1"/}" '
                    function module(path, dir,   n, p, base) {
                        n = split(path, p, "/")
                        base = p[n]; sub(/\.[ch]$/, "", base)
                        if (n == 1) return dir "/" base
                        if (p[n - 1] == "adhere") return "core/" base
                        return p[n - 1] "/" base
                    }
                    BEGIN {
                        n = split(f, p, "/")
                        dir = p[1] == "include" ? "core" : p[n - 1]
                        from = module(f, dir)
                    }
                    { to = module($0, dir); if (to != from) print from, to }'
        done | sort -u
}

# analyse: reads "FROM TO" arrows, prints "up FROM TO" for each arrow from
# a lower layer to a higher one, "circle A B ... A" for one circle through
# each module that is on one (one line per circle found).
analyse() {
    awk '
        BEGIN { split("core scene plot util tui cli", L, " "); for (i in L) rank[L[i]] = i }
        function layer(m) { split(m, q, "/"); return q[1] }
        {
            if (!($1 in seen)) { seen[$1] = 1; nodes[++nn] = $1 }
            if (!($2 in seen)) { seen[$2] = 1; nodes[++nn] = $2 }
            out[$1] = out[$1] " " $2
            if (rank[layer($1)] < rank[layer($2)]) print "up", $1, $2
        }
        # A path from s back to s, breadth first (the shortest), or "".
        function cycle(s,   head, tail, queue, prev, u, k, n, nb, v, path) {
            head = tail = 0; split("", prev)
            queue[tail++] = s
            while (head < tail) {
                u = queue[head++]
                n = split(out[u], nb, " ")
                for (k = 1; k <= n; k++) {
                    v = nb[k]
                    if (v == s) {
                        path = s
                        for (; u != s; u = prev[u]) path = u " " path
                        return s " " path
                    }
                    if (!(v in prev) && v != s) { prev[v] = u; queue[tail++] = v }
                }
            }
            return ""
        }
        END {
            for (i = 1; i <= nn; i++) {
                if (nodes[i] in oncycle) continue
                c = cycle(nodes[i])
                if (c == "") continue
                n = split(c, m, " ")
                for (k = 1; k <= n; k++) oncycle[m[k]] = 1
                print "circle", c
            }
        }'
}

# without KNOWN: the arrows of stdin minus the known ones
without_known() {
    printf '%s\n' "$KNOWN" | awk 'NR == FNR { if (NF == 2) k[$1 " " $2] = 1; next } !(($1 " " $2) in k)' - "$1"
}

# The analysis on a planted tree: core/a -> core/b -> core/c -> core/a and
# core/c -> tui/screen (up), beside a clean cli/main -> core/a.
P="$TMP/planted"
mkdir -p "$P/include/adhere" "$P/src/core" "$P/src/tui" "$P/src/cli"
printf '#include "adhere/b.h"\n' >"$P/src/core/a.c"
printf '#include "adhere/a.h"\n' >"$P/include/adhere/a.h"
printf '  #  include "adhere/c.h"  /* indented */\n' >"$P/include/adhere/b.h"
printf '#include "adhere/a.h"\n#include "tui/screen.h"\n#include <stdio.h>\n' >"$P/src/core/c.c"
printf '#include "adhere/a.h"\n' >"$P/src/cli/main.c"
edges "$P" >"$TMP/planted.edges"
analyse <"$TMP/planted.edges" >"$TMP/planted.found"
check "the check finds a planted circle of three modules" grep -qx 'circle core/a core/b core/c core/a' "$TMP/planted.found"
check "the check finds a planted arrow from core up to tui" grep -qx 'up core/c tui/screen' "$TMP/planted.found"
check "the check finds nothing else in the planted tree (a module's own header is no arrow, <...> is not read)" \
    [ "$(wc -l <"$TMP/planted.found")" -eq 2 ]

# The real tree.
edges . >"$TMP/edges"
check "the include graph has arrows ($(wc -l <"$TMP/edges") read)" [ "$(wc -l <"$TMP/edges")" -gt 100 ]
printf '%s\n' "$KNOWN" | while read -r a b; do
    [ -n "$a" ] || continue
    if grep -qx "$a $b" "$TMP/edges"; then echo "ok - known arrow $a -> $b is still there (allowlisted)"; else
        echo "not ok - known arrow $a -> $b is gone: remove it from the allowlist"; fi
done >"$TMP/known"
while IFS= read -r line; do
    case "$line" in ok*) ok "${line#ok - }" ;; *) not_ok "${line#not ok - }" ;; esac
done <"$TMP/known"
without_known "$TMP/edges" | analyse >"$TMP/found"
ups=$(grep -c '^up ' "$TMP/found")
circles=$(grep -c '^circle ' "$TMP/found")
check "no arrow from a lower layer to a higher one (core < scene < plot < util < tui < cli)$(grep '^up ' "$TMP/found" | sed 's/^up \(.*\) \(.*\)/; \1 -> \2/' | tr -d '\n')" [ "$ups" -eq 0 ]
check "no circle between modules$(grep '^circle ' "$TMP/found" | sed 's/^circle //;s/ / -> /g;s/^/; /' | tr -d '\n')" [ "$circles" -eq 0 ]
done_testing
