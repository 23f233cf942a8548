"""Example 01: a first plan. Read a map, plan a coverage path for a disc robot (checked exactly
as every plan is), look at its numbers, write the path file and a picture.

    python3 01_first_plan.py DATA_DIR OUT_DIR      (DATA_DIR: datasets/data of the source tree)
"""
import os
import sys

import coverkit

data, out = sys.argv[1], sys.argv[2]

# 1. A workspace: polygons with holes (a grid map becomes one). Numbers that decide geometry are
#    exact: 0.125 is taken as the decimal 1/8, as on the command line ("1/8" works too).
w = coverkit.load_map(os.path.join(data, "rooms.grid"))
print(w)

# 2. Plan, validate exactly, measure: what `coverkit plan` does.
plan = coverkit.plan(w, "spiral_stc", radius=0.125)
print(plan.status, "valid:", plan.valid, "length:", round(plan.metrics["length"], 2),
      "turns:", int(plan.metrics["turns"]), "coverage of the coverable region:", round(plan.metrics["coverable_coverage"], 4))

# 3. The path as numpy: an (n, 2) float64 array of the pieces' ends.
xy = plan.paths[0].vertices
print("path of", len(xy), "points, from", xy[0], "to", xy[-1])

# 4. The path file (the same bytes as `coverkit plan --out`) and a picture.
plan.write(os.path.join(out, "01_first_plan.json"))
plan.picture(os.path.join(out, "01_first_plan.png"), title="spiral_stc on rooms.grid")
assert plan.valid
