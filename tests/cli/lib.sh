# Shared by the shell tests: TAP helpers and the program under test.
ADHERE=${ADHERE_BIN:-$PWD/adhere}
T=0
FAILED=0
ok() { T=$((T + 1)); echo "ok $T - $*"; }
not_ok() { T=$((T + 1)); FAILED=$((FAILED + 1)); echo "not ok $T - $*"; }
check() { # check "what" command...: ok when the command succeeds
    what=$1; shift
    if "$@"; then ok "$what"; else not_ok "$what"; fi
}
done_testing() { echo "1..$T"; [ "$FAILED" -eq 0 ]; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
