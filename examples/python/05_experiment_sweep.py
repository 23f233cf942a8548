"""Example 05: a small experiment, in parallel threads (coverkit releases the GIL while it plans).
Planners × radii × maps, one CSV row per run, a chart of mean coverage against radius.

    python3 05_experiment_sweep.py DATA_DIR OUT_DIR
"""
import csv
import itertools
import os
import sys
from concurrent.futures import ThreadPoolExecutor

import coverkit

data, out = sys.argv[1], sys.argv[2]
maps = {name: coverkit.load_map(os.path.join(data, name)) for name in ("rooms.grid", "pillars.wkt")}
planners = ["stc", "full_stc", "boustrophedon"]
radii = [0.125, 0.25, 0.375]
cases = list(itertools.product(maps, planners, radii))


def run(case):
    name, planner, r = case
    plan = coverkit.plan(maps[name], planner, radius=r)
    return dict(map=name, planner=planner, radius=r, status=plan.status, valid=plan.valid,
                coverable_coverage=plan.metrics.get("coverable_coverage", 0), length=plan.metrics.get("length", 0),
                turns=plan.metrics.get("turns", 0))


with ThreadPoolExecutor(max_workers=os.cpu_count()) as pool:
    rows = list(pool.map(run, cases))   # in the order of `cases`, whatever the threads did
with open(os.path.join(out, "05_sweep.csv"), "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=list(rows[0]))
    writer.writeheader()
    writer.writerows(rows)
assert all(row["valid"] for row in rows if row["status"] in ("exact_solution", "approximate_solution", "partial_coverage"))

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5, 3.5))
    for planner in planners:
        ys = [sum(row["coverable_coverage"] for row in rows if row["planner"] == planner and row["radius"] == r) / len(maps) for r in radii]
        ax.plot(radii, ys, marker="o", label=planner)
    ax.set_xlabel("robot radius")
    ax.set_ylabel("coverage of the coverable region")
    ax.legend()
    fig.savefig(os.path.join(out, "05_sweep.png"), dpi=100)
except ImportError:
    pass
print(f"{len(rows)} runs; wrote 05_sweep.csv")
