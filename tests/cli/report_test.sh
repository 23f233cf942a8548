#!/usr/bin/env bash
# `coverkit experiment report DIR`: runs a tiny sweep with the engine, makes its report, checks the
# files, that the same folder gives the same bytes, that a folder without results is refused (exit
# 2, the file named), then opens report.html in headless Chromium: no console message, no uncaught
# error, the page's script ran (data-ready="1") and counted every chart (data-charts = the number of
# <svg class="chart"> elements, not 0).
#
# Usage: report_test.sh COVERKIT WORK_DIR (WORK_DIR is emptied). Exit 0: passed, 1: failed,
# 77: Chromium not found (ctest's skip code; the checks before the browser have passed then).
# CHROMIUM=/path/to/chromium picks the browser.
set -u
CK="$1"; T="$2"
rm -rf "$T"; mkdir -p "$T"
T="$(cd "$T" && pwd)"   # file:// needs an absolute path
fail() { echo "FAIL: $*"; exit 1; }

# ---- the run and its report ---------------------------------------------------------------------
cat > "$T/sweep.yaml" <<'EOF'
title: Report test sweep
planners: [stc, full_stc]
vary: radius
radii: [0.5, 1]
worlds: {count: 2, width: 10, height: 10, obstacles: 3}
EOF
timeout 300 "$CK" experiment run "$T/sweep.yaml" --out "$T/run" --jobs 2 --quiet > "$T/run.stdout" 2> "$T/run.stderr" ||
  fail "experiment run: exit $? ($(cat "$T/run.stderr"))"
[ -f "$T/run/results.db" ] || fail "experiment run wrote no results.db"
timeout 120 "$CK" experiment report "$T/run" > "$T/report.stdout" 2> "$T/report.stderr" ||
  fail "experiment report: exit $? ($(cat "$T/report.stderr"))"
[ -s "$T/run/report.html" ] || fail "experiment report wrote no report.html"
chart_files=$(find "$T/run/charts" -maxdepth 1 -name '*.svg' 2>/dev/null | wc -l)
[ "$chart_files" -gt 0 ] || fail "experiment report wrote no charts/*.svg"
for f in "$T"/run/charts/*.svg; do
  grep -q '<svg class="chart"' "$f" || fail "$f is not a chart SVG"
done
grep -q 'class="sortable"' "$T/run/report.html" || fail "report.html has no sortable table"
grep -q 'Report test sweep' "$T/run/report.html" || fail "report.html lacks the config's title"
if grep -qiE '<(script|link|img|iframe)[^>]* (src|href)="?(https?:)?//' "$T/run/report.html"; then
  fail "report.html fetches something from the network"
fi

# the same folder, the same bytes
cp "$T/run/report.html" "$T/report.first.html"
(cd "$T/run/charts" && md5sum -- *.svg) > "$T/charts.first.md5"
timeout 120 "$CK" experiment report "$T/run" > /dev/null 2> "$T/report.stderr" || fail "experiment report (again): exit $? ($(cat "$T/report.stderr"))"
cmp -s "$T/report.first.html" "$T/run/report.html" || fail "a second report of the same folder differs: $(diff "$T/report.first.html" "$T/run/report.html" | head -5)"
(cd "$T/run/charts" && md5sum -c --quiet "$T/charts.first.md5") > /dev/null 2>&1 || fail "a second report of the same folder gives other charts"

# a folder without results: exit 2, the file named, nothing written
mkdir -p "$T/empty"
timeout 60 "$CK" experiment report "$T/empty" > "$T/bad.stdout" 2> "$T/bad.stderr"; rc=$?
[ $rc -eq 2 ] || fail "report of a folder without results.db: exit $rc, expected 2 ($(cat "$T/bad.stderr"))"
grep -qF "$T/empty/results.db" "$T/bad.stderr" || fail "report of a folder without results.db: the message does not name the file: $(cat "$T/bad.stderr")"
[ -z "$(ls -A "$T/empty")" ] || fail "report of a folder without results.db wrote: $(ls -A "$T/empty" | tr '\n' ' ')"

# ---- the page in a browser ----------------------------------------------------------------------
BROWSER="${CHROMIUM:-}"
if [ -z "$BROWSER" ]; then
  for b in chromium chromium-browser google-chrome; do
    BROWSER="$(command -v "$b" 2>/dev/null)" && break
  done
fi
if [ -z "$BROWSER" ] || [ ! -f "$BROWSER" ] || [ ! -x "$BROWSER" ]; then
  echo "chromium not found: skipped"
  exit 77
fi
# A profile of its own (HOME, XDG dirs: the browser writes there); --no-sandbox: the sandbox refuses
# to run as root (containers, CI); --disable-dev-shm-usage: small /dev/shm in containers.
B="$T/browser"; mkdir -p "$B/cache" "$B/config"
HOME="$B" XDG_CACHE_HOME="$B/cache" XDG_CONFIG_HOME="$B/config" timeout 120 "$BROWSER" --headless --no-sandbox --disable-gpu \
  --disable-dev-shm-usage --no-first-run --user-data-dir="$B/profile" --enable-logging=stderr --v=0 --virtual-time-budget=5000 \
  --dump-dom "file://$T/run/report.html" > "$T/dom.html" 2> "$T/console.txt"
rc=$?
[ $rc -eq 0 ] || fail "chromium: exit $rc: $(grep -v dbus "$T/console.txt" | tail -5)"
# Chromium logs every console message as INFO:CONSOLE whatever its level (console.error too), so
# any console line fails: the page itself logs nothing (a CSP violation would show here too).
if grep -E 'CONSOLE|Uncaught' "$T/console.txt" > "$T/console.errors"; then
  fail "the page logged to the console: $(head -5 "$T/console.errors")"
fi
grep -q 'data-ready="1"' "$T/dom.html" || fail "the page's script did not finish (no data-ready=\"1\" in the DOM)"
charts=$(grep -o 'data-charts="[0-9]*"' "$T/dom.html" | head -1 | tr -dc '0-9')
svgs=$(grep -o '<svg class="chart"' "$T/dom.html" | wc -l)
[ -n "$charts" ] || fail "no data-charts in the DOM"
[ "$charts" -gt 0 ] || fail "data-charts is 0: the report has no chart"
[ "$charts" -eq "$svgs" ] || fail "data-charts=$charts but the DOM holds $svgs <svg class=\"chart\"> elements"
[ "$charts" -eq "$chart_files" ] || fail "data-charts=$charts but charts/ holds $chart_files SVG files"
echo "report test passed: $charts charts, $(grep -c '<tr>' "$T/run/report.html") table rows"
exit 0
