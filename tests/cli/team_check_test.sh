#!/usr/bin/env bash
# Teams on the command line: team-check on the first 96 seeded scenarios, and two worlds where a
# team of r = 1 is cornered by obstacles that pass through walls. A ctest of its own
# (cli.team_check) so that the sanitize step can leave it out: under ASan it took about ten
# minutes, and the same planners and checks run there in the MultiStc.* and Team.* tests
# (.ci/bootstrap, docs/fuzzing.md).
# Usage: team_check_test.sh COVERKIT WORKDIR
set -u
CK="$1"; T="$2"
# shellcheck source=tests/cli/common.sh
. "$(dirname "$0")/common.sh"

# team-check on the first 96 seeded scenarios (81 among moving obstacles): every plan valid, every
# reachable free sub-cell entered, the same bytes twice
"$CK" experiment team-check --seeds 96 --out "$T/tc" --quiet > /dev/null 2>&1 &&
  [ "$(csv_count "$T/tc/results.csv" "r['static_violations'] == '0' and r['robot_robot'] == '0' and r['timeline'] == '0' and r['deterministic'] == '1'")" -eq 96 ] &&
  [ "$(csv_count "$T/tc/results.csv" "r['valid'] == '1' and r['missed_subcells'] == '0' and r['missed_from_team'] == '0'")" -eq 96 ] && ok ||
  bad "team-check: $(head -20 "$T/tc/summary.md" 2> /dev/null)"
# two team-check worlds (seeds 230 and 350 of 500) where 7 robots of r = 1 on 16 x 16 m are cornered
# by obstacles that pass through walls: with a 20-step horizon one robot was caught in a corner; in
# 350 three robots in a row had to move up one after the other (tests/cli/data, docs/multi-robot.md)
TD="$(cd "$(dirname "$0")" && pwd)/data"
for s in 230 350; do
  case $s in
    230) starts="--start 1,1 --start 15,15 --start 7,9 --start 1,15 --start 5,3 --start 1,7 --start 3,11" ;;
    350) starts="--start 13,5 --start 9,15 --start 15,11 --start 15,7 --start 13,9 --start 11,13 --start 13,15" ;;
  esac
  # shellcheck disable=SC2086
  "$CK" plan --map "$TD/team_cornered_$s.wkt" --radius 1 $starts --scenario "$TD/team_cornered_$s.yaml" --planner multi_st \
      --out "$T/cornered.json" > /dev/null 2>&1 &&
    "$CK" evaluate --map "$TD/team_cornered_$s.wkt" --radius 1 --path "$T/cornered.json" --scenario "$TD/team_cornered_$s.yaml" \
      --metrics basic 2>&1 | grep -q "valid: yes" && ok ||
    bad "multi_st cornered world $s: $("$CK" evaluate --map "$TD/team_cornered_$s.wkt" --radius 1 --path "$T/cornered.json" \
      --scenario "$TD/team_cornered_$s.yaml" --metrics basic 2>&1 | grep -i violation | head -2)"
done

echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
