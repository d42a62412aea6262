# Shared by the shell tests: TAP helpers and the program under test.
ADHERE=${ADHERE_BIN:-$PWD/adhere}
# the tests' seeded noise: an awk file of functions (srand48, urand,
# gauss), the same numbers under any awk; absolute, as tests cd
DRAND48=$(cd "$(dirname "$0")" && pwd)/drand48.awk
T=0
FAILED=0
ok() { T=$((T + 1)); echo "ok $T - $*"; }
not_ok() { T=$((T + 1)); FAILED=$((FAILED + 1)); echo "not ok $T - $*"; }
check() { # check "what" command...: ok when the command succeeds
    what=$1; shift
    if "$@"; then ok "$what"; else not_ok "$what"; fi
}
# wait_phase FILE LINE PID: until FILE (ADHERE_READY_FILE, see adhere(1))
# has the line LINE -- a phase's name, or "step" once the first step is
# solved -- a readiness signal, not a guessed delay. Gives up after 60 s or
# as soon as process PID is gone; 0 when the line came.
wait_phase() {
    _i=0
    while [ "$_i" -lt 600 ]; do
        grep -qx "$2" "$1" 2>/dev/null && return 0
        kill -0 "$3" 2>/dev/null || return 1
        sleep 0.1
        _i=$((_i + 1))
    done
    return 1
}
# need_gnuplot: a script that needs gnuplot reports one skip and stops
# without it (the runner fails a skip under CI=true; make deps installs it).
need_gnuplot() {
    command -v gnuplot >/dev/null 2>&1 && return 0
    echo "ok 1 # SKIP gnuplot is not installed"
    echo "1..1"
    exit 0
}
done_testing() { echo "1..$T"; [ "$FAILED" -eq 0 ]; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
