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
# wait_file FILE SECONDS [PID]: until FILE exists (a readiness signal, not a
# guessed delay); gives up after SECONDS, or as soon as process PID is gone.
wait_file() {
    _i=0
    while [ ! -e "$1" ] && [ "$_i" -lt $(($2 * 20)) ]; do
        [ -n "${3:-}" ] && ! kill -0 "$3" 2>/dev/null && return 1
        sleep 0.05
        _i=$((_i + 1))
    done
    [ -e "$1" ]
}
done_testing() { echo "1..$T"; [ "$FAILED" -eq 0 ]; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
