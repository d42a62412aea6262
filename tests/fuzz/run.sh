#!/bin/sh
# A short libFuzzer pass over the parsers that read user text (the
# number/unit parser, scene files, replay scripts, measured curves as adhere
# fit labels them) and over the quoting that
# carries user text into gnuplot's command stream. Seeds in corpus/; the
# pass is seconds long (FUZZ_SECONDS, default 3 each in make check, whose
# longest single test it was; a minute each in make check-fuzz) and must
# find nothing.
. "$(dirname "$0")/../cli/lib.sh"
BUILD=${BUILD:-build}
secs=${FUZZ_SECONDS:-3}
for t in units scene replay gpstring measured; do
    bin="$BUILD/fuzz/fuzz_$t"
    if [ ! -x "$bin" ]; then not_ok "fuzz_$t was not built"; continue; fi
    work="$TMP/$t"
    mkdir -p "$work"
    cp "$(dirname "$0")/corpus/$t"/* "$work"/
    if "$bin" -max_total_time="$secs" -max_len=4096 -timeout=10 -artifact_prefix="$TMP/$t-" "$work" >"$TMP/$t.log" 2>&1; then
        ok "fuzz_$t: $(grep -o 'Done [0-9]* runs' "$TMP/$t.log" | tail -1) in ${secs}s, no crash"
    else
        not_ok "fuzz_$t found a failure: $(grep -m3 -E 'ERROR|SUMMARY|abort' "$TMP/$t.log" | tr '\n' ' ')"
    fi
done
done_testing
