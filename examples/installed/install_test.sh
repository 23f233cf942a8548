#!/usr/bin/env bash
# After `cmake --install`: the command, the Python package (when built) and a separate CMake project
# that finds coverkit with find_package and plans with every planner.
#   install_test.sh BUILD_DIR SOURCE_DIR PYTHON PYTHON_DIR   (PYTHON_DIR empty: no Python module)
set -euo pipefail
build="$1" src="$2" python="$3" pydir="$4"
prefix="$(mktemp -d)"
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" > /dev/null
listed="$("$prefix/bin/coverkit" list)"   # not piped into grep -q: with pipefail its early exit is a SIGPIPE
grep -q '^boustrophedon:' <<< "$listed" || { echo "installed coverkit does not list boustrophedon"; exit 1; }
if [ -n "$pydir" ]; then
  (cd "$prefix" && PYTHONPATH="$prefix/$pydir" "$python" -c "import coverkit, os; assert os.path.dirname(coverkit.__file__).startswith('$prefix'); print(len(coverkit.planners()), 'planners from', coverkit.__file__)")
fi
launcher=""
command -v ccache > /dev/null && launcher="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"
cmake -S "$src/examples/installed" -B "$prefix/consumer" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release $launcher > /dev/null
cmake --build "$prefix/consumer" -j2 > /dev/null
"$prefix/consumer/first_plan" "$src/datasets/data/pillars.wkt"
