#!/bin/sh
# The key table is one table: every key --list-keys prints must be in the
# man page's KEYS section and on the help screen, and every :set name the
# program knows must be in the REPLAY SCRIPTS section. Prints TAP; exits 1
# when any case failed.
set -u
here=$(cd "$(dirname "$0")" && pwd)
src=${ADHERE_SRC:-$(cd "$here/../.." && pwd)}
bin=${ADHERE_BIN:-$src/adhere}
man=$src/man/adhere.1
export LC_ALL=C.UTF-8
unset TERM
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n=0 failed=0
pass() { n=$((n + 1)); echo "ok $n - $*"; }
fail() { n=$((n + 1)); failed=$((failed + 1)); echo "not ok $n - $*"; }

"$bin" --list-keys >"$work/keys" 2>"$work/err"
rc=$?
if [ "$rc" = 0 ] && [ "$(wc -l <"$work/keys")" -ge 10 ]; then
    pass "--list-keys prints the key table ($(wc -l <"$work/keys") keys)"
else
    fail "--list-keys prints the key table (exit $rc: $(head -c 200 "$work/err"))"
fi
if awk -F'\t' 'NF != 2 || $1 == "" || $2 == "" { bad = 1 } END { exit bad }' "$work/keys"; then
    pass "every line is KEY, TAB, description"
else
    fail "every line is KEY, TAB, description"
fi

mandoc -T ascii "$man" | col -b | sed -n '/^KEYS/,/^REPLAY SCRIPTS/p' >"$work/man-keys"
printf '?\n' >"$work/help.keys"
(cd "$work" && "$bin" --replay=help.keys --screen=help.txt --size=120x60 </dev/null >/dev/null 2>&1)
cut -f1 "$work/keys" | sort -u | while IFS= read -r key; do
    if awk -v k="$key" '$1 == k { found = 1 } END { exit !found }' "$work/man-keys"; then
        echo "ok - man page KEYS lists $key"
    else
        echo "not ok - man page KEYS lists $key"
    fi
    # the help puts an action's keys together in its first 19 columns
    if cut -c1-19 "$work/help.txt" | tr -s ' ' '\n' | grep -qxF -- "$key"; then
        echo "ok - help screen lists $key"
    else
        echo "not ok - help screen lists $key"
    fi
done >"$work/results"
while IFS= read -r line; do
    case "$line" in
    "ok - "*) pass "${line#ok - }" ;;
    *) fail "${line#not ok - }" ;;
    esac
done <"$work/results"

# The :set names, as the program itself lists them in its error message.
printf ':set no-such-name 1\n' >"$work/names.keys"
(cd "$work" && "$bin" --replay=names.keys </dev/null >/dev/null 2>"$work/names.err")
names=$(sed -n 's/.*the names are //p' "$work/names.err")
if [ -n "$names" ]; then pass ":set lists its names ($names)"; else fail ":set lists its names"; fi
sed -n '/BEGIN REPLAY/,/END REPLAY/p' "$man" >"$work/man-replay"
for name in $names; do
    if grep -Eq "^\.Cm $name( |$)" "$work/man-replay"; then
        pass "man page REPLAY SCRIPTS documents :set $name"
    else
        fail "man page REPLAY SCRIPTS documents :set $name"
    fi
done

if mandoc -Tlint -W warning "$man" >"$work/lint" 2>&1; then
    pass "mandoc -Tlint -W warning is clean"
else
    fail "mandoc -Tlint -W warning is clean"
    sed 's/^/#   /' "$work/lint"
fi
echo "1..$n"
[ "$failed" -eq 0 ]
