#!/bin/sh
# The man pages lint clean and match the program: every long option that
# --help lists and every key --list-keys prints is documented in adhere.1.
. "$(dirname "$0")/../cli/lib.sh"
cd "${ADHERE_SRC:-.}"
for page in man/*.[0-9]; do
    out=$(mandoc -Tlint -W warning "$page" 2>&1)
    if [ -z "$out" ]; then ok "mandoc -Tlint -W warning $page is clean"; else not_ok "mandoc lint $page: $out"; fi
done
opts=$("$ADHERE" --help | grep -oE -- '--[a-zA-Z][a-zA-Z0-9-]+' | sort -u)
check "--help lists at least 30 long options" [ "$(echo "$opts" | wc -l)" -ge 30 ]
for o in $opts; do
    name=${o#--}
    # mdoc writes --name as \-name inside Fl, or \-\-name in text.
    esc=$(printf '%s' "$name" | sed 's/-/\\\\-/g')
    if grep -q -- "Fl \\\\-$esc" man/adhere.1 || grep -q -- "Fl -$name" man/adhere.1; then ok "$o is documented in adhere.1"; else not_ok "$o is missing from adhere.1 OPTIONS"; fi
done
# ... and the other way: every option adhere.1's OPTIONS documents is one
# --help lists (an option removed from the program leaves the page too).
sed -n '/BEGIN OPTIONS/,/END OPTIONS/p' man/adhere.1 | grep '^\.It Fl' |
    grep -oE 'Fl -[a-zA-Z][a-zA-Z0-9-]*' | sed 's/^Fl -/--/' | sort -u >"$TMP/mopts"
check "adhere.1's OPTIONS is read ($(wc -l <"$TMP/mopts") long options)" [ "$(wc -l <"$TMP/mopts")" -ge 30 ]
printf '%s\n' "$opts" >"$TMP/hopts"
while read -r o; do
    check "adhere.1 documents $o, which --help lists" grep -qxF -- "$o" "$TMP/hopts"
done <"$TMP/mopts"
# Every option's help starts in the one column (a flag too long for it
# stands on a line of its own, its help below).
"$ADHERE" --help | grep -E '^ +-' | grep -vE '^  .{28} [^ ]|^  (-[A-Za-z], |    )--[^ ]+$' >"$TMP/overflow"
check "--help's option lines keep the help's column ($(wc -l <"$TMP/overflow") do not)" [ ! -s "$TMP/overflow" ]
# A short option goes with the same long one in both: '-E, --modulus'.
"$ADHERE" --help | sed -nE 's/^ +-([A-Za-z]), --([a-zA-Z0-9-]+).*/\1 \2/p' >"$TMP/short"
check "--help lists short options ($(wc -l <"$TMP/short"))" [ "$(wc -l <"$TMP/short")" -ge 10 ]
while read -r c long; do
    esc=$(printf '%s' "$long" | sed 's/-/\\\\-/g')
    check "adhere.1 gives -$c with --$long" grep -qE -- "^\.It Fl $c , Fl (-|\\\\-)$esc( |$)" man/adhere.1
done <"$TMP/short"
# EXIT STATUS gives every status src/cli/exit.h names, and a signal's
# 128 + its number for the three the drivers hear (SIGHUP, SIGINT, SIGTERM).
exitsec=$(sed -n '/^\.Sh EXIT STATUS/,/^\.Sh /p' man/adhere.1)
codes=$(sed -nE 's/^ *CLI_EXIT_[A-Z]+ = ([0-9]+).*/\1/p' src/cli/exit.h)
check "src/cli/exit.h's statuses are read ($(echo $codes))" [ "$(echo "$codes" | wc -l)" -ge 4 ]
for code in $codes 129 143; do
    check "adhere.1's EXIT STATUS gives $code" sh -c 'printf "%s\n" "$1" | grep -qE "^\.It ([0-9]+ , )*$2( |$)"' _ "$exitsec" "$code"
done
# FILES names every file adhere writes in DIR: the names src/plot/outdir.c
# owns (the ones it removes or refuses to replace), one list for every mode.
sed -n '/^static const char \*const owned\[\]/,/};/p' src/plot/outdir.c |
    grep -oE '"[a-z.-]+\.(tsv|png|log|scene)"' | tr -d '"' >"$TMP/owned"
