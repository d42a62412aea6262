#!/bin/sh
# Submits a study to Slurm as N shards (a job array of study.sbatch) and
# its merge (merge.sbatch), which waits for the array:
#
#   submit.sh SCENE OUT N [adhere flags...]
#
# e.g. submit.sh map.scene "$PWD/study" 8 --eps=0.5pm (SCENE a file, or a
# shipped scene's name: submit.sh fig3 ...). Prints the two job
# ids. The results: OUT/merged/sweep.tsv and its figure; each shard's rows
# in OUT/shard-K/runs.tsv. `adhere --plan SCENE --shard 1/N` first says
# what a shard holds and about how long it takes. Flags may hold spaces
# (--gnuplot-style="$PWD/my styles"): ADHERE_ARGS carries them as quoted
# shell words. A task that failed is
# resubmitted alone with the same environment (ADHERE_ARGS too) and its index:
#   sbatch --array=K --export=ALL,ADHERE_SCENE=SCENE,ADHERE_OUT=OUT,ADHERE_SHARDS=N study.sbatch
set -eu
if [ $# -lt 3 ]; then
    echo "usage: $0 SCENE OUT N [adhere flags...]" >&2
    exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
# the scene and OUT as absolute paths, each whole: $(...) would drop a
# name's trailing newlines. A SCENE that is no file here and has no /
# is a shipped scene's name (fig3, afm): made a path, every task was
# refused a file that is not there
case $1 in
/*) scene=$1 ;;
*/*) scene=$PWD/$1 ;;
*) if [ -e "$1" ]; then scene=$PWD/$1; else scene=$1; fi ;;
esac
out=$2 n=$3
shift 3
# N before anything is made or queued: sbatch took --array=1-0 or 1-x
case $n in
'' | *[!0-9]* | 0*)
    echo "$0: N = '$n': give the number of shards, a whole number from 1" >&2
    exit 2 ;;
esac
mkdir -p -- "$out"
case $out in /*) ;; *) out=$PWD/$out ;; esac
# the flags as shell words, each single-quoted (' as '\''): study.sbatch
# reads them back one by one, a value with a space (a path) whole. $(...)
# drops the trailing newlines of what it captures: the quoted value ends
# with a sentinel x, removed after, so a value ending in newlines keeps them
args=
for a in "$@"; do
    q=$(printf '%s' "$a" | sed "s/'/'\\\\''/g"; printf x)
    args="$args '${q%x}'"
done
# ADHERE_SHARDS: task K is shard K/N, so a task resubmitted alone is its shard again
array=$(ADHERE_SCENE="$scene" ADHERE_OUT="$out" ADHERE_ARGS="$args" ADHERE_SHARDS="$n" \
    sbatch --parsable --export=ALL --chdir="$out" --array="1-$n" "$here/study.sbatch")
array=${array%%;*}
merge=$(ADHERE_OUT="$out" sbatch --parsable --export=ALL --chdir="$out" --dependency="afterany:$array" \
    "$here/merge.sbatch")
merge=${merge%%;*}
echo "shards: job $array (array 1-$n), merge: job $merge"
