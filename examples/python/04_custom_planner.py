"""Example 04: bring your own planner. Plan in Python on a numpy grid, then let coverkit judge it:
the exact validator (continuity, clearance at radius r) and the metrics `coverkit evaluate`
prints. The planner: depth-first over the free cells, back to the parent when stuck.

    python3 04_custom_planner.py DATA_DIR OUT_DIR
"""
import os
import sys

import numpy as np

import coverkit

data, out = sys.argv[1], sys.argv[2]

# a grid of 0.25 m cells, True = free, row 0 on top (as an image); origin = lower-left corner
free = np.ones((16, 24), dtype=bool)
free[0, :] = free[-1, :] = free[:, 0] = free[:, -1] = False   # walls
free[4:12, 8] = False                                          # an inner wall with gaps
free[6:10, 15:17] = False                                      # a pillar
res, origin = 0.25, (0.0, 0.0)
w = coverkit.Workspace.from_grid(free, resolution=res, origin=origin)
r = res / 2   # the disc fits a cell


def centre(row, col):
    rows = free.shape[0]
    return (origin[0] + (col + 0.5) * res, origin[1] + (rows - 1 - row + 0.5) * res)


start = (1, 1)
seen = {start}
stack = [start]
points = [centre(*start)]
while stack:
    row, col = stack[-1]
    for dr, dc in ((0, 1), (-1, 0), (0, -1), (1, 0)):
        nxt = (row + dr, col + dc)
        if free[nxt] and nxt not in seen:
            seen.add(nxt)
            stack.append(nxt)
            points.append(centre(*nxt))
            break
    else:
        stack.pop()
        if stack:
            points.append(centre(*stack[-1]))
path = np.array(points)

report = coverkit.validate(w, path, radius=r)
m = coverkit.metrics(w, path, radius=r)
print("valid:", report["valid"], "| coverable coverage:", round(m["coverable_coverage"], 4), "| length:", m["length"],
      "| revisited sub-cells:", int(m["revisited_subcells"]))
assert report["valid"]

# the same map with a planner of the library, for comparison, and a picture of both
plan = coverkit.plan(w, "spiral_stc", radius=r, start=tuple(path[0]))
print("spiral_stc: coverable coverage", round(plan.metrics["coverable_coverage"], 4), "| length", plan.metrics["length"])
try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(9, 3.5))
    axes[0].plot(path[:, 0], path[:, 1], linewidth=0.8)
    for ring in w.rings():
        rr = np.vstack([ring, ring[:1]])
        axes[0].plot(rr[:, 0], rr[:, 1], color="black", linewidth=1)
    axes[0].set_aspect("equal")
    axes[0].set_title("depth-first (this example)")
    plan.plot(axes[1], workspace=w)
    axes[1].set_title("spiral_stc")
    fig.savefig(os.path.join(out, "04_custom_planner.png"), dpi=100)
except ImportError:   # no matplotlib: coverkit's own renderer
    plan.picture(os.path.join(out, "04_custom_planner.png"))