check "outdir.c's owned names are read ($(wc -l <"$TMP/owned"))" [ "$(wc -l <"$TMP/owned")" -ge 25 ]
filesec=$(sed -n '/^\.Sh FILES/,/^\.Sh /p' man/adhere.1)
while read -r f; do
    check "adhere.1's FILES names $f" sh -c 'printf "%s\n" "$1" | grep -qF -- "$2"' _ "$filesec" "$f"
done <"$TMP/owned"
check "adhere.1's FILES names the manifest" sh -c 'printf "%s\n" "$1" | grep -qF "DIR/.adhere-manifest"' _ "$filesec"
# ENVIRONMENT gives every variable of the program's own (ADHERE_*) that
# the sources read, and the TMPDIR its figures are drawn in.
grep -rhoE 'getenv\("[A-Z_]+"\)' src | sed -E 's/getenv\("([A-Z_]+)"\)/\1/' | sort -u |
    grep -E '^(ADHERE_|TMPDIR$)' >"$TMP/envs"
check "the sources' environment variables are read ($(echo $(cat "$TMP/envs")))" [ "$(wc -l <"$TMP/envs")" -ge 3 ]
envsec=$(sed -n '/^\.Sh ENVIRONMENT/,/^\.Sh /p' man/adhere.1)
while read -r v; do
    check "adhere.1's ENVIRONMENT gives $v" sh -c 'printf "%s\n" "$1" | grep -qx "\.It Ev $2"' _ "$envsec" "$v"
done <"$TMP/envs"
# Every option the parser accepts is in --help: the table is the same one, but
# check that an option from each family is accepted, so the table is live.
for o in --no-clock --quiet --no-plot; do
    "$ADHERE" "$o" --help >/dev/null 2>&1 && ok "$o is accepted" || not_ok "$o is not accepted"
done
keys=$("$ADHERE" --list-keys | cut -f1)
check "--list-keys prints the key table" [ -n "$keys" ]
keysec=$(sed -n '/^\.Sh KEYS/,/^\.Sh /p' man/adhere.1)
# read from a file, not a pipe: a loop in a pipeline runs in a subshell,
# and its failures would not reach done_testing's exit status
printf '%s\n' "$keys" >"$TMP/keys"
while IFS= read -r k; do
    [ -n "$k" ] || continue
    esc=$(printf '%s' "$k" | sed 's/[][\.*^$]/\\&/g; s/-/\\\\-/g')
    if printf '%s' "$keysec" | grep -q -- "$esc"; then ok "key '$k' is in the KEYS section"; else not_ok "key '$k' is missing from the KEYS section"; fi
done <"$TMP/keys"
# Every scene key is documented under its section in adhere-scene.5, and
# the page documents no key the parser refuses. The keys are read from the
# configuration's own table (keys[] in src/scene/configset.c, the one every
# scene, flag and TUI edit is set through: no option prints it); a scene
# may hold those marked S.
grep -oE '\{ \{ "[a-z]+\.[A-Za-z0-9_]+", S[ |,]' src/scene/configset.c |
    sed -E 's/\{ \{ "([a-z]+)\.([^"]+)".*/\1 \2/' >"$TMP/skeys"
check "configset.c's key table is read ($(wc -l <"$TMP/skeys") scene keys)" [ "$(wc -l <"$TMP/skeys")" -ge 25 ]
awk '/^\.Ss \[[a-z]+\]/ { sec = $2; gsub(/[][]/, "", sec); next }
     /^\.S[hs] / { sec = "" }
     sec != "" && /^\.It Cm [A-Za-z0-9_]+ No =/ { print sec, $3 }' man/adhere-scene.5 >"$TMP/mkeys"
while read -r sec key; do
    check "scene key $key is documented under [$sec] in adhere-scene.5" grep -qxF "$sec $key" "$TMP/mkeys"
done <"$TMP/skeys"
while read -r sec key; do
    check "adhere-scene.5's [$sec] $key is a key the parser takes" grep -qxF "$sec $key" "$TMP/skeys"
done <"$TMP/mkeys"
done_testing
