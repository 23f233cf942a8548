#!/usr/bin/env python3
"""Team scenarios of another generator than team-check's (docs/multi-robot.md, "Beyond team-check's
generator"): grid worlds (Moving AI format), polygon worlds (WKT) and, with MAPS, the Moving AI maps
random-32-32-10, maze-32-32-4 and room-64-64-8 found there; 1-8 robots (--robots), 0-10 moving
obstacles of radius 0.2-0.8 at 0.3-2 m/s whose waypoints lie anywhere in the map (through walls),
r = 1/4, 0.4, 1/2 or 1. Each scenario is planned with `coverkit plan` and judged by `coverkit
evaluate --json`; one JSON line per scenario on stdout (rc, valid, violation kinds,
missed_from_starts/team as mfs/mft, status, message, horizon statistics).

Usage: team_scenarios.py COVERKIT FIRST COUNT OUTDIR [PLANNER] [MAPS]
"""
import json, os, random, subprocess, sys, time
ck = sys.argv[1]
first, n, out = int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
os.makedirs(out, exist_ok=True)
shared = sys.argv[6] if len(sys.argv) > 6 else ""
rows = []
def movingai(path, w, h, blocked):
    with open(path, "w") as f:
        f.write(f"type octile\nheight {h}\nwidth {w}\nmap\n")
        for y in range(h):
            f.write("".join("@" if (x, y) in blocked else "." for x in range(w)) + "\n")
for s in range(first, first + n):
    g = random.Random(1000003 * s + 17)
    kind = g.choice(["grid", "poly", "mai", "grid"])
    r = g.choice([0.25, 0.4, 0.5, 1.0])
    if kind == "grid":
        w, h = g.randint(12, 40), g.randint(12, 40)
        blocked = set()
        for _ in range(g.randint(0, 12)):
            x0, y0, bw, bh = g.randrange(w), g.randrange(h), g.randint(1, 5), g.randint(1, 5)
            for x in range(x0, min(w, x0 + bw)):
                for y in range(y0, min(h, y0 + bh)):
                    blocked.add((x, y))
        mp = f"{out}/s{s}.map"; movingai(mp, w, h, blocked); W, H = w, h
    elif kind == "poly":
        W, H = g.uniform(10, 30), g.uniform(10, 30)
        holes = []
        for _ in range(g.randint(0, 8)):
            cx, cy, a, b = g.uniform(2, W - 2), g.uniform(2, H - 2), g.uniform(0.3, 2), g.uniform(0.3, 2)
            pts = [(cx - a, cy - b), (cx + a, cy - b + g.uniform(-0.3, 0.3)), (cx + a, cy + b), (cx - a + g.uniform(-0.3, 0.3), cy + b)]
            holes.append(pts)
        # drop overlapping holes crudely: keep only boxes disjoint from previous ones
        kept = []
        for hpts in holes:
            xs = [p[0] for p in hpts]; ys = [p[1] for p in hpts]
            box = (min(xs) - 0.2, min(ys) - 0.2, max(xs) + 0.2, max(ys) + 0.2)
            if all(box[2] < k[0] or k[2] < box[0] or box[3] < k[1] or k[3] < box[1] for k, _ in kept):
                kept.append((box, hpts))
        def ring(p): return "(" + ",".join(f"{x:.3f} {y:.3f}" for x, y in p + [p[0]]) + ")"
        wkt = "POLYGON(" + ring([(0, 0), (W, 0), (W, H), (0, H)]) + "".join("," + ring(list(reversed(hp))) for _, hp in kept) + ")"
        mp = f"{out}/s{s}.wkt"; open(mp, "w").write(wkt + "\n")
    else:
        name = g.choice(["random-32-32-10", "maze-32-32-4", "room-64-64-8"])
        if not shared:
            continue
        mp = f"{shared}/{name}.map"; W = H = 64 if "64" in name else 32
        r = g.choice([0.5, 1.0]) if "maze" not in name else 0.5
    k = g.randint(1, 8)
    obs = []
    for _ in range(g.randint(0, 10)):
        t = g.uniform(0, 5); x, y = g.uniform(0, W), g.uniform(0, H); wps = [[round(t, 2), round(x, 2), round(y, 2)]]
        for _ in range(g.randint(1, 3)):
            nx, ny = g.uniform(0, W), g.uniform(0, H)
            d = ((nx - x) ** 2 + (ny - y) ** 2) ** 0.5
            t += d / g.uniform(0.3, 2.0); x, y = nx, ny
            wps.append([round(t, 2), round(x, 2), round(y, 2)])
        obs.append({"radius": round(g.uniform(0.2, 0.8), 2), "waypoints": wps})
    sc = f"{out}/s{s}.yaml"
    with open(sc, "w") as f:
        f.write("format: coverkit.scenario/1\ndynamic_obstacles:\n" if obs else "format: coverkit.scenario/1\ndynamic_obstacles: []\n")
        for o in obs:
            f.write(f"  - radius: {o['radius']}\n    waypoints: {json.dumps(o['waypoints'])}\n")
    planner = sys.argv[5] if len(sys.argv) > 5 else "multi_st"
    pj = f"{out}/s{s}.json"
    cmd = [ck, "plan", "--map", mp, "--planner", planner, "--radius", str(r), "--robots", str(k), "--out", pj]
    if obs: cmd += ["--scenario", sc]
    began = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True)
    row = {"seconds": round(time.monotonic() - began, 3), "seed": s, "kind": kind, "r": r, "k": k, "obs": len(obs), "rc": p.returncode, "map": mp}
    if p.returncode == 0:
        e = subprocess.run([ck, "evaluate", "--map", mp, "--path", pj, "--json"] + (["--scenario", sc] if obs else []), capture_output=True, text=True)
        try:
            j = json.loads(e.stdout)
            row.update(valid=j.get("valid"), viol=[v["kind"] for v in j.get("violations", [])][:3], status=json.load(open(pj)).get("status"), mfs=j.get("missed_from_starts"), mft=j.get("missed_from_team"), map=mp, msg=json.load(open(pj)).get("message","")[:120], stats={k: v for k, v in json.load(open(pj)).get("statistics", {}).items() if "horizon" in k or "caught" in k})
        except Exception as ex:
            row.update(valid=None, err=e.stderr[-300:])
    else:
        row["err"] = p.stderr.strip()[-300:]
    print(json.dumps(row), flush=True)
