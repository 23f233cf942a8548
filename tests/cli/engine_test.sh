#!/usr/bin/env bash
# The experiment engine (docs/experiments.md, "The engine"): the rows do not depend on --jobs, on
# MPI ranks or on sharding; a run killed with SIGKILL at any moment and run again gives exactly the
# rows of an uninterrupted run; a folder of another experiment is refused; bad configs fail before
# anything is written (exit 2, the file and the key named).
# Usage: engine_test.sh COVERKIT WORKDIR
set -u
CK="$1"; T="$2"
# shellcheck source=tests/cli/common.sh
. "$(dirname "$0")/common.sh"

# The rows of a results.db without the timing columns, as text (python3's sqlite3, standard library).
rows() {
  python3 - "$1" <<'EOF'
import sqlite3, sys
db = sqlite3.connect(sys.argv[1] + "/results.db")
cols = [r[1] for r in db.execute("PRAGMA table_info(runs)")]
keep = [c for c in cols if not (c.endswith("_seconds") or c == "peak_rss_mib")]
for r in db.execute("SELECT %s FROM runs ORDER BY \"case\", \"row\"" % ", ".join('"%s"' % c for c in keep)):
    print("|".join(repr(v) for v in r))
print("cases:", db.execute("SELECT COUNT(*) FROM cases").fetchone()[0])
EOF
}
# results.csv without the timing columns
csv_rows() {
  python3 - "$1/results.csv" <<'EOF'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
keep = [i for i, c in enumerate(rows[0]) if not (c.endswith("_seconds") or c == "peak_rss_mib")]
for r in rows:
    print(",".join(r[i] for i in keep))
EOF
}

cat > "$T/small.yaml" <<'EOF'
title: engine test
planners: [stc, full_stc, "smooth_stc:corners=keep"]
vary: obstacles
values: [2, 6]
radius: 0.5
worlds: {count: 3, width: 12, height: 10, obstacles: 4}
EOF

# --jobs 1 and --jobs 2: the same rows, the same summary and chart, byte for byte
"$CK" experiment run "$T/small.yaml" --out "$T/j1" --jobs 1 --quiet > "$T/j1.out" || bad "jobs 1: $(cat "$T/j1.out")"
"$CK" experiment run "$T/small.yaml" --out "$T/j2" --jobs 2 --quiet > "$T/j2.out" || bad "jobs 2: $(cat "$T/j2.out")"
[ "$(rows "$T/j1" | tail -1)" = "cases: 6" ] && [ "$(rows "$T/j1" | wc -l)" -eq 19 ] && ok || bad "jobs 1: expected 6 cases and 18 rows: $(rows "$T/j1" | tail -3)"
[ "$(rows "$T/j1")" = "$(rows "$T/j2")" ] && ok || bad "jobs 1 and 2 give other rows"
[ "$(csv_rows "$T/j1")" = "$(csv_rows "$T/j2")" ] && ok || bad "jobs 1 and 2 give another results.csv"
cmp -s "$T/j1/summary.md" "$T/j2/summary.md" && cmp -s "$T/j1/chart.svg" "$T/j2/chart.svg" && ok || bad "jobs 1 and 2 give another summary or chart"
for f in results.csv results.db run.json summary.md chart.svg config.yaml; do [ -s "$T/j1/$f" ] || bad "missing $f"; done
python3 -c "import json,sys; j=json.load(open(sys.argv[1])); assert j['format']=='coverkit.run/1' and j['cases']==6 and j['jobs']==1 and j['git_revision'] and j['cpu']" "$T/j1/run.json" && ok || bad "run.json: $(cat "$T/j1/run.json")"
head -1 "$T/j1/results.csv" | grep -q '^case,row,key,map,world,vary,value,planner,repetition,radius,start,status,valid,violations,subcell_coverage,' && ok || bad "results.csv header: $(head -1 "$T/j1/results.csv")"

# the same command again on a complete folder: nothing runs, the same files
"$CK" experiment run "$T/small.yaml" --out "$T/j1" --quiet > "$T/again.out" && grep -q "0 cases run now, 6 resumed" "$T/again.out" && ok || bad "rerun of a complete folder: $(cat "$T/again.out")"

