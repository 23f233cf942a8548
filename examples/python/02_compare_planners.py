"""Example 02: compare every registered planner on one map: coverage, length, turns, a picture
each.

    python3 02_compare_planners.py DATA_DIR OUT_DIR
"""
import os
import sys

import coverkit

data, out = sys.argv[1], sys.argv[2]
w = coverkit.load_map(os.path.join(data, "pillars.wkt"))   # a polygon map: arcs in C-space

print(f"{'planner':20} {'status':22} {'valid':>5} {'coverage':>9} {'turns':>6} {'length':>8}")
for p in coverkit.planners():
    plan = coverkit.plan(w, p["name"], radius=0.25)
    m = plan.metrics
    print(f"{p['name']:20} {plan.status:22} {str(plan.valid):>5} {m.get('coverable_coverage', 0):9.4f} "
          f"{int(m.get('turns', 0)):6d} {m.get('length', 0):8.1f}")
    plan.picture(os.path.join(out, f"02_{p['name']}.svg"))
    assert plan.valid
