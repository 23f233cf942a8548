#!/usr/bin/env bash
# One long fuzzing run of a target, stopped after CPU_SECONDS of CPU time (not wall time: on a shared
# machine a wall-time limit measures the neighbours). Corpus and artifacts in OUT/<target>/; the
# committed seeds in fuzz/corpus/<target>/ are read, never written. Prints libFuzzer's final stats
# and one summary line (executions, CPU-minutes, corpus size, crashes).
#   bash fuzz/campaign.sh BUILD_DIR TARGET DICT CPU_SECONDS OUT
set -uo pipefail
cd "$(dirname "$0")/.."
build="$1" target="$2" dict="$3" cpu="$4" out="$5"
dir="$out/$target"
mkdir -p "$dir/corpus" "$dir/artifacts"
nice -n "${FUZZ_NICE:-10}" "$build/fuzz/$target" "$dir/corpus" "fuzz/corpus/$target" -dict="fuzz/dict/$dict.dict" \
  -timeout=10 -rss_limit_mb=2048 -max_total_time=86400 -print_final_stats=1 \
  -artifact_prefix="$dir/artifacts/" >"$dir/log" 2>&1 &
pid=$!
tick=$(getconf CLK_TCK)
used=0
while kill -0 "$pid" 2>/dev/null; do
  sleep 5
  stat=$(cat /proc/$pid/stat 2>/dev/null) || break
  set -- ${stat##*) }   # fields after the command name: $12 = utime, $13 = stime
  used=$(( (${12} + ${13}) / tick ))
  if [ "$used" -ge "$cpu" ]; then kill -INT "$pid"; break; fi
done
wait "$pid"
rc=$?
execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$dir/log" | tail -1)
crashes=$(ls "$dir/artifacts" | wc -l)
echo "$target: exit $rc, ${execs:-?} executions, $(awk "BEGIN {printf \"%.1f\", $used / 60}") CPU-minutes," \
  "corpus $(ls "$dir/corpus" | wc -l) files ($(cat "$dir/corpus"/* 2>/dev/null | wc -c) bytes), crashes $crashes" | tee -a "$out/summary.txt"