# killed with SIGKILL at several moments, then run again: the rows of the uninterrupted run
for delay in 0.3 0.9 1.6 2.4; do
  rm -rf "$T/k"
  "$CK" experiment run "$T/small.yaml" --out "$T/k" --jobs 2 --quiet > /dev/null 2>&1 &
  pid=$!
  sleep "$delay"
  kill -9 "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  "$CK" experiment run "$T/small.yaml" --out "$T/k" --jobs 2 --quiet > "$T/k.out" 2>&1 || bad "resume after kill at ${delay}s: $(cat "$T/k.out")"
  [ "$(rows "$T/j1")" = "$(rows "$T/k")" ] && [ "$(csv_rows "$T/j1")" = "$(csv_rows "$T/k")" ] && ok || bad "kill at ${delay}s then resume: other rows"
done

# shards, then merge: the same rows
"$CK" experiment run "$T/small.yaml" --out "$T/s0" --shard 0/2 --quiet > /dev/null && "$CK" experiment run "$T/small.yaml" --out "$T/s1" --shard 1/2 --quiet > /dev/null &&
  "$CK" experiment merge "$T/s0" "$T/s1" --config "$T/small.yaml" --out "$T/merged" --quiet > /dev/null && [ "$(rows "$T/j1")" = "$(rows "$T/merged")" ] &&
  cmp -s "$T/j1/summary.md" "$T/merged/summary.md" && ok || bad "shards 0/2 and 1/2 merged: other rows"
[ ! -e "$T/s0/results.csv" ] && ok || bad "a shard wrote results.csv (it holds only part of the cases)"

# MPI: mpirun -np 3 (rank 0 hands out the cases, two ranks run them)
if ! "$CK" --version | grep -q "with MPI"; then
  echo "note: this coverkit is built without MPI (-DCOVERKIT_MPI=OFF): the MPI case is skipped"
elif command -v mpirun > /dev/null; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader OMPI_MCA_rmaps_base_oversubscribe=1
  if mpirun --oversubscribe -np 3 "$CK" experiment run "$T/small.yaml" --out "$T/mpi" --quiet > "$T/mpi.out" 2>&1; then
    grep -q '"mpi_ranks": 3' "$T/mpi/run.json" && [ "$(rows "$T/j1")" = "$(rows "$T/mpi")" ] && cmp -s "$T/j1/summary.md" "$T/mpi/summary.md" && ok ||
      bad "mpirun -np 3: other rows, or not 3 ranks: $(grep mpi_ranks "$T/mpi/run.json")"
  else
    bad "mpirun -np 3: $(tail -5 "$T/mpi.out")"
  fi
else
  bad "built with MPI but mpirun is not there (Debian: openmpi-bin)"
fi

# another experiment into the same folder is refused, and nothing in it changes
sed 's/count: 3/count: 4/' "$T/small.yaml" > "$T/other.yaml"
before="$(md5sum "$T/j1/results.db" "$T/j1/results.csv")"
"$CK" experiment run "$T/other.yaml" --out "$T/j1" --quiet > /dev/null 2> "$T/other.err"; rc=$?
[ "$rc" -eq 2 ] && grep -q "results.db: holds the results of another experiment" "$T/other.err" && [ "$before" = "$(md5sum "$T/j1/results.db" "$T/j1/results.csv")" ] && ok ||
  bad "another experiment into a used folder: exit $rc: $(cat "$T/other.err")"

