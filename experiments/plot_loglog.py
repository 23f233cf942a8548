#!/usr/bin/env python3
"""Log-log chart (SVG, standard library only) of Google Benchmark JSON output: time against size,
one line per benchmark family, with the least-squares slope of log(time) on log(size).

usage: plot_loglog.py BENCH.json OUT.svg [--counter subcells|nodes] [--filter REGEX] [--title T]
                      [--seconds c1,c2,...]
With --seconds, each named counter (seconds, e.g. smooth_s,stc_s of BM_SmoothStcVsStc) is a line of
its own instead of the benchmark's real time.
"""
import argparse, json, math, re, sys
from collections import OrderedDict

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("bench"); ap.add_argument("out")
    ap.add_argument("--counter", default="subcells")
    ap.add_argument("--filter", default=".")
    ap.add_argument("--title", default="time against size")
    ap.add_argument("--seconds", default="")
    a = ap.parse_args()
    data = json.load(open(a.bench))
    series = OrderedDict()
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" or a.counter not in b or not re.search(a.filter, b["name"]):
            continue
        parts = b["name"].split("/")
        key = parts[0] + ("/" + "/".join(parts[2:]) if len(parts) > 2 else "")
        unit = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b.get("time_unit", "ns")]
        if a.seconds:
            for c in a.seconds.split(","):
                if c in b:
                    series.setdefault(c, []).append((b[a.counter], b[c] * 1e3))
        else:
            series.setdefault(key, []).append((b[a.counter], b["real_time"] * unit))
    if not series:
        sys.exit("no matching benchmarks")
    xs = [x for s in series.values() for x, _ in s]; ys = [y for s in series.values() for _, y in s]
    lx0, lx1 = math.floor(math.log10(min(xs))), math.ceil(math.log10(max(xs)))
    ly0, ly1 = math.floor(math.log10(min(ys))), math.ceil(math.log10(max(ys)))
    W, H, L, B, T, R = 720, 460, 70, 50, 40, 230
    px = lambda x: L + (math.log10(x) - lx0) / max(lx1 - lx0, 1) * (W - L - R)
    py = lambda y: H - B - (math.log10(y) - ly0) / max(ly1 - ly0, 1) * (H - B - T)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
           f'<rect width="{W}" height="{H}" fill="white"/>',
           f'<text x="{L}" y="22" font-size="14">{a.title}</text>']
    for e in range(lx0, lx1 + 1):
        out.append(f'<line x1="{px(10**e):.1f}" y1="{T}" x2="{px(10**e):.1f}" y2="{H-B}" stroke="#ddd"/>')
        out.append(f'<text x="{px(10**e):.1f}" y="{H-B+16}" text-anchor="middle">1e{e}</text>')
    for e in range(ly0, ly1 + 1):
        out.append(f'<line x1="{L}" y1="{py(10**e):.1f}" x2="{W-R}" y2="{py(10**e):.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{L-6}" y="{py(10**e)+4:.1f}" text-anchor="end">{10**e:g} ms</text>')
    out.append(f'<text x="{(L+W-R)/2}" y="{H-12}" text-anchor="middle">{a.counter}</text>')
    colors = ["#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"]
    for i, (name, pts) in enumerate(series.items()):
        pts.sort(); c = colors[i % len(colors)]
        lx = [math.log10(x) for x, _ in pts]; ly = [math.log10(y) for _, y in pts]
        n = len(pts); mx = sum(lx) / n; my = sum(ly) / n
        den = sum((x - mx) ** 2 for x in lx)
        slope = sum((x - mx) * (y - my) for x, y in zip(lx, ly)) / den if den else float("nan")
        out.append('<polyline fill="none" stroke="%s" stroke-width="2" points="%s"/>' % (c, " ".join(f"{px(x):.1f},{py(y):.1f}" for x, y in pts)))
        for x, y in pts:
            out.append(f'<circle cx="{px(x):.1f}" cy="{py(y):.1f}" r="3" fill="{c}"/>')
        out.append(f'<text x="{W-R+10}" y="{T+18*i+10}" fill="{c}">{name}: slope {slope:.2f}</text>')
        print(f"{name}: slope {slope:.3f} over {n} sizes")
    out.append("</svg>")
    open(a.out, "w").write("\n".join(out) + "\n")

if __name__ == "__main__":
    main()
