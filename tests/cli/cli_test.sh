#!/usr/bin/env bash
# The command line on good and bad input: bad input gets exit code 2, a message naming the file or
# option, the place and the problem, and no output file (an existing one is left as it was).
#
# With COVERKIT_BAD_INPUTS_TABLE=FILE every bad-input case is also written to FILE as a row of a
# Markdown table (case | command | exit | first line of stderr); tests/cli/bad_inputs_doc.sh turns
# it into docs/bad-inputs.md.
set -u
CK="$1"; DATA="$2"; T="$3"
# shellcheck source=tests/cli/common.sh
. "$(dirname "$0")/common.sh"
TABLE="${COVERKIT_BAD_INPUTS_TABLE:-}"
[ -n "$TABLE" ] && printf '| case | command | exit | message (first line of stderr) |\n|---|---|---|---|\n' > "$TABLE"

# Every file and folder under $T with its size and checksum (stdout and stderr of the cases aside).
snapshot() {
  (cd "$T" && find . -mindepth 1 ! -name stdout ! -name stderr -printf '%p %y %s\n' | LC_ALL=C sort &&
     find . -type f ! -name stdout ! -name stderr -print0 | LC_ALL=C sort -z | xargs -0 -r md5sum)
}
# A table cell: paths of this run shortened, | escaped.
cell() { printf '%s' "$1" | sed -e "s|$T/|T/|g" -e "s|$T|T|g" -e "s|$DATA/|data/|g" -e 's/|/\\|/g'; }

# expect_bad "description" "expected message fragment" args...
# Exit 2 within 120 s, a message containing the fragment, nothing created or changed under $T.
expect_bad() {
  local what="$1" frag="$2"; shift 2
  rm -f "$T/out.json" "$T/out.png"
  local before; before="$(snapshot)"
  timeout 120 "$CK" "$@" > "$T/stdout" 2> "$T/stderr"; local rc=$?
  if [ -n "$TABLE" ]; then
    printf '| %s | `coverkit %s` | %s | %s |\n' "$(cell "$what")" "$(cell "$*")" "$rc" "$(cell "$(head -1 "$T/stderr")")" >> "$TABLE"
  fi
  if [ $rc -eq 124 ]; then bad "$what: timed out (120 s)"; return; fi
  if [ $rc -ne 2 ]; then bad "$what: exit $rc, expected 2 ($(cat "$T/stderr"))"; return; fi
  if [ -z "$frag" ]; then bad "$what: the test gives no message fragment to expect"; return; fi
  if ! grep -qF -- "$frag" "$T/stderr"; then bad "$what: message lacks '$frag': $(cat "$T/stderr")"; return; fi
  if [ "$(snapshot)" != "$before" ]; then
    bad "$what: wrote or changed files: $(diff <(echo "$before") <(snapshot) | head -5 | tr '\n' ' ')"; return
  fi
  ok
}
plan() { echo plan --planner stc --radius "${1:-0.25}" --out "$T/out.json" --picture "$T/out.png" --map; }

printf 'image: x.pgm\norigin: [0, 0, 0]\n' > "$T/nores.yaml"
printf 'image: x.pgm\nresolution: 0\n' > "$T/zerores.yaml"
printf 'image: x.pgm\nresolution: -0.05\n' > "$T/negres.yaml"
printf 'image: nothere.pgm\nresolution: 0.05\n' > "$T/noimg.yaml"
printf 'P5\n100 100\n255\nshort' > "$T/trunc.pgm"; printf 'image: trunc.pgm\nresolution: 0.05\n' > "$T/trunc.yaml"
printf 'GIF89a not a pgm' > "$T/gif.pgm"; printf 'image: gif.pgm\nresolution: 0.05\n' > "$T/gif.yaml"
printf 'type octile\nwidht 3\nheight 2\nmap\n...\n...\n' > "$T/hdr.map"
printf 'type octile\nheight 2\nwidth 4\nmap\n....\n..\n' > "$T/short.map"
printf 'POLYGON((0 0, 10 0, 10 10' > "$T/broken.wkt"
printf '{"type": "Polygon", "coordinates": [[[0,0],[1,0]' > "$T/broken.geojson"
printf 'POLYGON((0 0, 10 10, 10 0, 0 10, 0 0))' > "$T/bowtie.wkt"
printf 'POLYGON((0 0, 10 0, 10 10, 0 10, 0 0),(20 20, 21 20, 21 21, 20 20))' > "$T/holeout.wkt"
printf 'POLYGON((0 0, NaN 0, 10 10, 0 10, 0 0))' > "$T/nan.wkt"
printf '{"type":"Polygon","coordinates":[[[0,0],[1e999,0],[1,1],[0,0]]]}' > "$T/inf.geojson"
printf '####\n####\n' > "$T/full.grid"
printf 'POLYGON((0 0, 10 0, 10 0, 10 10, 0 10, 0 0))' > "$T/dup.wkt"
printf 'POLYGON((0 0, 5 0, 10 0, 0 0))' > "$T/flat.wkt"
printf 'POLYGON((0 0, 10 0, 10 10, 0 10, 0 0),(4 4, 6 4, 6 6, 4 6, 4 4))' > "$T/room.wkt"

expect_bad "missing map" "nothere.map: file not found" $(plan) "$T/nothere.map"
expect_bad "map is a directory" "is a directory" $(plan) "$T"
expect_bad "yaml without resolution" "resolution: missing" $(plan) "$T/nores.yaml"
expect_bad "resolution 0" "resolution: must be > 0" $(plan) "$T/zerores.yaml"
expect_bad "resolution < 0" "resolution: must be > 0" $(plan) "$T/negres.yaml"
expect_bad "image missing" "image: image file" $(plan) "$T/noimg.yaml"
expect_bad "truncated pgm" "truncated PGM" $(plan) "$T/trunc.yaml"
expect_bad "not a pgm" "not a PGM" $(plan) "$T/gif.yaml"
expect_bad "moving ai header" "hdr.map: line 2: bad Moving AI header" $(plan) "$T/hdr.map"
expect_bad "moving ai short row" "short.map: line 6: row has 2 cells, width is 4" $(plan) "$T/short.map"
expect_bad "wkt syntax" "broken.wkt: line 1 column" $(plan) "$T/broken.wkt"
expect_bad "geojson syntax" "GeoJSON does not parse" $(plan) "$T/broken.geojson"
expect_bad "self-intersecting" "self-intersecting ring" $(plan) "$T/bowtie.wkt"
expect_bad "hole outside" "hole is outside its outer ring" $(plan) "$T/holeout.wkt"
expect_bad "NaN" "not finite" $(plan) "$T/nan.wkt"
expect_bad "infinite" "GeoJSON does not parse" $(plan) "$T/inf.geojson"
expect_bad "empty free space" "empty free space" $(plan) "$T/full.grid"
expect_bad "radius 0" "--radius: 0: robot radius must be > 0" $(plan 0) "$T/room.wkt"
expect_bad "radius < 0" "robot radius must be > 0" $(plan -1) "$T/room.wkt"
expect_bad "radius too large" "robot is larger than the workspace" $(plan 8) "$T/room.wkt"
expect_bad "start outside" "--start: 20,1: start is outside the workspace or inside an obstacle" $(plan) "$T/room.wkt" --start 20,1
expect_bad "start in obstacle" "inside an obstacle" $(plan) "$T/room.wkt" --start 5,5
expect_bad "unknown planner" "--planner: nope: unknown planner (known: " plan --planner nope --radius 0.25 --out "$T/out.json" --map "$T/room.wkt"
expect_bad "unknown parameter" "--param: depth: unknown parameter" $(plan) "$T/room.wkt" --param depth=3
expect_bad "parameter out of range" "--param: tree=random: must be one of" $(plan) "$T/room.wkt" --param tree=random
expect_bad "cell size below 2r" "--cell-size: 0.4: must be at least 2r" $(plan) "$T/room.wkt" --cell-size 0.4
expect_bad "unknown output format" "unknown output format '.txt'" plan --planner stc --radius 0.25 --out "$T/out.txt" --map "$T/room.wkt"
expect_bad "unknown picture format" "unknown picture format" plan --planner stc --radius 0.25 --out "$T/out.json" --picture "$T/out.bmp" --map "$T/room.wkt"
expect_bad "missing path file" "file not found" evaluate --map "$T/room.wkt" --path "$T/none.json"
expect_bad "bad CLI flag" "--map is required" plan --bogus