# bad configs: exit 2, the file and the key named, no folder made
expect_bad() {
  local what="$1" frag="$2"; shift 2
  rm -rf "$T/bad-out"
  "$CK" "$@" --out "$T/bad-out" --quiet > /dev/null 2> "$T/bad.err"; local rc=$?
  if [ "$rc" -eq 2 ] && grep -qF -- "$frag" "$T/bad.err" && [ ! -e "$T/bad-out" ]; then ok; else bad "$what: exit $rc, stderr: $(head -c 300 "$T/bad.err")"; fi
}
cfg() { printf "$2" > "$T/$1.yaml"; echo "$T/$1.yaml"; }
expect_bad "unknown planner" "unk-planner.yaml: planners: unknown planner 'stcc'" experiment run "$(cfg unk-planner 'planners: [stcc]\n')"
expect_bad "unknown key" "unk-key.yaml: radiuses: line 1: unknown key" experiment run "$(cfg unk-key 'radiuses: [0.5]\n')"
expect_bad "bad range" "range.yaml: worlds.count: line 1: 0: must be in 1..10000" experiment run "$(cfg range 'worlds: {count: 0}\n')"
expect_bad "missing map" "nomap.yaml: maps: 'no-such.map': no such map file or folder" experiment run "$(cfg nomap 'maps: [no-such.map]\nradii: [0.5]\n')"
expect_bad "unknown kind" "kind.yaml: kind: unknown experiment kind 'nope'" experiment run "$(cfg kind 'kind: nope\n')"
expect_bad "bad repetitions" "reps.yaml: repetitions: line 1: 0: must be in 1..1000" experiment run "$(cfg reps 'repetitions: 0\n')"
expect_bad "maps and worlds" "both.yaml: maps: line 1: give maps or worlds, not both" experiment run "$(cfg both 'maps: [x.map]\nworlds: {count: 1}\n')"
expect_bad "no config" "experiment run: expected one config file" experiment run
expect_bad "bad shard" "--shard: 2/2: expected i/n with 0 <= i < n" experiment run "$T/small.yaml" --shard 2/2
mkdir -p "$T/nothing-here"
"$CK" experiment report "$T/nothing-here" > /dev/null 2> "$T/bad.err"; rc=$?
[ "$rc" -eq 2 ] && grep -qF "nothing-here/results.db: not found" "$T/bad.err" && [ -z "$(ls -A "$T/nothing-here")" ] && ok || bad "report of a folder with no results: exit $rc: $(cat "$T/bad.err")"

# a sweep over map files (a folder of maps), two radii
mkdir -p "$T/maps"
printf '..........\n..##......\n..##...#..\n.......#..\n..........\n' > "$T/maps/a.grid"
printf '........\n.#....#.\n........\n' > "$T/maps/b.grid"
cfg maps 'planners: [stc, boustrophedon]\nmaps: [maps]\nradii: [0.25, 0.5]\n' > /dev/null
"$CK" experiment run "$T/maps.yaml" --out "$T/m" --quiet > "$T/m.out" 2>&1 && [ "$(rows "$T/m" | tail -1)" = "cases: 4" ] &&
  [ "$(grep -c ',exact_solution,1,' "$T/m/results.csv")" -ge 6 ] && ok || bad "sweep over a folder of maps: $(cat "$T/m.out") $(rows "$T/m")"

# every kind on the engine: the same rows and files (pictures too) for --jobs 1 and --jobs 2; a
# summary with times in it (decompositions) is left out of the comparison
same_files() {   # DIR_A DIR_B: every file other than the database, run.json and results.csv, byte for byte
  local f
  for f in $(cd "$1" && find . -type f ! -name results.db ! -name run.json ! -name results.csv ! -name report.html | sort); do
    cmp -s "$1/$f" "$2/$f" || { echo "$f"; return 1; }
  done
}
printf 'kind: scenarios\nscenarios: list.txt\nplanners: [full_stc, boustrophedon]\n' > "$T/scen.yaml"
printf 'a maps/a.grid 0.25\nb maps/b.grid 0.25\n' > "$T/list.txt"
printf 'kind: coverage-vs-time\nplanners: [stc, full_stc]\nradius: 0.5\nsteps: 3\nworlds: {count: 2, width: 8, height: 8, obstacles: 2}\n' > "$T/time.yaml"
printf 'kind: decompositions\nseeds: 1\nholes: [0, 3]\n' > "$T/dec.yaml"
printf 'kind: bsa-backtracking\nseeds: 4\nsize: 12\n' > "$T/bsa.yaml"
printf 'kind: tracc-scenarios\n' > "$T/tracc.yaml"
for c in scen time dec bsa tracc; do
  file="$T/$c.yaml"
  "$CK" experiment run "$file" --out "$T/$c-1" --jobs 1 --quiet > "$T/$c.out" 2>&1 && "$CK" experiment run "$file" --out "$T/$c-2" --jobs 2 --quiet >> "$T/$c.out" 2>&1 ||
    bad "kind $c: $(tail -3 "$T/$c.out")"
  [ "$(rows "$T/$c-1")" = "$(rows "$T/$c-2")" ] && [ "$(rows "$T/$c-1" | wc -l)" -gt 2 ] && ok || bad "kind $c: jobs 1 and 2 give other rows"
  if [ "$c" = dec ]; then diff -q <(csv_rows "$T/$c-1") <(csv_rows "$T/$c-2") > /dev/null && ok || bad "kind $c: other results.csv"
  else d="$(same_files "$T/$c-1" "$T/$c-2")" && ok || bad "kind $c: jobs 1 and 2 give another $d"; fi
