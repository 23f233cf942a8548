# shellcheck shell=bash
# Shared by the command-line test scripts (sourced, after CK and T are set): an empty work folder
# $T, the pass and fail counters with ok/bad, and csv_count.
rm -rf "$T"; mkdir -p "$T"
fails=0; passes=0
ok() { passes=$((passes + 1)); }
bad() { echo "FAIL: $*"; fails=$((fails + 1)); }
# rows of a results.csv for which a python condition on r (column name → text) holds
csv_count() { python3 -c 'import csv, sys; print(sum(1 for r in csv.DictReader(open(sys.argv[1])) if eval(sys.argv[2])))' "$1" "$2"; }