# --- outputs, options, experiment configs and limits (issue 12) -------------------------------
# an existing output that every failing case below must leave as it was
printf 'previous content\n' > "$T/existing.json"; printf 'previous picture\n' > "$T/existing.png"
mkdir -p "$T/folder.json" "$T/folder.png"
printf 'POLYGON((0 0, 1e400 0, 1e400 1e400, 0 1e400, 0 0))' > "$T/huge.wkt"
printf 'MULTIPOLYGON(((0 0, 10 0, 10 10, 0 10, 0 0)),((1e400 0, 2e400 0, 2e400 1e400, 1e400 0)))' > "$T/far.wkt"
printf '{"format":"coverkit.path/1","robots":[{"start":[1,1],"segments":[{"type":"line","from":[1,1],"to":[2,1]}]}]}' > "$T/hand.json"
p() { echo plan --planner stc --radius 0.25 --map "$T/room.wkt"; }
expect_bad "--picture in a missing folder, existing --out" "missing-folder/p.png: --picture: folder '$T/missing-folder' does not exist" $(p) --out "$T/existing.json" --picture "$T/missing-folder/p.png"
expect_bad "--out in a missing folder" "x.json: --out: folder '$T/missing-folder' does not exist" $(p) --out "$T/missing-folder/x.json"
expect_bad "--out is a folder" "folder.json: --out: is a folder, not a file" $(p) --out "$T/folder.json"
expect_bad "--picture is a folder" "folder.png: --picture: is a folder, not a file" $(p) --out "$T/existing.json" --picture "$T/folder.png"
expect_bad "--out under a file" "existing.json/x.json: --out: folder '$T/existing.json' is not a folder" $(p) --out "$T/existing.json/x.json"
expect_bad "--out without a name" "--out: no file name given" $(p) --out ""
expect_bad "--out with an unknown extension, existing --picture" "unknown output format '.txt'" $(p) --out "$T/x.txt" --picture "$T/existing.png"
expect_bad "coordinates 1e400 (beyond a double), existing --out and --picture" "huge.wkt: polygon 1 outer ring vertex 2: coordinate beyond ±1e15" plan --planner stc --radius 1e399 --map "$T/huge.wkt" --out "$T/existing.json" --picture "$T/existing.png"
expect_bad "a second polygon at x = 1e400" "far.wkt: polygon 2 outer ring vertex 1: coordinate beyond ±1e15" plan --planner stc --radius 0.25 --map "$T/far.wkt" --out "$T/existing.json"
expect_bad "radius 1e-300: cell grid beyond the limit" "--radius: 1e-300: the sub-cell grid would have 5e+300 × 5e+300 sub-cells of size D = 2e-300 (2r) over the 10 × 10 bounding box of $T/room.wkt, more than the limit of 2e+08 sub-cells" plan --planner stc --radius 1e-300 --map "$T/room.wkt" --out "$T/existing.json" --picture "$T/existing.png"
expect_bad "cell size 1e-6: cell grid beyond the limit" "--cell-size: 1e-06: the sub-cell grid would have 1e+07 × 1e+07 sub-cells" plan --planner stc --radius 1e-7 --cell-size 1e-6 --map "$T/room.wkt" --out "$T/existing.json"
expect_bad "render: radius 1e-300" "--radius: 1e-300: the sub-cell grid would have" render --radius 1e-300 --map "$T/room.wkt" --out "$T/existing.png"
expect_bad "evaluate: radius 1e-300" "--radius: 1e-300: the sub-cell grid would have" evaluate --radius 1e-300 --map "$T/room.wkt" --path "$T/hand.json"
expect_bad "--time-limit -1" "--time-limit: -1: must be a finite number of seconds in [0, 10^9] (0: no limit)" $(p) --out "$T/existing.json" --time-limit -1
expect_bad "--time-limit nan" "--time-limit: nan: must be a finite number of seconds" $(p) --out "$T/existing.json" --time-limit nan
expect_bad "--time-limit inf" "--time-limit: inf: must be a finite number of seconds" $(p) --out "$T/existing.json" --time-limit inf
expect_bad "--time-limit 1e300" "--time-limit: 1e300: must be a finite number of seconds in [0, 10^9]" $(p) --out "$T/existing.json" --time-limit 1e300
expect_bad "--time-limit not a number" "--time-limit: 10s: not a number of seconds" $(p) --out "$T/existing.json" --time-limit 10s
expect_bad "cspace: --picture in a missing folder, existing --out" "p.png: --picture: folder '$T/missing-folder' does not exist" cspace --map "$T/room.wkt" --radius 0.25 --out "$T/existing.json" --picture "$T/missing-folder/p.png"
expect_bad "cspace: --out in a missing folder" "--out: folder '$T/missing-folder' does not exist" cspace --map "$T/room.wkt" --radius 0.25 --out "$T/missing-folder/c.json"
expect_bad "cspace: coordinates 1e400" "coordinate beyond ±1e15" cspace --map "$T/huge.wkt" --radius 1 --out "$T/existing.json" --picture "$T/existing.png"
expect_bad "render: --out in a missing folder" "--out: folder '$T/missing-folder' does not exist" render --map "$T/room.wkt" --radius 0.25 --out "$T/missing-folder/r.png"
expect_bad "render: --out is a folder" "folder.png: --out: is a folder, not a file" render --map "$T/room.wkt" --radius 0.25 --out "$T/folder.png"
expect_bad "render: --out with an unknown extension" "r.jpg: --out: unknown picture format '.jpg' (expected .png or .svg)" render --map "$T/room.wkt" --radius 0.25 --out "$T/r.jpg"
expect_bad "demo: --out is an existing file" "existing.json: --out: exists and is not a folder" demo --out "$T/existing.json"
expect_bad "demo: --out under a file" "existing.json/demo: --out: cannot be used: Not a directory" demo --out "$T/existing.json/demo"
# experiments: options
expect_bad "bsa: --size 100000 (would not fit)" "--size: 100000: must be in 2..1000" experiment bsa-backtracking --size 100000 --out "$T/bsa-out"
expect_bad "bsa: --size 1" "--size: 1: must be in 2..1000" experiment bsa-backtracking --size 1 --out "$T/bsa-out"
expect_bad "bsa: --seeds 1000000" "--seeds: 1000000: must be in 1..100000" experiment bsa-backtracking --seeds 1000000 --out "$T/bsa-out"
expect_bad "bsa: --density 1" "--density: 1: must be in [0, 1)" experiment bsa-backtracking --density 1 --out "$T/bsa-out"
expect_bad "bsa: --density nan" "--density: nan: must be in [0, 1)" experiment bsa-backtracking --density nan --out "$T/bsa-out"
expect_bad "bsa: --density -0.1" "--density: -0.1: must be in [0, 1)" experiment bsa-backtracking --density -0.1 --out "$T/bsa-out"
expect_bad "bsa: --density where S is walled in on nearly every map" "--density: 0.6: the start S(0, 0) is walled in" experiment bsa-backtracking --seeds 3 --density 0.6 --out "$T/bsa-out"
expect_bad "bsa: --out is an existing file" "existing.json: --out: exists and is not a folder" experiment bsa-backtracking --seeds 1 --out "$T/existing.json"
expect_bad "tracc: --out is an existing file" "existing.json: --out: exists and is not a folder" experiment tracc-scenarios --out "$T/existing.json"
expect_bad "--seeds given to a sweep" "--seeds: 3: not a setting of the sweep experiment" experiment coverage-vs-size --seeds 3 --out "$T/cfg-out"
printf 'kind: sweep\n' > "$T/cfg-kind-sweep.yaml"
expect_bad "a sweep config given to bsa-backtracking" "cfg-kind-sweep.yaml: kind: sweep: this config is of another kind than bsa-backtracking" experiment bsa-backtracking --config "$T/cfg-kind-sweep.yaml" --out "$T/cfg-out"
printf 'kind: bsa-backtracking\nseeds: 0\n' > "$T/cfg-bsa-seeds.yaml"
expect_bad "bsa config: seeds 0" "cfg-bsa-seeds.yaml: seeds: 0: must be in 1..100000" experiment run "$T/cfg-bsa-seeds.yaml" --out "$T/cfg-out"
printf 'kind: tracc-scenarios\nsize: 3\n' > "$T/cfg-tracc-key.yaml"
expect_bad "tracc config: a key" "cfg-tracc-key.yaml: size: line 2: unknown key (known: kind)" experiment run "$T/cfg-tracc-key.yaml" --out "$T/cfg-out"
printf 'kind: decompositions\nholes: [2, x]\n' > "$T/cfg-dec-holes.yaml"
expect_bad "decompositions config: holes" "cfg-dec-holes.yaml: holes: x: not a hole count" experiment run "$T/cfg-dec-holes.yaml" --out "$T/cfg-out"
# experiments: configs (each would run the whole default experiment, or crash, before)
cfg() { printf -- "$2" > "$T/cfg-$1.yaml"; echo "$T/cfg-$1.yaml"; }
# a results.csv without its timing columns (names ending in _seconds, and peak_rss_mib)
csv_untimed() { python3 -c 'import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
keep = [i for i, c in enumerate(rows[0]) if not (c.endswith("_seconds") or c == "peak_rss_mib")]
print("\n".join(",".join(r[i] for i in keep) for r in rows))' "$1"; }
expect_bad "config: a YAML scalar" "cfg-scalar.yaml: line 1: expected a YAML mapping with the keys title, planners, vary, radii, values, radius, worlds, maps, starts, repetitions, kind, got 'hello'" experiment sweep --config "$(cfg scalar 'hello\n')" --out "$T/cfg-out"
expect_bad "config: an empty file" "cfg-empty.yaml: the config is empty: expected a YAML mapping" experiment sweep --config "$(cfg empty '')" --out "$T/cfg-out"
expect_bad "config: comments only" "cfg-comment.yaml: the config is empty" experiment sweep --config "$(cfg comment '# nothing\n')" --out "$T/cfg-out"
expect_bad "config: a YAML list" "cfg-list.yaml: line 1: expected a YAML mapping with the keys title, planners, vary, radii, values, radius, worlds, maps, starts, repetitions, kind, got a list" experiment sweep --config "$(cfg list '- stc\n- full_stc\n')" --out "$T/cfg-out"
expect_bad "config: worlds a scalar" "cfg-wscalar.yaml: worlds: line 1: expected a mapping (count or seeds, width, height, obstacles, shape, min_size, max_size), got '3'" experiment sweep --config "$(cfg wscalar 'worlds: 3\n')" --out "$T/cfg-out"
expect_bad "config: worlds a list" "cfg-wlist.yaml: worlds: line 1: expected a mapping" experiment coverage-vs-time --config "$(cfg wlist 'worlds: [1, 2]\n')" --out "$T/cfg-out"
expect_bad "config: min_size .nan" "cfg-nan.yaml: worlds.min_size: line 1: must be a finite number, got '.nan'" experiment sweep --config "$(cfg nan 'worlds: {min_size: .nan}\n')" --out "$T/cfg-out"
expect_bad "config: max_size .inf" "cfg-inf.yaml: worlds.max_size: line 1: must be a finite number, got '.inf'" experiment sweep --config "$(cfg inf 'worlds: {max_size: .inf}\n')" --out "$T/cfg-out"
expect_bad "config: min_size > max_size" "cfg-minmax.yaml: worlds.max_size: 1: must be at least min_size (2)" experiment sweep --config "$(cfg minmax 'worlds: {min_size: 2, max_size: 1}\n')" --out "$T/cfg-out"
expect_bad "config: min_size 0" "cfg-min0.yaml: worlds.min_size: 0: must be > 0" experiment sweep --config "$(cfg min0 'worlds: {min_size: 0}\n')" --out "$T/cfg-out"
expect_bad "config: obstacles larger than the world" "cfg-big.yaml: worlds.max_size: 30: an obstacle must fit the 20×20 world" experiment sweep --config "$(cfg big 'worlds: {max_size: 30}\n')" --out "$T/cfg-out"
expect_bad "config: count 0" "cfg-count.yaml: worlds.count: line 1: 0: must be in 1..10000" experiment sweep --config "$(cfg count 'worlds: {count: 0}\n')" --out "$T/cfg-out"
expect_bad "config: width not an integer" "cfg-width.yaml: worlds.width: line 2: expected an integer, got '12.5'" experiment sweep --config "$(cfg width 'worlds:\n  width: 12.5\n')" --out "$T/cfg-out"
expect_bad "config: unknown key in worlds" "cfg-wkey.yaml: worlds.widht: line 1: unknown key (known: count, seeds, width, height, obstacles, shape, min_size, max_size)" experiment sweep --config "$(cfg wkey 'worlds: {widht: 12}\n')" --out "$T/cfg-out"
expect_bad "config: unknown key" "cfg-key.yaml: radiuses: line 1: unknown key (known: title, planners, vary, radii, values, radius, worlds, maps, starts, repetitions, kind)" experiment sweep --config "$(cfg key 'radiuses: [0.5]\n')" --out "$T/cfg-out"
expect_bad "config: a key that is a list" "cfg-listkey.yaml: keys: line 1: a key is a list: keys are names" experiment sweep --config "$(cfg listkey '{[a]: 1}\n')" --out "$T/cfg-out"
expect_bad "config: empty planner list" "cfg-noplanner.yaml: planners: line 1: the list is empty: name at least one planner" experiment sweep --config "$(cfg noplanner 'planners: []\n')" --out "$T/cfg-out"
expect_bad "config: planners a scalar" "cfg-plscalar.yaml: planners: line 1: expected a list of texts, e.g. [a, b], got 'stc'" experiment sweep --config "$(cfg plscalar 'planners: stc\n')" --out "$T/cfg-out"
expect_bad "config: a planner that is a mapping" "cfg-plmap.yaml: planners[1]: line 1: expected a text, got a mapping" experiment sweep --config "$(cfg plmap 'planners: [stc, {a: 1}]\n')" --out "$T/cfg-out"
expect_bad "config: a planner listed twice" "cfg-twice.yaml: planners: 'stc' is listed twice" experiment sweep --config "$(cfg twice 'planners: [stc, full_stc, stc]\n')" --out "$T/cfg-out"
expect_bad "config: title a list" "cfg-title.yaml: title: line 1: expected a text, got a list" experiment sweep --config "$(cfg title 'title: [a]\n')" --out "$T/cfg-out"
expect_bad "config: empty radii" "cfg-noradii.yaml: radii: line 1: the list is empty: give at least one value" experiment sweep --config "$(cfg noradii 'radii: []\n')" --out "$T/cfg-out"
expect_bad "config: radius .nan" "cfg-rnan.yaml: radii: .nan:" experiment sweep --config "$(cfg rnan 'radii: [.nan]\n')" --out "$T/cfg-out"
expect_bad "config: radius 1e-300 (cell grid)" "cfg-rtiny.yaml: radii: 1e-300: the sub-cell grid would have 1e+301 × 1e+301 sub-cells" experiment sweep --config "$(cfg rtiny 'radii: [0.5, 1e-300]\n')" --out "$T/cfg-out"
expect_bad "config: radius larger than the worlds" "cfg-rbig.yaml: radii: 11: robot is larger than the workspace (the 20×20 worlds)" experiment sweep --config "$(cfg rbig 'radii: [11]\n')" --out "$T/cfg-out"
expect_bad "config: radii with vary: obstacles" "cfg-unused.yaml: radii: line 2: not used with vary: obstacles" experiment sweep --config "$(cfg unused 'vary: obstacles\nradii: [0.5]\n')" --out "$T/cfg-out"
expect_bad "config: steps 0" "cfg-steps.yaml: steps: 0: must be in 1..1000" experiment coverage-vs-time --config "$(cfg steps 'steps: 0\n')" --out "$T/cfg-out"
expect_bad "config: steps -3" "cfg-steps2.yaml: steps: -3: must be in 1..1000" experiment coverage-vs-time --config "$(cfg steps2 'steps: -3\n')" --out "$T/cfg-out"
expect_bad "config: speed .inf" "cfg-speed.yaml: speed: line 1: must be a finite number, got '.inf'" experiment coverage-vs-time --config "$(cfg speed 'speed: .inf\n')" --out "$T/cfg-out"
expect_bad "config: --out is an existing file" "existing.json: --out: exists and is not a folder" experiment sweep --config "$(cfg good 'planners: [stc]\nradii: [0.5]\nworlds: {count: 1, width: 8, height: 8, obstacles: 2}\n')" --out "$T/existing.json"
expect_bad "config: --out under a file" "existing.json/sweep: --out: cannot be used: Not a directory" experiment sweep --config "$T/cfg-good.yaml" --out "$T/existing.json/sweep"
[ "$(cat "$T/existing.json")" = "previous content" ] && [ "$(cat "$T/existing.png")" = "previous picture" ] && ok || bad "an existing output was changed"
# two writers to one --out at once: each writes through its own temporary file
"$CK" plan --planner stc --radius 0.25 --map "$T/room.wkt" --out "$T/shared.json" > /dev/null 2> "$T/w1.err" & w1=$!
"$CK" plan --planner stc --radius 0.25 --map "$T/room.wkt" --out "$T/shared.json" > /dev/null 2> "$T/w2.err" & w2=$!
wait $w1; r1=$?; wait $w2; r2=$?
[ $r1 -eq 0 ] && [ $r2 -eq 0 ] && grep -q '"format": "coverkit.path/1"' "$T/shared.json" && ! ls "$T"/*tmp-coverkit* > /dev/null 2>&1 && ok || bad "concurrent writers: exits $r1 $r2: $(cat "$T/w1.err" "$T/w2.err")"
# a plan with --out and --picture writes both
"$CK" plan --planner stc --radius 0.25 --map "$T/room.wkt" --out "$T/both.json" --picture "$T/both.png" > /dev/null && [ -s "$T/both.json" ] && [ -s "$T/both.png" ] && ok || bad "plan with --out and --picture"
# every shipped config passes the checks (--check runs nothing)
for c in coverage_vs_size coverage_vs_complexity coverage_vs_shape smooth_stc_additions; do
  "$CK" experiment sweep --check --config "$DATA/../../experiments/configs/$c.yaml" > /dev/null && ok || bad "shipped config $c refused"
done
"$CK" experiment coverage-vs-time --check > /dev/null && ok || bad "shipped coverage_vs_time.yaml refused"
"$CK" experiment run "$DATA/../../experiments/configs/coverage_vs_time_constant.yaml" --check > /dev/null && ok || bad "shipped coverage_vs_time_constant.yaml refused"
"$CK" experiment tracc-scenarios --check --out "$T/check-out" | grep -q "config checked: 3 cases" && [ ! -e "$T/check-out" ] && ok || bad "--check of tracc-scenarios"
# an experiment's --out folder is created with its parents
"$CK" experiment sweep --config "$T/cfg-good.yaml" --out "$T/new/deeper" > /dev/null && [ -s "$T/new/deeper/results.csv" ] && ok || bad "sweep into a new nested folder"
# the README's main job: every built-in scenario with every planner (team planners among them, whose
# extra team figures are not columns of the table), every plan valid, the report written
"$CK" demo --out "$T/demo" > "$T/demo.out" 2>&1 && grep -q "plans, 0 invalid" "$T/demo.out" && [ -s "$T/demo/report.html" ] &&
  ok || bad "demo: $(tail -2 "$T/demo.out")"
# ---------------------------------------------------------------------------------------------

# evaluate's verdict on pieces far outside the map (issue 12): invalid (exit 1), in seconds
printf 'POLYGON((0 0,10 0,10 10,0 10,0 0),(4 4,4 6,6 6,6 4,4 4))' > "$T/room10.wkt"
far_case() {  # name, segment JSON
  printf '{"format":"coverkit.path/1","robot_radius":0.25,"robots":[{"start":[1,1],"segments":[%s]}]}' "$2" > "$T/far.json"
  timeout 60 "$CK" evaluate --map "$T/room10.wkt" --path "$T/far.json" > "$T/far.out" 2>&1
  local rc=$?
  [ $rc -eq 1 ] && grep -q 'valid: no' "$T/far.out" && ok || bad "evaluate $1: exit $rc, $(head -2 "$T/far.out")"
}
for c in 1e150 1e160 1e200 1e300; do
  far_case "arc about ($c, 1) the long way" '{"type":"arc","from":[1,1],"to":[1,1.5],"center":['$c',1],"ccw":true}'
done
far_case "segment to x = 7.2e9" '{"type":"line","from":[1,1],"to":[7.2e9,1]}'
far_case "near-full circle of radius 2e154" '{"type":"arc","from":[1,1],"to":[1,1.0000000000000002],"center":[2e154,1],"ccw":true}'
far_case "arc of radius 1e7" '{"type":"arc","from":[1,1],"to":[1,1.5],"center":[1e7,1],"ccw":true}'
far_case "arc of radius 1e12" '{"type":"arc","from":[1,1],"to":[1,1.5],"center":[1e12,1],"ccw":true}'

# good input
if "$CK" plan --planner stc --radius 0.25 --map "$DATA/pillars.wkt" --out "$T/good.json" --picture "$T/good.svg" > "$T/stdout"; then ok; else bad "plan failed"; fi
[ -s "$T/good.svg" ] && ok || bad "no picture"
if "$CK" evaluate --map "$DATA/pillars.wkt" --path "$T/good.json" --json > "$T/eval.json"; then ok; else bad "evaluate failed: $(cat "$T/eval.json")"; fi
grep -q '"valid": true' "$T/eval.json" && grep -q '"violations": \[\]' "$T/eval.json" && grep -q '"area_coverage"' "$T/eval.json" && grep -q '"coverable_coverage"' "$T/eval.json" && ok || bad "evaluate JSON: $(head -c 300 "$T/eval.json")"
"$CK" plan --planner stc --radius 0.25 --map "$DATA/pillars.wkt" --out "$T/again.json" > /dev/null
cmp -s "$T/good.json" "$T/again.json" && ok || bad "same input, different output"
"$CK" plan --planner stc --radius 0.25 --map "$DATA/pillars.wkt" --out "$T/good.csv" > /dev/null && head -1 "$T/good.csv" | grep -q '^robot,seq,x,y$' && ok || bad "csv"
"$CK" evaluate --map "$DATA/pillars.wkt" --radius 0.25 --path "$T/good.csv" > /dev/null && ok || bad "evaluate csv"
"$CK" plan --planner stc --radius 0.25 --map "$DATA/pillars.wkt" --out "$T/good.geojson" > /dev/null && grep -q LineString "$T/good.geojson" && ok || bad "geojson"
"$CK" render --map "$DATA/office.yaml" --radius 0.1 --planner stc --cells --tree --out "$T/render.png" && [ -s "$T/render.png" ] && ok || bad "render"
"$CK" list | grep -q '^stc:' && ok || bad "list"
"$CK" plan --help | grep -q -- '--planner' && ok || bad "help"
"$CK" evaluate --map "$DATA/pillars.wkt" --path "$T/good.json" --start 1,1 > "$T/start.out"; rc=$?
[ $rc -eq 1 ] && grep -q "violation \[start\]" "$T/start.out" && ok || bad "start not checked (rc $rc)"
# C-space
"$CK" cspace --map "$DATA/pillars.wkt" --radius 0.5 --start 1,1 --out "$T/cs.json" --picture "$T/cs.svg" > /dev/null && grep -q '"format": "coverkit.cspace/1"' "$T/cs.json" && grep -q '"start_component": 0' "$T/cs.json" && grep -q '"type": "arc"' "$T/cs.json" && [ -s "$T/cs.svg" ] && ok || bad "cspace json"
"$CK" cspace --map "$DATA/pillars.wkt" --radius 0.5 --out "$T/cs.geojson" > /dev/null && grep -q '"cobstacle"' "$T/cs.geojson" && ok || bad "cspace geojson"
"$CK" cspace --map "$DATA/pillars.wkt" --radius 0.5 --out "$T/cs2.json" > /dev/null; "$CK" cspace --map "$DATA/pillars.wkt" --radius 0.5 --out "$T/cs3.json" > /dev/null
cmp -s "$T/cs2.json" "$T/cs3.json" && ok || bad "cspace not deterministic"
"$CK" render --map "$DATA/pillars.wkt" --radius 0.5 --planner stc --cspace --out "$T/overlay.png" && [ -s "$T/overlay.png" ] && ok || bad "render --cspace"
expect_bad "cspace radius 0" "robot radius must be > 0" cspace --map "$T/room.wkt" --radius 0 --out "$T/out.json"
expect_bad "cspace start in obstacle" "inside an obstacle" cspace --map "$T/room.wkt" --radius 0.25 --start 5,5 --out "$T/out.json"
expect_bad "cspace bad format" "unknown output format" cspace --map "$T/room.wkt" --radius 0.25 --out "$T/out.csv"
expect_bad "cspace hole outside" "hole is outside its outer ring" cspace --map "$T/holeout.wkt" --radius 0.25 --out "$T/out.json"
expect_bad "cspace NaN" "not finite" cspace --map "$T/nan.wkt" --radius 0.25 --out "$T/out.json"
expect_bad "cspace radius too large" "robot is larger than the workspace" cspace --map "$T/room.wkt" --radius 8 --out "$T/out.json"
expect_bad "cspace duplicate vertex" "repeated vertex" cspace --map "$T/dup.wkt" --radius 0.25 --out "$T/out.json"
expect_bad "cspace degenerate ring" "zero area" cspace --map "$T/flat.wkt" --radius 0.25 --out "$T/out.json"
expect_bad "cspace self-intersecting" "self-intersecting ring" cspace --map "$T/bowtie.wkt" --radius 0.25 --out "$T/out.json"
"$CK" evaluate --map "$DATA/pillars.wkt" --path "$T/good.json" --cspace --json | grep -q '"valid": true' && ok || bad "evaluate --cspace on a valid STC path"
# a path that cuts through the obstacle is reported invalid (exit 1), with the segment
cat > "$T/cut.json" <<'JSON'
{"format":"coverkit.path/1","planner":"hand","robot_radius":0.25,"robots":[{"start":[1,5],"segments":[{"type":"line","from":[1,5],"to":[9,5]}]}]}
JSON
"$CK" evaluate --map "$T/room.wkt" --path "$T/cut.json" --json > "$T/cut.out"; rc=$?
[ $rc -eq 1 ] && grep -q '"valid": false' "$T/cut.out" && grep -q '"kind": "clearance"' "$T/cut.out" && ok || bad "cut path not caught (rc $rc)"
"$CK" evaluate --map "$T/room.wkt" --path "$T/cut.json" --json --cspace | grep -q '"kind": "cspace"' && ok || bad "cut path not caught by the C-space check"

# the BSA paper's experiment: one command, CSV + table + chart; bad options leave no folder
"$CK" experiment bsa-backtracking --seeds 3 --out "$T/bsa" --quiet > "$T/bsa.out" && [ "$(csv_count "$T/bsa/results.csv" "r['valid'] == '1' and r['status'] == 'exact_solution'")" -eq 6 ] && grep -q '| backtracks' "$T/bsa/summary.md" && grep -q '<svg' "$T/bsa/backtracking.svg" && ok || bad "bsa experiment: $(head -c 300 "$T/bsa.out")"
"$CK" experiment bsa-backtracking --seeds 3 --out "$T/bsa2" --jobs 1 --quiet > /dev/null && [ "$(csv_untimed "$T/bsa/results.csv")" = "$(csv_untimed "$T/bsa2/results.csv")" ] && cmp -s "$T/bsa/summary.md" "$T/bsa2/summary.md" && cmp -s "$T/bsa/backtracking.svg" "$T/bsa2/backtracking.svg" && ok || bad "bsa experiment not deterministic"
expect_bad "unknown experiment" "experiment: nope: unknown experiment" experiment nope --out "$T/out.json"
# coverage against robot size from a config: a tiny one here; bad configs are exit 2 with no output
printf 'planners: [stc, full_stc]\nradii: [0.5]\nworlds: {count: 1, width: 8, height: 8, obstacles: 2, shape: rotated}\n' > "$T/cvs.yaml"
"$CK" experiment coverage-vs-size --config "$T/cvs.yaml" --out "$T/cvs" > /dev/null && [ "$(grep -c ',exact_solution,1,' "$T/cvs/results.csv")" -eq 2 ] && grep -q "<svg" "$T/cvs/chart.svg" && ok || bad "coverage-vs-size: $(cat "$T/cvs/results.csv" 2>/dev/null)"
printf 'planners: [full_stc]\nvary: shape\nvalues: [discs, stars]\nradius: 0.5\nworlds: {count: 1, width: 8, height: 8, obstacles: 2}\n' > "$T/shape.yaml"
"$CK" experiment sweep --config "$T/shape.yaml" --out "$T/shape" > /dev/null && grep -q ',worlds,1,shape,discs,full_stc,0,0.5,default,exact_solution,1,' "$T/shape/results.csv" && grep -q ',worlds,1,shape,stars,full_stc,' "$T/shape/results.csv" && ok || bad "sweep over shapes: $(cat "$T/shape/results.csv" 2>/dev/null)"
printf 'planners: [stc, full_stc]\nradius: 0.5\nsteps: 4\nworlds: {count: 1, width: 8, height: 8, obstacles: 2}\n' > "$T/time.yaml"
"$CK" experiment coverage-vs-time --config "$T/time.yaml" --out "$T/time" --quiet > /dev/null && [ "$(csv_count "$T/time/results.csv" "r['planner'] == 'full_stc' and r['valid'] == '1' and 0 < float(r['coverage_step_2']) < float(r['coverage_step_4']) == float(r['coverable_coverage'])")" -eq 1 ] && grep -q '<svg' "$T/time/chart.svg" && ok || bad "coverage-vs-time: $(cat "$T/time/results.csv" 2>/dev/null)"
printf 'time: fast\n' > "$T/time-bad2.yaml"
expect_bad "time config time" "time-bad2.yaml: time: fast: must be robot or constant" experiment coverage-vs-time --config "$T/time-bad2.yaml" --out "$T/out.json"
printf 'omega_max: -1\n' > "$T/time-bad3.yaml"
expect_bad "time config omega_max" "time-bad3.yaml: omega_max: must be a finite number > 0" experiment coverage-vs-time --config "$T/time-bad3.yaml" --out "$T/out.json"
printf 'speed: 0\n' > "$T/time-bad.yaml"
expect_bad "time config speed" "time-bad.yaml: speed: must be > 0" experiment coverage-vs-time --config "$T/time-bad.yaml" --out "$T/out.json"
printf 'vary: colour\n' > "$T/cvs-bad4.yaml"
expect_bad "config vary" "cvs-bad4.yaml: vary: colour: must be radius, obstacles or shape" experiment sweep --config "$T/cvs-bad4.yaml" --out "$T/out.json"
expect_bad "sweep without config" "--config: the sweep needs a config file" experiment sweep --out "$T/out.json"
printf 'planners: [stc, nope]\n' > "$T/cvs-bad1.yaml"; printf 'planners: [stc\n' > "$T/cvs-bad2.yaml"; printf 'radii: [0.2, -1]\n' > "$T/cvs-bad3.yaml"
expect_bad "config unknown planner" "cvs-bad1.yaml: planners: unknown planner 'nope'" experiment coverage-vs-size --config "$T/cvs-bad1.yaml" --out "$T/out.json"
printf 'planners: [stc, "smooth_stc:corners=round"]\n' > "$T/cvs-bad5.yaml"; printf 'planners: ["smooth_stc:corners"]\n' > "$T/cvs-bad6.yaml"
printf 'planners: ["stc:tree=bfs"]\nradii: [0.5]\nworlds: {count: 1, width: 8, height: 8, obstacles: 2}\n' > "$T/cvs-param.yaml"
"$CK" experiment coverage-vs-size --config "$T/cvs-param.yaml" --out "$T/cvs-param" > /dev/null && grep -q ',worlds,1,radius,0.5,stc:tree=bfs,0,0.5,default,exact_solution,1,' "$T/cvs-param/results.csv" && ok || bad "planner with parameters in a config: $(cat "$T/cvs-param/results.csv" 2>/dev/null)"
expect_bad "config planner parameter" "cvs-bad5.yaml: planners: 'smooth_stc:corners=round': --param: corners=round: must be one of auto|fill|keep" experiment coverage-vs-size --config "$T/cvs-bad5.yaml" --out "$T/out.json"
expect_bad "config planner parameter syntax" "cvs-bad6.yaml: planners: 'smooth_stc:corners': parameters are key=value" experiment coverage-vs-size --config "$T/cvs-bad6.yaml" --out "$T/out.json"
expect_bad "config syntax" "cvs-bad2.yaml: line 2: YAML does not parse" experiment coverage-vs-size --config "$T/cvs-bad2.yaml" --out "$T/out.json"
expect_bad "config radius" "cvs-bad3.yaml: radii: -1: must be > 0" experiment coverage-vs-size --config "$T/cvs-bad3.yaml" --out "$T/out.json"
expect_bad "config missing" "nothere.yaml: file: cannot be read" experiment coverage-vs-size --config "$T/nothere.yaml" --out "$T/out.json"
"$CK" experiment tracc-scenarios --out "$T/tracc" --quiet > /dev/null && [ "$(csv_count "$T/tracc/results.csv" "r['valid'] == '1'")" -eq 3 ] && [ "$(csv_count "$T/tracc/results.csv" "r['scenario'] == '1' and r['cells_entered'] == '115'")" -eq 1 ] && [ -s "$T/tracc/scenario-1.svg" ] && ok || bad "tracc scenarios: $(cat "$T/tracc/results.csv" 2>/dev/null)"
expect_bad "experiment seeds 0" "--seeds: 0: must be in 1..100000" experiment bsa-backtracking --seeds 0 --out "$T/out.json"
expect_bad "experiment obstacles" "--obstacles: blobs: must be clustered or scattered" experiment bsa-backtracking --obstacles blobs --out "$T/out.json"
# the grid-rail planners on a map, end to end
for p in tracc bsa_zigzag full_stc; do
  "$CK" plan --planner $p --radius 0.125 --map "$DATA/rooms.grid" --out "$T/$p.json" > /dev/null && "$CK" evaluate --map "$DATA/rooms.grid" --radius 0.125 --path "$T/$p.json" --json | grep -q '"valid": true' && ok || bad "$p on rooms.grid"
done

# ---------------------------------------------------------------------------------------------
# Map and path-file readers (issue 12): images read as map_server reads them, limits checked
# before anything is allocated, wrong types refused with exit 2 naming the file and the place.
# The issue's image: 5x5 16-bit RGBA, white but for one grey 49151/65535 pixel (unknown): 24 free.
printf '\211\120\116\107\015\012\032\012\000\000\000\015\111\110\104\122\000\000\000\005\000\000\000\005\020\006\000\000\000\335\377\372\246\000\000\000\026\111\104\101\124\170\332\143\370\117\044\140\040\133\341\176\060\244\246\211\270\000\000\173\132\306\171\020\306\252\277\000\000\000\000\111\105\116\104\256\102\140\202' > "$T/rgba16.png"
printf 'image: rgba16.png\nresolution: 1\norigin: [0, 0, 0]\n' > "$T/rgba16.yaml"
"$CK" cspace --map "$T/rgba16.yaml" --radius 0.01 --out "$T/rgba16-cspace.json" > "$T/rgba16.out" 2>&1 && grep -q 'of free area 24 ' "$T/rgba16.out" && ok || bad "16-bit RGBA map: $(cat "$T/rgba16.out")"
printf 'image: rgba16.png\nresolution: 1\norigin: [1e300, 0, 0]\n' > "$T/farorigin.yaml"
expect_bad "a ROS map whose origin is at 1e300" "coordinates: a coordinate of magnitude about 10^300 is beyond the limit of 10^15" plan --planner stc --radius 0.25 --map "$T/farorigin.yaml" --out "$T/existing.json"
# 165 bytes announcing 100000 x 100000 pixels
printf '\211\120\116\107\015\012\032\012\000\000\000\015\111\110\104\122\000\001\206\240\000\001\206\240\010\000\000\000\000\215\071\124\024\000\000\000\170\111\104\101\124\170\332\354\301\041\001\000\000\000\002\040\377\237\326\033\006\040\005\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\156\015\000\000\377\377\131\223\353\253' > "$T/huge.png"
printf 'image: huge.png\nresolution: 0.05\norigin: [0, 0, 0]\n' > "$T/huge.yaml"
printf 'P5\n16000 16000\n255\n' > "$T/hdr.pgm"; printf 'image: hdr.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n' > "$T/hdr.yaml"
printf 'image: hdr.pgm\nresolution: 0.05\norigin: [0, 0, 0, 0]\n' > "$T/origin4.yaml"
printf 'type octile\nheight 100000\nwidth 100000\nmap\n....\n' > "$T/huge.map"
printf 'type octile\nheight 2\nwidth 3junk\nmap\n...\n...\n' > "$T/junk.map"
printf 'type octile\nheight 2\nwidth 3.5\nmap\n...\n...\n' > "$T/frac.map"
printf 'type octile\nheight 2\nwidth 3\nmap\n...\n...\n...\n' > "$T/extra.map"
printf 'type octile\nheight 2\nwidth 3\nmap\n...\n...\n\n\n' > "$T/trailing.map"
printf '{"type":"GeometryCollection"}' > "$T/gc-missing.geojson"
printf '{"type":"GeometryCollection","geometries":3}' > "$T/gc-number.geojson"
printf '{"type":"Feature","properties":{}}' > "$T/nogeom.geojson"
printf '{"type":"Polygon","crs":{"type":"name","properties":{"name":"EPSG:4326"}},"coordinates":[[[179.9,1],[180.2,1],[180.2,1.1],[179.9,1]]]}' > "$T/lon.geojson"
printf '{"format":7,"robots":[]}' > "$T/fmt.json"
printf '{"format":"coverkit.path/1","planner":3,"robot_radius":0.25,"robots":[{"start":[1,5],"segments":[]}]}' > "$T/planner.json"
printf '{"format":"coverkit.path/1","robot_radius":0.25,"robots":[{"start":[1,5],"segments":[{"type":"arc","from":[1,5],"to":[2,5],"center":[1.5,5],"ccw":"yes"}]}]}' > "$T/ccw.json"
printf 'robot,seq,x,y\n0,0,1,5\n0,1,nan,5\n' > "$T/nan.csv"
expect_bad "png announcing 100000^2 pixels" "huge.png: header: grid of 100000 x 100000 cells is too large (the limit is 268435456 = 2^28 cells)" $(plan) "$T/huge.yaml"
expect_bad "pgm header without data" "hdr.pgm: pixel data: truncated PGM: 0 of 256000000 pixels" $(plan) "$T/hdr.yaml"
expect_bad "ros origin of 4 numbers" "origin4.yaml: origin: expected [x, y, yaw], found 4 numbers" $(plan) "$T/origin4.yaml"
expect_bad "moving ai 100000^2" "huge.map: header: grid of 100000 x 100000 cells is too large (the limit is 268435456" $(plan) "$T/huge.map"
expect_bad "moving ai width 3junk" "junk.map: line 3: bad width '3junk'" $(plan) "$T/junk.map"
expect_bad "moving ai width 3.5" "frac.map: line 3: bad width '3.5'" $(plan) "$T/frac.map"
expect_bad "moving ai extra row" "extra.map: line 7: extra row beyond the height of 2 rows" $(plan) "$T/extra.map"
"$CK" plan --planner stc --radius 0.25 --map "$T/trailing.map" --out "$T/trailing.json" > /dev/null 2>&1 && ok || bad "moving ai: trailing empty lines refused"
expect_bad "geometrycollection without geometries" "gc-missing.geojson: geometries: missing" $(plan) "$T/gc-missing.geojson"
expect_bad "geometrycollection geometries a number" "gc-number.geojson: geometries: expected an array" $(plan) "$T/gc-number.geojson"
expect_bad "feature without geometry" "nogeom.geojson: geometry: missing" $(plan) "$T/nogeom.geojson"
expect_bad "lon/lat crs, longitude out of range" "lon.geojson: coordinates[0][1]: longitude 180.2 outside [-180, 180]" $(plan) "$T/lon.geojson"
expect_bad "path format a number" "fmt.json: format: expected the string" evaluate --map "$T/room.wkt" --path "$T/fmt.json"
expect_bad "path planner a number" "planner.json: planner: expected a string, found number" evaluate --map "$T/room.wkt" --path "$T/planner.json"
expect_bad "path arc ccw a string" "ccw.json: robots[0].segments[0].ccw: expected true or false, found string" evaluate --map "$T/room.wkt" --path "$T/ccw.json"
expect_bad "path csv nan" "nan.csv: line 3: non-finite x 'nan'" evaluate --map "$T/room.wkt" --radius 0.25 --path "$T/nan.csv"
# --------------------------------------------------------------------------------------------- end of the readers block

# --------------------------------------------------------------------------------------------- decompositions (issue 13)
"$CK" list | grep -q '^decomposition boustrophedon:' && "$CK" list | grep -q '^decomposition trapezoidal:' && "$CK" list | grep -q '^decomposition grid:' && ok || bad "list: decompositions"
"$CK" decompose --map "$DATA/pillars.wkt" --radius 0.25 --method boustrophedon --out "$T/cells.json" --picture "$T/cells.svg" > "$T/dec.out" &&
  grep -q '"format": "coverkit.cells/1"' "$T/cells.json" && grep -q '"type": "arc"' "$T/cells.json" && [ -s "$T/cells.svg" ] &&
  grep -q '^boustrophedon: 10 cell(s)' "$T/dec.out" && ok || bad "decompose json: $(cat "$T/dec.out")"
"$CK" decompose --map "$DATA/pillars.wkt" --radius 0.25 --method trapezoidal --param direction=30 --out "$T/cells.geojson" > "$T/dec.out" &&
  grep -q '"kind": "cell"' "$T/cells.geojson" && grep -q '"neighbours"' "$T/cells.geojson" && grep -q 'direction 29.99' "$T/dec.out" && ok || bad "decompose geojson: $(cat "$T/dec.out")"
"$CK" decompose --map "$DATA/pillars.wkt" --radius 0.25 --method grid --out "$T/g1.json" > /dev/null && "$CK" decompose --map "$DATA/pillars.wkt" --radius 0.25 --method grid --out "$T/g2.json" > /dev/null &&
  cmp -s "$T/g1.json" "$T/g2.json" && ok || bad "decompose not deterministic"
"$CK" plan --map "$DATA/pillars.wkt" --radius 0.25 --planner boustrophedon --param direction=best --out "$T/bou.json" > /dev/null &&
  "$CK" evaluate --map "$DATA/pillars.wkt" --path "$T/bou.json" --json | grep -q '"valid": true' && ok || bad "plan boustrophedon"
expect_bad "decompose: unknown method" "--method: voronoi: unknown decomposition (known: boustrophedon, grid, trapezoidal)" decompose --map "$T/room.wkt" --radius 0.25 --method voronoi --out "$T/out.json"
expect_bad "decompose: direction not a number" "--param: direction=north: 'north' is not a number" decompose --map "$T/room.wkt" --radius 0.25 --method boustrophedon --param direction=north --out "$T/out.json"
expect_bad "decompose: direction out of range" "--param: direction=720: out of range [-360:360]" decompose --map "$T/room.wkt" --radius 0.25 --method trapezoidal --param direction=720 --out "$T/out.json"
expect_bad "decompose: parameter of another model" "unknown parameter of decomposition 'grid'" decompose --map "$T/room.wkt" --radius 0.25 --method grid --param direction=10 --out "$T/out.json" --picture "$T/out.png"
expect_bad "decompose: C-free empty" "C-free is empty: a disc of this radius fits nowhere" decompose --map "$T/room.wkt" --radius 2.5 --method boustrophedon --out "$T/out.json" --picture "$T/out.png"
expect_bad "decompose: bad output format" "unknown output format" decompose --map "$T/room.wkt" --radius 0.25 --method boustrophedon --out "$T/out.csv"
expect_bad "experiment decompositions: --seeds 0" "--seeds: 0: must be 1 to 10000" experiment decompositions --seeds 0 --out "$T/dec-out"
expect_bad "experiment decompositions: --size" "--size: 10: not a setting of the decompositions experiment" experiment decompositions --size 10 --out "$T/dec-out"
expect_bad "plan boustrophedon: direction not a number" "--param: direction=west: must be a number in [-360:360] or best" plan --map "$T/room.wkt" --radius 0.25 --planner boustrophedon --param direction=west --out "$T/out.json"
expect_bad "plan boustrophedon: unknown decomposition" "--param: decomposition=grid: must be one of boustrophedon|trapezoidal" plan --map "$T/room.wkt" --radius 0.25 --planner boustrophedon --param decomposition=grid --out "$T/out.json"

# --------------------------------------------------------------------------------------------- path post-processing
has_phases() { local f="$1"; shift; for phase in "$@"; do grep -q "^ *$phase" "$f" || return 1; done; }
# --post runs before the validator; the path file gets the processor's statistics and the robot-time
# metrics; a bad step is refused before any work, exit 2, no file
"$CK" plan --map "$DATA/pillars.wkt" --radius 0.25 --planner stc --post fillet --post "fillet:max_radius=0.5;keep_coverage=false" --out "$T/post.json" --timings > "$T/post.out" 2> "$T/post.err" &&
  python3 - "$T/post.json" <<'PYEOF' && has_phases "$T/post.err" plan post fillet validate && ok || bad "plan --post fillet: $(cat "$T/post.out" "$T/post.err")"
import json, sys
d = json.load(open(sys.argv[1]))
s, m = d["statistics"], d["metrics"]
assert s["post_fillet_rounded"] > 0 and s["post_fillet_reverted"] == 0, s
assert m["turns"] < s["post_fillet_corners"] and m["reversals"] == 0 and m["max_curvature"] > 0 and m["robot_time_s"] > 0, m
assert any(g["type"] == "arc" for g in d["robots"][0]["segments"])
PYEOF
expect_bad "plan --post: unknown processor" "--post: smoothen: unknown path processor (known: fillet" plan --map "$T/room.wkt" --radius 0.25 --planner stc --post smoothen --out "$T/out.json"
expect_bad "plan --post: unknown parameter" "--post: fillet:radius: unknown parameter of path processor 'fillet'" plan --map "$T/room.wkt" --radius 0.25 --planner stc --post "fillet:radius=1" --out "$T/out.json"
expect_bad "plan --post: parameter out of range" "--post: fillet:max_radius=-1: out of range" plan --map "$T/room.wkt" --radius 0.25 --planner stc --post "fillet:max_radius=-1" --out "$T/out.json"
expect_bad "plan --post: parameter without a value" "--post: fillet:max_radius: expected KEY=VALUE" plan --map "$T/room.wkt" --radius 0.25 --planner stc --post "fillet:max_radius" --out "$T/out.json"
expect_bad "plan --post: smooth's iterations out of range" "--post: smooth:iterations=0: out of range" plan --map "$T/room.wkt" --radius 0.25 --planner stc --post "smooth:iterations=0" --out "$T/out.json"
"$CK" plan --map "$DATA/pillars.wkt" --radius 0.25 --planner smooth_stc --post smooth --out "$T/smooth.json" > "$T/smooth.out" 2>&1 &&
  python3 - "$T/smooth.json" <<'PYEOF' && ok || bad "plan --post smooth: $(cat "$T/smooth.out")"
import json, sys
d = json.load(open(sys.argv[1])); s = d["statistics"]
assert s["post_smooth_reverted"] == 0 and s["post_smooth_stretches"] > 0 and s["post_smooth_iterations"] > 0, s
assert s["post_smooth_cost_after"] <= s["post_smooth_cost_before"], s
PYEOF
expect_bad "plan --v-max not positive" "--v-max" plan --map "$T/room.wkt" --radius 0.25 --planner stc --v-max 0 --out "$T/out.json"
printf 'planners: ["stc+fillet:max_radius=0.5", "stc+nope"]\n' > "$T/cvs-bad7.yaml"
expect_bad "config path processor" "cvs-bad7.yaml: planners: 'stc+nope': --post: nope: unknown path processor" experiment coverage-vs-size --config "$T/cvs-bad7.yaml" --out "$T/out.json"
printf 'planners: ["stc", "stc+fillet"]\nradii: [0.5]\nworlds: {count: 1, width: 8, height: 8, obstacles: 2}\n' > "$T/cvs-post.yaml"
"$CK" experiment coverage-vs-size --config "$T/cvs-post.yaml" --out "$T/cvs-post" > /dev/null &&
  [ "$(csv_count "$T/cvs-post/results.csv" "r['planner'] == 'stc+fillet' and r['valid'] == '1' and float(r['turns']) < 4")" -eq 1 ] &&
  ok || bad "planner with a path processor in a config: $(cat "$T/cvs-post/results.csv" 2>/dev/null)"

# --------------------------------------------------------------------------------------------- timings and threads
"$CK" plan --map "$DATA/rooms.grid" --radius 0.125 --planner stc --out "$T/t0.json" --metrics full > /dev/null 2> "$T/t0.err" &&
  "$CK" plan --map "$DATA/rooms.grid" --radius 0.125 --planner stc --out "$T/t1.json" --metrics full --timings --threads 1 > /dev/null 2> "$T/t1.err" &&
  "$CK" plan --map "$DATA/rooms.grid" --radius 0.125 --planner stc --out "$T/t3.json" --metrics full --timings --threads 3 > /dev/null 2> "$T/t3.err" &&
  cmp -s "$T/t0.json" "$T/t1.json" && cmp -s "$T/t0.json" "$T/t3.json" && [ ! -s "$T/t0.err" ] &&
  has_phases "$T/t1.err" read cells plan validate metrics "coverable region" write total "peak memory" &&
  ok || bad "plan --timings --threads: outputs differ or phases missing: $(cat "$T/t1.err")"
"$CK" evaluate --map "$DATA/rooms.grid" --path "$T/t0.json" --json --threads 1 > "$T/e1.out" 2> /dev/null &&
  "$CK" evaluate --map "$DATA/rooms.grid" --path "$T/t0.json" --json --threads 2 --timings > "$T/e2.out" 2> "$T/e2.err" &&
  cmp -s "$T/e1.out" "$T/e2.out" && grep -q "^  metrics" "$T/e2.err" && grep -q "^  validate" "$T/e2.err" && ok || bad "evaluate --timings --threads"
# --metrics: plan's default is basic (no areas), area adds the covered area, full (evaluate's
# default) the coverable region; the exact validator runs at every level, and the path and the
# metrics a level shares with the next are the same
"$CK" plan --map "$DATA/rooms.grid" --radius 0.125 --planner stc --out "$T/b0.json" --timings > /dev/null 2> "$T/b0.err" &&
  "$CK" plan --map "$DATA/rooms.grid" --radius 0.125 --planner stc --out "$T/a0.json" --metrics area > /dev/null 2> /dev/null &&
  has_phases "$T/b0.err" validate metrics && ! grep -q "coverable region" "$T/b0.err" && ! grep -q "covered area" "$T/b0.err" &&
  python3 - "$T/b0.json" "$T/a0.json" "$T/t0.json" <<'EOF' &&
import json, sys
basic, area, full = (json.load(open(f)) for f in sys.argv[1:4])
assert basic["robots"] == area["robots"] == full["robots"]    # the same path
areas = {"free_area", "covered_area", "area_coverage", "area_coverage_error", "area_exact", "swept_area_overlap"}
assert not areas & set(basic["metrics"]) and areas <= set(area["metrics"])
assert "coverable_coverage" not in area["metrics"] and "coverable_coverage" in full["metrics"]
assert basic["metrics"] == {k: v for k, v in area["metrics"].items() if k not in areas}
assert area["metrics"] == {k: v for k, v in full["metrics"].items() if not k.startswith("coverable")}
EOF
  ok || bad "plan --metrics basic (the default) and area: $(head -c 300 "$T/b0.json")"
"$CK" evaluate --map "$DATA/rooms.grid" --path "$T/b0.json" --json --metrics basic > "$T/eb.out" 2> /dev/null && grep -q '"valid": true' "$T/eb.out" &&
  ! grep -q '"coverable_coverage"' "$T/eb.out" && ! grep -q '"area_method"' "$T/eb.out" && grep -q '"coverable_coverage"' "$T/e1.out" &&
  grep -q '"area_method"' "$T/e1.out" && ok || bad "evaluate --metrics basic"
expect_bad "plan: --metrics unknown" "--metrics" plan --map "$T/room.wkt" --radius 0.25 --planner stc --metrics most --out "$T/out.json"
expect_bad "plan: --threads not a number" "--threads" plan --map "$T/room.wkt" --radius 0.25 --planner stc --threads many --out "$T/out.json"
expect_bad "cspace: --threads not a number" "--threads" cspace --map "$T/room.wkt" --radius 0.25 --threads many --out "$T/out.json"

# --------------------------------------------------------------------------------------------- teams
team() { echo plan --planner multi_stc_balanced --map "$T/room.wkt" --radius 0.25 --out "$T/out.json"; }
printf 'format: coverkit.scenario/1\ndynamic_obstacles:\n  - radius: 0.3\n    waypoints: [[0, 8, 8], [1, 8]]\n' > "$T/short.yaml"
printf 'format: coverkit.scenario/1\ndynamic_obstacle: []\n' > "$T/typo.yaml"
printf 'format: coverkit.scenario/1\ndynamic_obstacles:\n  - radius: 0.5\n    waypoints: [[0, 1.2, 1]]\n' > "$T/onrobot.yaml"
printf 'format: coverkit.scenario/1\ndynamic_obstacles:\n  - radius: 0.3\n    waypoints: [[0, 8, 8]]\n' > "$T/still.yaml"
expect_bad "team: two starts nearer than 2r" "--start: robots 0 and 1: start closer than the sum of their radii" $(team) --start 1,1 --start 1,1.4
expect_bad "team: a start in an obstacle" "inside an obstacle" $(team) --start 1,1 --start 5,5
expect_bad "team: fewer --robots than starts" "--robots: 1: fewer robots than --start options" $(team) --start 1,1 --start 3,1 --robots 1
expect_bad "team: --robots negative" "--robots: -2: must be >= 1" $(team) --robots -2
expect_bad "team: a single-robot planner" "--planner: stc: plans for one robot" $(plan) "$T/room.wkt" --robots 2
expect_bad "scenario: a single-robot planner among moving obstacles" "--planner: stc: plans in static worlds, and the scenario has 1 moving obstacle(s)" \
  $(plan) "$T/room.wkt" --start 1,1 --scenario "$T/still.yaml"
expect_bad "scenario: a waypoint of two numbers" "short.yaml: dynamic_obstacles[0].waypoints[1]: expected [t, x, y]" $(team) --scenario "$T/short.yaml"
expect_bad "scenario: a misspelt key" "typo.yaml: dynamic_obstacle: unknown key" $(team) --scenario "$T/typo.yaml"
expect_bad "scenario: missing file" "nothere.yaml" $(team) --scenario "$T/nothere.yaml"
expect_bad "scenario: an obstacle on a robot" "onrobot.yaml: dynamic_obstacles[0]: starts on robot 0" $(team) --start 1,1 --scenario "$T/onrobot.yaml"
printf 'format: coverkit.scenario/1\ndynamic_obstacles:\n  - radius: 100\n    waypoints: [[0, 5, 5], [10, 200, 200]]\n' > "$T/everywhere.yaml"
expect_bad "team: --robots with every place under an obstacle" "--robots: 2: no sub-cell of free mega-cells reachable from the default start is clear of the moving obstacles' first places" \
  $(team) --robots 2 --scenario "$T/everywhere.yaml"
"$CK" plan --planner multi_stc_balanced --map "$DATA/maze.map" --radius 0.25 --robots 3 --out "$T/team.json" > /dev/null 2>&1 &&
  python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert len(d['robots']) == 3 and all(len(r['timeline']) > 1 for r in d['robots'])" "$T/team.json" &&
  "$CK" evaluate --map "$DATA/maze.map" --path "$T/team.json" > "$T/team.out" 2>&1 && grep -q "valid: yes" "$T/team.out" &&
  grep -Eq "missed_from_starts +0$" "$T/team.out" && grep -Eq "missed_from_team +0$" "$T/team.out" &&
  "$CK" evaluate --map "$DATA/maze.map" --path "$T/team.json" --scenario "$T/still.yaml" > "$T/team2.out" 2>&1; rc=$?
[ -f "$T/team.out" ] && grep -q "valid: yes" "$T/team.out" && { [ $rc -eq 0 ] || grep -q "robot_obstacle" "$T/team2.out"; } && ok ||
  bad "team plan and its evaluation: $(cat "$T/team.out" "$T/team2.out" 2> /dev/null | head -5)"
# a radius whose sub-cell centres are not doubles (r = 0.4): the team plans on sub-cells a little
# larger than 2r (written as cell_size_exact), and evaluate, reading that size, finds it valid
"$CK" plan --planner multi_st --map "$T/room.wkt" --radius 0.4 --robots 3 --scenario "$T/still.yaml" --out "$T/wide.json" > /dev/null 2>&1 &&
  python3 -c "import json,sys; from fractions import Fraction as F; d=F(json.load(open(sys.argv[1]))['cell_size_exact']); assert F(4,5) < d < F(4,5) + F(1, 2**20)" "$T/wide.json" &&
  "$CK" evaluate --map "$T/room.wkt" --path "$T/wide.json" --scenario "$T/still.yaml" 2>&1 | grep -q "valid: yes" && ok ||
  bad "team at r = 0.4: $(head -c 300 "$T/wide.json" 2> /dev/null)"
# among a moving obstacle: planned around it, and valid against it
"$CK" plan --planner multi_stc_balanced --map "$T/room.wkt" --radius 0.25 --start 1,1 --start 9,9 --scenario "$T/still.yaml" \
  --out "$T/moving.json" > /dev/null 2>&1 &&
  "$CK" evaluate --map "$T/room.wkt" --path "$T/moving.json" --scenario "$T/still.yaml" 2>&1 | grep -q "valid: yes" && ok ||
  bad "team plan among a moving obstacle"
expect_bad "evaluate: a malformed scenario" "typo.yaml: dynamic_obstacle: unknown key" evaluate --map "$DATA/maze.map" --path "$T/team.json" --scenario "$T/typo.yaml"
# evaluate: robots that start too near each other make an invalid plan, which the validator reports
printf '{"format":"coverkit.path/1","robots":[{"start":[1.5,1.5],"segments":[],"timeline":[[0,1.5,1.5]]},{"start":[1.7,1.5],"segments":[],"timeline":[[0,1.7,1.5]]}]}\n' > "$T/close.json"
"$CK" evaluate --map "$DATA/maze.map" --radius 0.25 --path "$T/close.json" > "$T/close.out" 2>&1; rc=$?
[ $rc -ne 2 ] && grep -q "valid: no" "$T/close.out" && grep -q "robot_robot" "$T/close.out" && ok || bad "evaluate: starts too near: exit $rc, $(head -3 "$T/close.out")"
# multi_st: its knowledge base is a file of rules; a bad one is bad input naming the file and the place
mst() { echo plan --planner multi_st --map "$DATA/maze.map" --radius 0.5 --robots 2 --out "$T/out.json"; }
printf 'format: coverkit.kb/1\nrules:\n  - {name: a, event: robot_ahead, action: teleport}\n' > "$T/kb-action.yaml"
printf 'format: coverkit.kb/1\nrules:\n  - {name: a, event: robot_ahead, action: wait, weight: 2}\n' > "$T/kb-weight.yaml"
printf 'format: coverkit.kb/1\nrule: []\n' > "$T/kb-typo.yaml"
expect_bad "knowledge base: an unknown action" "kb-action.yaml: rules[0].action: 'teleport' is not one of" $(mst) --param "kb=$T/kb-action.yaml"
expect_bad "knowledge base: a weight above 1" "kb-weight.yaml: rules[0].weight: expected a number in [0, 1]" $(mst) --param "kb=$T/kb-weight.yaml"
expect_bad "knowledge base: a misspelt key" "kb-typo.yaml: rule: unknown key" $(mst) --param "kb=$T/kb-typo.yaml"
expect_bad "knowledge base: missing file" "nothere-kb.yaml: cannot read the knowledge base file" $(mst) --param "kb=$T/nothere-kb.yaml"
# a team plan of multi_st, valid, with every reachable sub-cell; kb=off and a rule file of one's own run too
printf 'format: coverkit.kb/1\nrules:\n  - {name: only_wait, event: robot_ahead, action: wait}\n' > "$T/kb-own.yaml"
"$CK" plan --planner multi_st --map "$DATA/maze.map" --radius 0.5 --robots 4 --out "$T/mst.json" > "$T/mst.out" 2>&1 &&
  grep -q "valid yes; sub-cell coverage 1;" "$T/mst.out" &&
  "$CK" plan --planner multi_st --map "$DATA/maze.map" --radius 0.5 --robots 4 --param kb=off --out "$T/mst-off.json" > /dev/null 2>&1 &&
  "$CK" plan --planner multi_st --map "$DATA/maze.map" --radius 0.5 --robots 4 --param "kb=$T/kb-own.yaml" --out "$T/mst-own.json" > /dev/null 2>&1 &&
  "$CK" evaluate --map "$DATA/maze.map" --path "$T/mst.json" 2>&1 | grep -q "valid: yes" && ok ||
  bad "multi_st team plan: $(head -3 "$T/mst.out" 2> /dev/null)"
# team-check and the cornered team worlds: tests/cli/team_check_test.sh (ctest cli.team_check)

# --------------------------------------------------------------------------------------------- provenance
# --version (and run.json) name the revision built (cmake/git_revision.cmake), not the one configured
SRC="$(cd "$DATA/../.." && pwd)"
if command -v git > /dev/null && [ -e "$SRC/.git" ]; then
  rev="$(git -C "$SRC" rev-parse --short HEAD 2> /dev/null)"
  "$CK" --version | grep -qF "($rev)" && ok || bad "--version does not name the revision $rev: $("$CK" --version)"
fi

echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