done
ls "$T/scen-1/pictures/"*.svg > /dev/null 2>&1 && ok || bad "kind scenarios: no pictures"
[ -s "$T/tracc-2/scenario-2.svg" ] && grep -q '^| 1 | C5;' "$T/tracc-2/summary.md" && ok || bad "tracc-scenarios: $(head -c 300 "$T/tracc-2/summary.md")"
if "$CK" --version | grep -q "with MPI" && command -v mpirun > /dev/null; then
  mpirun --oversubscribe -np 3 "$CK" experiment run "$T/scen.yaml" --out "$T/scen-mpi" --quiet > "$T/scen-mpi.out" 2>&1 &&
    [ "$(rows "$T/scen-1")" = "$(rows "$T/scen-mpi")" ] && d="$(same_files "$T/scen-1" "$T/scen-mpi")" && ok || bad "scenarios under mpirun -np 3: other rows or $d"
fi

# starts and listed seeds: a case per world, setting and start; a start in an obstacle of a world is
# a row per planner with status invalid_start; the worlds are the seeds listed
printf 'planners: [full_stc]\nradii: [0.5]\nstarts: [default, "1,1", "5.5,4.5", "100,100"]\nworlds: {seeds: [7, 3], width: 12, height: 10, obstacles: 4}\n' > "$T/starts.yaml"
"$CK" experiment run "$T/starts.yaml" --out "$T/starts" --quiet > "$T/starts.out" 2>&1 && [ "$(rows "$T/starts" | tail -1)" = "cases: 8" ] &&
  python3 - "$T/starts/results.csv" <<'EOF' && ok || bad "starts and seeds: $(cat "$T/starts.out") $(csv_rows "$T/starts" | cut -c1-120)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert [r["world"] for r in rows][::4] == ["7", "3"], [r["world"] for r in rows]
assert [r["start"] for r in rows[:4]] == ["default", "1,1", "5.5,4.5", "100,100"]
assert all(r["status"] == "invalid_start" for r in rows if r["start"] == "100,100")   # outside the world: not planned
for r in rows:
    assert r["status"] in ("exact_solution", "partial_coverage", "invalid_start"), r["status"]
    assert r["status"] != "exact_solution" or r["valid"] == "1"
    assert r["status"] != "invalid_start" or (r["valid"] == "0" and r["violations"] == "1")   # no plan is not a valid plan
assert [r["start"] for r in rows if r["status"] == "invalid_start"] == ["5.5,4.5", "100,100", "100,100"]
EOF
expect_bad "bad start" "bad-start.yaml: starts: line 3: 'nowhere': expected default or X,Y" experiment run "$(cfg bad-start 'planners: [full_stc]\nradii: [0.5]\nstarts: ["1,1", nowhere]\n')"
expect_bad "bad seeds" "bad-seeds.yaml: worlds.seeds: line 1: x: not a seed" experiment run "$(cfg bad-seeds 'worlds: {seeds: [1, x]}\n')"
# a scenario list with starts (listed cases: map, radius, start); a start in an obstacle is refused first
printf 'kind: scenarios\nscenarios: list2.txt\nplanners: [full_stc]\n' > "$T/scen2.yaml"
printf 'a maps/a.grid 0.25 0.5,0.5\nb maps/b.grid 0.25 7.5,2.5\n' > "$T/list2.txt"
"$CK" experiment run "$T/scen2.yaml" --out "$T/scen2" --quiet > "$T/scen2.out" 2>&1 &&
  [ "$(python3 -c 'import csv,sys; print(sum(r["valid"] == "1" for r in csv.DictReader(open(sys.argv[1]))))' "$T/scen2/results.csv")" = 2 ] && ok ||
  bad "scenarios with starts: $(cat "$T/scen2.out")"
printf 'a maps/a.grid 0.25 2.5,2.5\n' > "$T/list2.txt"
expect_bad "scenario start in an obstacle" "list2.txt: line 1: --start: 2.5,2.5: start is outside the workspace or inside an obstacle" experiment run "$T/scen2.yaml"
printf 'a maps/a.grid 0.25 0.5,0.5 extra\n' > "$T/list2.txt"
expect_bad "scenario line with more fields" "list2.txt: line 1: 'extra': expected NAME FILE RADIUS [START], and nothing after" experiment run "$T/scen2.yaml"

echo "engine test: $passes passed, $fails failed"
[ "$fails" -eq 0 ]
