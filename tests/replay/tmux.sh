#!/bin/sh
# Through a real terminal, as a person would: tmux runs adhere, send-keys
# types, capture-pane reads the screen. Skipped only when tmux is absent
# (a skip, which fails the run under CI=true). Prints TAP; exits 1 when any
# case failed.
set -u
here=$(cd "$(dirname "$0")" && pwd)
src=${ADHERE_SRC:-$(cd "$here/../.." && pwd)}
bin=${ADHERE_BIN:-$src/adhere}
if ! command -v tmux >/dev/null 2>&1; then
    echo "ok 1 # SKIP tmux is not installed (make deps installs it)"
    echo "1..1"
    exit 0
fi
work=$(mktemp -d)
# One server per session started: a server being killed cannot take the next.
k=0
sock=adhere-test-$$-$k
T() { tmux -L "$sock" -f /dev/null "$@"; }
trap 'T kill-server 2>/dev/null; rm -rf "$work"' EXIT
n=0 failed=0
pass() { n=$((n + 1)); echo "ok $n - $*"; }
fail() { n=$((n + 1)); failed=$((failed + 1)); echo "not ok $n - $*"; }

screen() { T capture-pane -p -t t; }
# wait_for TEXT [SECONDS]: until the pane shows TEXT (a fixed string).
wait_for() {
    i=0
    limit=$((${2:-10} * 10))
    while [ "$i" -lt "$limit" ]; do
        screen | grep -qF -- "$1" && return 0
        sleep 0.1
        i=$((i + 1))
    done
    echo "#   waited in vain for: $1"
    screen | sed 's/^/#   | /'
    return 1
}
check() { what=$1; shift; if "$@"; then pass "$what"; else fail "$what"; fi; }
# start [LOCALE]: a fresh session running adhere in a 100x32 terminal
# (LC_ALL C.UTF-8 unless given); its exit status lands in $work/exit.
start() {
    rm -f "$work/exit" "$work/stty"
    T kill-server 2>/dev/null
    k=$((k + 1))
    sock=adhere-test-$$-$k
    T new-session -d -s t -x 100 -y 32 \
        "cd '$work' && LC_ALL=${1:-C.UTF-8} '$bin' 2>'$work/stderr'; echo \$? >'$work/exit'; stty -a >'$work/stty'; sleep 60"
}
exit_status() {
    i=0
    while [ ! -s "$work/exit" ] && [ "$i" -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
    cat "$work/exit" 2>/dev/null
}
type_cmd() { T send-keys -t t ':'; T send-keys -t t -l "$1"; T send-keys -t t Enter; }

start
check "the TUI opens in a terminal" wait_for "? lists every key"
type_cmd "set N 100"
type_cmd "set spacing 10nm"
type_cmd "set eps 10pm"
type_cmd "set d 0.5nm"
check "the : prompt sets parameters, echoed in the unit the panel shows (nm)" wait_for "d = 0.5 nm:"
T send-keys -t t f
check "f steps in" wait_for "approached to h0 = 16.5 nm"
T send-keys -t t -l 10f
check "a count repeats: 10f" wait_for "approached to h0 = 11.5 nm"
T send-keys -t t u
check "u undoes" wait_for "undid 1 step: back at h0 = 12 nm"
T send-keys -t t Enter
T send-keys -t t -l 1GPa
T send-keys -t t Enter
check "Enter edits E, sigma follows" wait_for "σ 2.251"
T send-keys -t t Enter
T send-keys -t t -l abc
T send-keys -t t Enter
check "a bad typed value is named" wait_for "error: E: 'abc' is not a number"
check "and changes nothing" sh -c "tmux -L '$sock' capture-pane -p -t t | grep -qF '>E     1 GPa'"
# A UTF-8 character typed at a prompt (a replay script is ASCII; a person's
# terminal is not): the micro sign the panel shows beside R, and a file
# name's accents. They were dropped: 5um with the micro sign set R = 5 m,
# and resume.tsv with accents was written as rsum.tsv.
type_cmd "set R 5µm"
check "the : prompt takes the micro sign the panel shows: R = 5 µm" wait_for "R = 5 µm:"
T send-keys -t t Down Down Down Enter
T send-keys -t t -l "7µmµ"
T send-keys -t t BSpace Enter
check "and so does an Enter edit, <BS> taking the whole character: R = 7 µm" wait_for "R = 7 µm:"
type_cmd "rows résumé.tsv"
check "a file name with accents is written under that name" wait_for "rows written to résumé.tsv"
check "... résumé.tsv, not rsum.tsv" sh -c "[ -s '$work/résumé.tsv' ] && [ ! -e '$work/rsum.tsv' ]"
type_cmd "set R 10um"
T send-keys -t t Up Up Up
T send-keys -t t '?'
check "? shows the help" wait_for "adhere keys"
T send-keys -t t Space
check "any key leaves the help" wait_for "Parameters"

# A long run (small d, tight eps) so there is time to pause it: ~10 CPU s
# to the turn at d = 0.05 nm and eps = 0.1 pm reached it before the Space
# at load 10, and the key then paused nothing; ~20 times that now (it is
# paused, then quit: the length costs nothing).
type_cmd "set d 0.01nm"
type_cmd "set eps 0.02pm"
T send-keys -t t r
check "r runs" wait_for "running to the turn"
# a resize during the run redraws and lets it go on (it paused the run, as
# a key does: the window changed, not the user's mind)
T resize-window -t t -x 90 -y 30
at90() { [ "$(screen | head -1 | wc -L)" -le 90 ] && screen | head -1 | grep -q ' ? help  q quit *$'; }
i=0
while ! at90 && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
check "a resize during a run redraws at the new size and does not pause it" sh -c "tmux -L '$sock' capture-pane -p -t t | head -1 | grep -q ' ? help  q quit *\$' && ! tmux -L '$sock' capture-pane -p -t t | grep -q 'paused'"
T send-keys -t t Space
check "a key pauses the run" wait_for "paused at h0"

T resize-window -t t -x 80 -y 24
# redrawn: the title bar ends at column 80 with its key hints
resized() { [ "$(screen | head -1 | wc -L)" -le 80 ] && screen | head -1 | grep -q ' ? help  q quit *$'; }
wait_until() {  # wait_until SECONDS COMMAND...: until COMMAND succeeds
    i=0 limit=$(($1 * 10)); shift
    while ! "$@"; do
        [ "$i" -ge "$limit" ] && { screen | sed 's/^/#   | /'; return 1; }
        sleep 0.1; i=$((i + 1))
    done
}
check "a resize redraws at the new size" wait_until 10 resized
check "and nothing is wider than 80 columns" [ "$(screen | wc -L)" -le 80 ]
# a tiny window: the compact parameters had no rows left and were drawn
# from row 0 over the title (pb = H - 2 - their rows < 1)
T resize-window -t t -x 20 -y 5
check "a 20x5 window keeps its title on the first row" wait_until 10 sh -c "tmux -L '$sock' capture-pane -p -t t | head -1 | grep -q '^ ad  ? help  q quit\$'"
T resize-window -t t -x 80 -y 24

T send-keys -t t q
check "q quits with status 0" [ "$(exit_status)" = 0 ]
check "the terminal is restored (the TUI is gone from the screen)" sh -c "! tmux -L '$sock' capture-pane -p -t t | grep -q 'Parameters'"

# An ASCII terminal (LC_ALL=C) names sigma, mu and gamma in letters: at
# 100 columns the derived panel's line was cut in gamma's unit ("mJ/m^")
start C
check "LC_ALL=C at 100 columns: the derived panel shows gamma with its unit whole, mJ/m^2" \
    wait_for "  sigma 7.503  mu 6.084  gamma 7.958 mJ/m^2"
# the heading's key hints and the Maugis-Dugdale lambda were cut there:
# "Parameters  (Up/Down select, Enter edit" with its bracket open, and
# "(lambda 7.06)" gone; now fewer hints with the bracket closed, and lambda
# after the M-D jump-out where the pull-off's line has no room for it
check "... the heading's hints whole, the bracket closed: (Up/Down select, Enter edit)" \
    sh -c "tmux -L '$sock' capture-pane -p -t t | grep -qF ' Parameters  (Up/Down select, Enter edit) '"
check "... the M-D line keeps lambda: M-D jump-out 5.408 nm (lambda 7.06)" \
    sh -c "tmux -L '$sock' capture-pane -p -t t | grep -qF '  M-D jump-out 5.408 nm (lambda 7.06)'"
T resize-window -t t -x 80 -y 32
check "... and at 80 columns (mu makes room): sigma 7.503  gamma 7.958 mJ/m^2" wait_for "  sigma 7.503  gamma 7.958 mJ/m^2"
check "... the heading's bracket closed: (Up/Down select)" \
    sh -c "tmux -L '$sock' capture-pane -p -t t | grep -qF ' Parameters  (Up/Down select) '"
check "... and lambda kept: (lambda 7.06)" \
    sh -c "tmux -L '$sock' capture-pane -p -t t | grep -qF '(lambda 7.06)'"
T send-keys -t t q
check "... q quits with status 0" [ "$(exit_status)" = 0 ]

start
wait_for "? lists every key" >/dev/null
T send-keys -t t C-c
check "C-c (SIGINT) ends it with status 130" [ "$(exit_status)" = 130 ]
check "and the terminal is restored" sh -c "! tmux -L '$sock' capture-pane -p -t t | grep -q 'Parameters'"
check "and it says why on stderr" grep -q "stopped by signal 2" "$work/stderr"

start
wait_for "? lists every key" >/dev/null
type_cmd "set d 0.01nm"   # a run that cannot end before the signal comes
T send-keys -t t r
wait_for "running to the turn" >/dev/null
# the pane runs sh, whose child is adhere
pid=$(pgrep -P "$(T display -p -t t '#{pane_pid}')" | head -1)
check "found the running adhere" [ -n "$pid" ]
kill -TERM "$pid" 2>/dev/null
check "SIGTERM during a run ends it with status 143 (128 + 15), as --batch" [ "$(exit_status)" = 143 ]
check "and the terminal is restored" sh -c "! tmux -L '$sock' capture-pane -p -t t | grep -q 'Parameters'"

# SIGHUP (the terminal closed): the screen is restored all the same, and
# the exit says which signal (129 = 128 + SIGHUP).
start
wait_for "? lists every key" >/dev/null
pid=$(pgrep -P "$(T display -p -t t '#{pane_pid}')" | head -1)
kill -HUP "$pid" 2>/dev/null
check "SIGHUP ends it with status 129" [ "$(exit_status)" = 129 ]
check "and the terminal is restored (curses is not left up)" sh -c "! tmux -L '$sock' capture-pane -p -t t | grep -q 'Parameters'"
i=0
while [ ! -s "$work/stty" ] && [ "$i" -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
check "and the terminal modes are back: echo and canonical input ($(grep -o -- '-*icanon\|-*echo ' "$work/stty" | tr '\n' ' '))" \
    sh -c "grep -q ' icanon' '$work/stty' && grep -q ' echo ' '$work/stty'"
check "and it says why on stderr" grep -q "stopped by signal 1" "$work/stderr"

# C-\ (SIGQUIT), the key a person presses when C-c seems not to work: it
# killed the TUI with the alternate screen still up, the cursor hidden and
# the keypad in application mode; now it restores them, as SIGINT does.
start
wait_for "? lists every key" >/dev/null
T send-keys -t t 'C-\'
check "C-\\ (SIGQUIT) ends it with status 131 (128 + 3)" [ "$(exit_status)" = 131 ]
check "and the terminal is restored: no alternate screen, the cursor shown ($(T display -p -t t 'alt #{alternate_on}, cursor #{cursor_flag}'))" \
    [ "$(T display -p -t t '#{alternate_on} #{cursor_flag}')" = "0 1" ]
check "and it says why on stderr" grep -q "stopped by signal 3" "$work/stderr"
echo "1..$n"
[ "$failed" -eq 0 ]
