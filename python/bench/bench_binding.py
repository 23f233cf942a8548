"""Binding overhead (docs/python.md): the same plans from Python (coverkit.plan) and from C++
(coverkit_bench's BM_PlanInProcess: makeContext + runOnce + the path JSON, the work plan() does),
on a small map (rooms.grid, 24 x 16 cells) and a large one (a generated 1000 x 1000 pixel ROS map
at 0.05 m with 60 rectangles; r = 0.1: 250 x 250 sub-cells), median of several runs each.

    PYTHONPATH=build/python python3 python/bench/bench_binding.py build/experiments/coverkit_bench
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import coverkit

bench = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
data = os.path.join(here, "..", "..", "datasets", "data")
tmp = tempfile.mkdtemp()

rng = np.random.default_rng(1)
free = np.ones((1000, 1000), dtype=bool)
free[:3, :] = free[-3:, :] = free[:, :3] = free[:, -3:] = False
for _ in range(60):
    r, c = rng.integers(20, 940, 2)
    h, w = rng.integers(10, 60, 2)
    free[r:r + h, c:c + w] = False
with open(os.path.join(tmp, "large.pgm"), "wb") as f:
    f.write(b"P5\n1000 1000\n255\n" + np.where(free, 254, 0).astype(np.uint8).tobytes())
with open(os.path.join(tmp, "large.yaml"), "w") as f:
    f.write("image: large.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")

cases = [(os.path.abspath(os.path.join(data, "rooms.grid")), "0.125", "stc", 30),
         (os.path.abspath(os.path.join(data, "rooms.grid")), "0.125", "boustrophedon", 10),
         (os.path.join(tmp, "large.yaml"), "0.1", "stc", 3),
         (os.path.join(tmp, "large.yaml"), "0.1", "bsa_spiral", 3)]

python_ms = {}
conversions = {}
for path, radius, planner, reps in cases:
    w = coverkit.load_map(path)
    times = []
    for _ in range(reps):
        t0 = time.perf_counter()
        plan = coverkit.plan(w, planner, radius=radius)
        plan.to_json()
        times.append((time.perf_counter() - t0) * 1000)
    assert plan.valid
    python_ms[(path, radius, planner)] = statistics.median(times)
    # what only Python pays: the path as numpy, the metrics as a dict
    t0 = time.perf_counter()
    for _ in range(10):
        v = plan.paths[0].vertices
        m = plan.metrics
    conversions[(path, radius, planner)] = ((time.perf_counter() - t0) * 100, len(v), len(m))

env = dict(os.environ, COVERKIT_BINDING_CASES=";".join(f"{p}|{r}|{pl}" for p, r, pl, _ in cases))
out = subprocess.run([bench, "--benchmark_filter=BM_PlanInProcess", "--benchmark_format=json",
                      "--benchmark_repetitions=3", "--benchmark_report_aggregates_only=true"],
                     env=env, check=True, capture_output=True, text=True).stdout
cpp_ms = {}
for b in json.loads(out)["benchmarks"]:
    if b.get("aggregate_name") == "median":
        key = b["run_name"].split("/", 1)[1].split("|")
        cpp_ms[tuple(key)] = b["real_time"]

print("| map | r | planner | C++ ms (median) | Python ms (median) | difference ms | difference % | path points | vertices + metrics to Python, ms |")
print("|---|---|---|---|---|---|---|---|---|")
for path, radius, planner, _ in cases:
    key = (path, radius, planner)
    c, p = cpp_ms[key], python_ms[key]
    ms, points, _ = conversions[key]
    print(f"| {os.path.basename(path)} | {radius} | {planner} | {c:.2f} | {p:.2f} | {p - c:.2f} | {100 * (p - c) / c:.1f} | {points} | {ms:.3f} |")
