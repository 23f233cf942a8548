"""Example 03: the exact C-space of a disc robot. C-obstacles are the obstacles grown by the disc
(segments and circular arcs); C-free is where the centre may be. Areas, components, and a picture
drawn with matplotlib from the pieces (arcs sampled here for drawing only).

    python3 03_cspace.py DATA_DIR OUT_DIR
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import coverkit  # noqa: E402

data, out = sys.argv[1], sys.argv[2]
w = coverkit.load_map(os.path.join(data, "pillars.wkt"))
cs = coverkit.cspace(w, radius=0.4, start=(1, 1))
print(f"free area {cs['free_area']:.3f}, C-free area {cs['cfree_area']:.3f}, "
      f"{len(cs['components'])} component(s), start in component {cs['start_component']}")


def loop_points(pieces, step=0.02):
    """Points along a loop of pieces (rows x0, y0, x1, y1, cx, cy, kind: 0 line, ±1 arc)."""
    pts = []
    for x0, y0, x1, y1, cx, cy, kind in pieces:
        if kind == 0:
            pts.append((x0, y0))
            continue
        a0, a1 = math.atan2(y0 - cy, x0 - cx), math.atan2(y1 - cy, x1 - cx)
        sweep = (a1 - a0) % (2 * math.pi) if kind > 0 else -((a0 - a1) % (2 * math.pi))
        rho = math.hypot(x0 - cx, y0 - cy)
        n = max(2, int(abs(sweep) * rho / step))
        for t in np.linspace(0, 1, n, endpoint=False):
            pts.append((cx + rho * math.cos(a0 + t * sweep), cy + rho * math.sin(a0 + t * sweep)))
    pts.append(pts[0])
    return np.array(pts)


arcs = sum(int((o["outer"][:, 6] != 0).sum()) for o in cs["obstacles"])
print(f"{len(cs['obstacles'])} C-obstacle(s), {arcs} arc(s) on their outer boundaries")
fig, ax = plt.subplots(figsize=(6, 4))
for ring in w.rings():
    r = np.vstack([ring, ring[:1]])
    ax.plot(r[:, 0], r[:, 1], color="black", linewidth=1)
for comp in cs["components"]:
    for loop in [comp["outer"], *comp["holes"]]:
        p = loop_points(loop)
        ax.fill(p[:, 0], p[:, 1], color="#9ecae1" if loop is comp["outer"] else "white", zorder=1)
        ax.plot(p[:, 0], p[:, 1], color="#1b6ca8", linewidth=0.8, zorder=2)
ax.set_aspect("equal")
ax.set_title("C-free of pillars.wkt, r = 0.4")
fig.savefig(os.path.join(out, "03_cspace.png"), dpi=100)
