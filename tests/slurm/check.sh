#!/bin/sh
# make check-slurm: the shipped Slurm example (share/adhere/examples) on a
# single-node Slurm started here. As root (make deps-slurm installs
# slurm-wlm and munge first), writes a minimal slurm.conf (one node,
# localhost, 2 CPUs, no cgroups) into a private directory, starts munged (its own socket and
# key copy), slurmctld -D and slurmd -D in the background, waits for sinfo
# to show the node idle (polling, no fixed delay), submits a 16-run map as
# 4 shards through submit.sh, waits for the merge job to leave the queue,
# checks the merged table against the study run whole, and stops the
# daemons it started (by their process ids). Prints TAP.
# ADHERE_BIN: the program (default ./adhere). SLURM_PORT: the first of two
# ports (default 16817).
set -u
ADHERE=$(cd "$(dirname "${ADHERE_BIN:-./adhere}")" && pwd)/$(basename "${ADHERE_BIN:-./adhere}")
EXAMPLES=$(cd "$(dirname "$0")/../../share/adhere/examples" && pwd)
PORT=${SLURM_PORT:-16817}
T=0 FAILED=0
ok() { T=$((T + 1)); echo "ok $T - $*"; }
not_ok() { T=$((T + 1)); FAILED=$((FAILED + 1)); echo "not ok $T - $*"; }
check() { what=$1; shift; if "$@"; then ok "$what"; else not_ok "$what"; fi; }
finish() { echo "1..$T"; [ "$FAILED" -eq 0 ] || exit 1; exit 0; }

if [ "$(id -u)" != 0 ]; then
    not_ok "make check-slurm starts Slurm's daemons as root: run it as root"
    finish
fi
for c in munged slurmctld slurmd sinfo sbatch squeue scontrol; do
    command -v "$c" >/dev/null 2>&1 || PATH=$PATH:/usr/sbin
done
check "slurm-wlm and munge are installed (make deps-slurm)" sh -c 'command -v slurmctld && command -v munged' >/dev/null

D=$(mktemp -d /tmp/adhere-slurm-XXXXXX)
chmod 755 "$D"
mkdir -p "$D/state" "$D/spool" "$D/munge" "$D/log" "$D/study"
chmod 700 "$D/munge"
pids=""
stop() {
    SLURM_CONF="$D/slurm.conf" scontrol shutdown >/dev/null 2>&1
    for p in $pids; do
        i=0
        while kill -0 "$p" 2>/dev/null && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
        kill "$p" 2>/dev/null
    done
    [ -f "$D/munge/munged.pid" ] && kill "$(cat "$D/munge/munged.pid")" 2>/dev/null
    rm -rf "$D"
}
trap stop EXIT

cat >"$D/slurm.conf" <<EOF
ClusterName=adhere
SlurmctldHost=localhost
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$D/munge/munge.socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SlurmctldPort=$PORT
SlurmdPort=$((PORT + 1))
StateSaveLocation=$D/state
SlurmdSpoolDir=$D/spool
SlurmctldPidFile=$D/slurmctld.pid
SlurmdPidFile=$D/slurmd.pid
SlurmctldLogFile=$D/log/slurmctld.log
SlurmdLogFile=$D/log/slurmd.log
ReturnToService=2
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
NodeName=localhost CPUs=2 State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$D/slurm.conf"
cp /etc/munge/munge.key "$D/munge/munge.key" 2>/dev/null ||
    dd if=/dev/urandom of="$D/munge/munge.key" bs=1024 count=1 2>/dev/null
chmod 600 "$D/munge/munge.key"
t0=$(date +%s.%N)
munged --force -S "$D/munge/munge.socket" --key-file="$D/munge/munge.key" --pid-file="$D/munge/munged.pid" \
    --log-file="$D/log/munged.log" --seed-file="$D/munge/seed"
check "munged starts (its own socket)" [ -S "$D/munge/munge.socket" ]
slurmctld -D -f "$SLURM_CONF" >"$D/log/ctld.out" 2>&1 &
pids="$pids $!"
slurmd -D -f "$SLURM_CONF" >"$D/log/d.out" 2>&1 &
pids="$pids $!"
state="" i=0
while [ $i -lt 600 ]; do
    state=$(sinfo -h -o %T 2>/dev/null)
    [ "$state" = idle ] && break
    sleep 0.1
    i=$((i + 1))
done
took=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN {printf "%.1f", b - a}')
check "sinfo shows the node idle (after $took s)" [ "$state" = idle ]
[ "$state" = idle ] || { sed 's/^/#   /' "$D"/log/*.log "$D"/log/*.out; finish; }

cp "$(dirname "$0")/../cli/map.scene" "$D/map.scene"
FLAGS="-N 100 --force --eps=10pm"
# shellcheck disable=SC2086
out=$(ADHERE="$ADHERE" "$EXAMPLES/submit.sh" "$D/map.scene" "$D/study" 4 $FLAGS 2>&1)
check "submit.sh queues the array and the merge ($out)" sh -c "echo '$out' | grep -q '^shards: job [0-9]* (array 1-4), merge: job [0-9]*$'"
merge=$(echo "$out" | sed -n 's/.*merge: job \([0-9]*\).*/\1/p')
t0=$(date +%s.%N)
i=0
while [ -n "$merge" ] && [ $i -lt 1800 ] && squeue -h 2>/dev/null | grep -q .; do
    sleep 0.2
    i=$((i + 1))
done
took=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN {printf "%.1f", b - a}')
check "the array and its merge leave the queue (after $took s)" sh -c "! squeue -h | grep -q ."
for k in 1 2 3 4; do
    n=$(grep -v '^#' "$D/study/shard-$k/runs.tsv" 2>/dev/null | tail -n +2 | wc -l)
    check "array task $k wrote shard $k/4: $n runs" [ "$n" -eq 4 ]
done
check "the merge wrote merged/sweep.tsv" [ -s "$D/study/merged/sweep.tsv" ]
# shellcheck disable=SC2086
"$ADHERE" --batch -q $FLAGS "$D/map.scene" -o "$D/whole" 2>/dev/null
untimed() { grep -v '^# scene:' "$1" | cut -f1-14,16-; }
untimed "$D/whole/sweep.tsv" >"$D/a"
untimed "$D/study/merged/sweep.tsv" >"$D/b" 2>/dev/null
check "the merged table is the study run whole, but for its timing column" cmp -s "$D/a" "$D/b"
check "and its map.png too, byte for byte" cmp -s "$D/whole/map.png" "$D/study/merged/map.png"
[ "$FAILED" -eq 0 ] || sed 's/^/#   /' "$D"/study/*.out 2>/dev/null | head -40
finish
