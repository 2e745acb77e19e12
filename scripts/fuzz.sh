#!/usr/bin/env bash
# fuzz.sh BUILD_DIR SECONDS - runs each libFuzzer target (make fuzz) for SECONDS on the committed corpus
# (fuzz/corpus/<target>, read only) plus the inputs it finds (BUILD_DIR/corpus/<target>, not committed).
# A broken promise (crash, sanitizer report, timeout, out of memory) leaves the input in
# BUILD_DIR/crashes/ and fails the run; turn it into a regression test by fixing the bug and copying the
# input to fuzz/regress/<target>/ (ctest fuzz_replay_<target> replays it from then on).
set -uo pipefail
build=${1:?usage: fuzz.sh BUILD_DIR SECONDS}
secs=${2:?usage: fuzz.sh BUILD_DIR SECONDS}
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$build/crashes" "$build/logs"
fail=0
printf '%-14s %8s %12s %10s %8s  %s\n' target seconds executions "corpus" features result
for t in cli format host obj specsim setup specsim_setup; do
    bin="$build/fuzz_$t"
    [ -x "$bin" ] || { echo "fuzz: $bin not built" >&2; exit 2; }
    mkdir -p "$build/corpus/$t"
    log="$build/logs/$t.log"
    # -close_fd_mask=1: the targets' own stdout (specsim span's CSV) is not wanted
    "$bin" -max_total_time="$secs" -timeout=20 -rss_limit_mb=4096 -close_fd_mask=1 -print_final_stats=1 \
        -artifact_prefix="$build/crashes/$t-" "$build/corpus/$t" "$root/fuzz/corpus/$t" > "$log" 2>&1
    rc=$?
    execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
    cov=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo "?")
    corp=$(ls "$build/corpus/$t" | wc -l)
    if [ $rc -eq 0 ]; then res=ok; else res="FAILED (exit $rc, log $log)"; fail=1; fi
    printf '%-14s %8s %12s %10s %8s  %s\n' "$t" "$secs" "$execs" "$corp new" "$cov" "$res"
    if [ $rc -ne 0 ]; then
        grep -E 'ERROR|SUMMARY|fuzz:|Test unit written|runtime error' "$log" | head -8 | sed 's/^/    /'
    fi
done
if [ $fail -ne 0 ]; then
    echo "make fuzz: a target broke a promise; the inputs are in $build/crashes/" >&2
    exit 1
fi
echo "make fuzz: no crash, sanitizer report, timeout or broken promise in ${secs} s per target"
