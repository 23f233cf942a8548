#!/usr/bin/env python3
"""Writes the seed corpora fuzz/corpus/<target>/ (committed; run again only to change them).

Seeds are small: the built-in maps of datasets/data (or pieces of them), the shipped experiment
configs, and images made here in every flavour the ROS reader must read (PNG: 1/2/4/8/16-bit
grey, grey+alpha, RGB, RGBA, palette, tRNS, interlaced; PGM: P2/P5, maxval 1..65535).
Path seeds are written by hand in the format of docs/formats.md.
Usage: python3 fuzz/make_seeds.py   (from anywhere)
"""
import os
import shutil
import struct
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "datasets", "data")
CORPUS = os.path.join(ROOT, "fuzz", "corpus")


def out(target, name, data):
    d = os.path.join(CORPUS, target)
    os.makedirs(d, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


def read(name):
    with open(os.path.join(DATA, name), "rb") as f:
        return f.read()


# ---------------------------------------------------------------- images
# the 6×5 test map as grey levels 0..255: occupied 0, free 254, unknown 205 (map_server's colours)
GREY = [
    [0, 0, 0, 0, 0, 0],
    [0, 254, 254, 254, 205, 0],
    [0, 254, 0, 254, 254, 0],
    [0, 254, 254, 254, 254, 0],
    [0, 0, 0, 0, 0, 0],
]
W, H = 6, 5


def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)


def pack_row(samples, depth):
    """Samples (ints) of one row at bit depth `depth` → bytes (big-endian, MSB first)."""
    if depth == 16:
        return b"".join(struct.pack(">H", s) for s in samples)
    if depth == 8:
        return bytes(samples)
    bits, n, acc = 0, 0, bytearray()
    for s in samples:
        bits = (bits << depth) | s
        n += depth
        if n == 8:
            acc.append(bits)
            bits, n = 0, 0
    if n:
        acc.append(bits << (8 - n))
    return bytes(acc)


ADAM7 = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)]


def png(colour_type, depth, pixel, interlace=False, extra=b"", plte=None):
    """pixel(x, y) → tuple of samples for one pixel."""
    raw = bytearray()
    passes = ADAM7 if interlace else [(0, 0, 1, 1)]
    for x0, y0, dx, dy in passes:
        xs = list(range(x0, W, dx))
        if not xs:
            continue
        for y in range(y0, H, dy):
            samples = [s for x in xs for s in pixel(x, y)]
            raw += b"\0" + pack_row(samples, depth)
    ihdr = struct.pack(">IIBBBBB", W, H, depth, colour_type, 0, 0, 1 if interlace else 0)
    body = chunk(b"IHDR", ihdr)
    if plte is not None:
        body += chunk(b"PLTE", plte)
    body += extra + chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b"")
    return b"\x89PNG\r\n\x1a\n" + body


def scaled(v, depth):
    return round(v * ((1 << depth) - 1) / 255)


def grey_png(depth, interlace=False):
    return png(0, depth, lambda x, y: (scaled(GREY[y][x], depth),), interlace)


def images():
    imgs = {}
    for d in (1, 2, 4, 8, 16):
        imgs["grey%d" % d] = grey_png(d)
    imgs["grey8-interlaced"] = grey_png(8, True)
    imgs["grey16-interlaced"] = grey_png(16, True)
    # the case: 16-bit grey 49151 (p = 0.25, unknown) must not read as free
    imgs["grey16-unknown49151"] = png(0, 16, lambda x, y: (49151 if (x, y) == (2, 2) else scaled(GREY[y][x], 16),))
    imgs["ga8"] = png(4, 8, lambda x, y: (GREY[y][x], 0 if (x, y) == (4, 1) else 255))
    imgs["ga16"] = png(4, 16, lambda x, y: (scaled(GREY[y][x], 16), 65535))
    imgs["rgb8"] = png(2, 8, lambda x, y: (GREY[y][x],) * 3)
    imgs["rgb16"] = png(2, 16, lambda x, y: (scaled(GREY[y][x], 16),) * 3)
    imgs["rgba8"] = png(6, 8, lambda x, y: (GREY[y][x],) * 3 + (255,))
    imgs["rgba16"] = png(6, 16, lambda x, y: (scaled(GREY[y][x], 16),) * 3 + (65535,))
    imgs["rgba16-unknown49151"] = png(6, 16, lambda x, y: ((49151,) * 3 if (x, y) == (2, 2) else (scaled(GREY[y][x], 16),) * 3) + (65535,))
    levels = [0, 205, 254]
    plte = b"".join(bytes([v, v, v]) for v in levels)
    idx = lambda x, y: (levels.index(GREY[y][x]),)
    imgs["palette2"] = png(3, 2, idx, plte=plte)
    imgs["palette8-trns"] = png(3, 8, idx, plte=plte, extra=chunk(b"tRNS", bytes([255, 0, 255])))
    imgs["grey8-trns"] = png(0, 8, lambda x, y: (GREY[y][x],), extra=chunk(b"tRNS", struct.pack(">H", 205)))
    imgs["rgb8-interlaced"] = png(2, 8, lambda x, y: (GREY[y][x],) * 3, interlace=True)
    return imgs


def pgm_p5(maxval):
    body = b"".join(struct.pack(">H" if maxval > 255 else ">B", round(v * maxval / 255)) for row in GREY for v in row)
    return b"P5\n# made by fuzz/make_seeds.py\n%d %d\n%d\n" % (W, H, maxval) + body


def pgm_p2(maxval):
    rows = "\n".join(" ".join(str(round(v * maxval / 255)) for v in row) for row in GREY)
    return ("P2\n%d %d\n%d\n" % (W, H, maxval) + rows + "\n").encode()


def main():
    if os.path.isdir(CORPUS):
        shutil.rmtree(CORPUS)
    # ROS images: one options byte (fuzz_ros_image.cpp) + the image
    opts = [0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x20, 0x30]
    for i, (name, data) in enumerate(sorted(images().items())):
        out("fuzz_ros_png", name, bytes([opts[i % len(opts)]]) + data)
    pgms = {"p5-255": pgm_p5(255), "p5-65535": pgm_p5(65535), "p5-1000": pgm_p5(1000), "p5-1": pgm_p5(1),
            "p2-255": pgm_p2(255), "p2-65535": pgm_p2(65535), "office": read("office.pgm")}
    for i, (name, data) in enumerate(sorted(pgms.items())):
        out("fuzz_ros_pgm", name, bytes([opts[i % len(opts)]]) + data)
    # ROS YAML: the built-in map's YAML pointing at the fixed images beside it (fuzz_ros_yaml.cpp)
    office = read("office.yaml").decode()
    out("fuzz_ros_yaml", "office-pgm", office.replace("office.pgm", "map.pgm"))
    out("fuzz_ros_yaml", "office-png", office.replace("office.pgm", "map.png"))
    out("fuzz_ros_yaml", "scale-negate", "image: map.png\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 1\nmode: scale\n"
        "occupied_thresh: 0.5\nfree_thresh: 0.2\n")
    out("fuzz_ros_yaml", "raw-flow", "{image: map.pgm, resolution: 1/2, origin: [-3.5, 2e1], mode: raw, negate: true}\n")
    out("fuzz_ros_yaml", "minimal", "image: \"map.pgm\"\nresolution: 0.05\n")
    # Moving AI, WKT, GeoJSON, text grid: the built-in maps and small variants
    out("fuzz_moving_ai", "maze", read("maze.map"))
    out("fuzz_moving_ai", "small", "type octile\nheight 3\nwidth 4\nmap\n@@@@\n@.G@\n@TSW\n")
    out("fuzz_moving_ai", "crlf", "type octile\r\nheight 2\r\nwidth 2\r\nmap\r\n..\r\n.O\r\n")
    out("fuzz_wkt", "pillars", read("pillars.wkt"))
    out("fuzz_wkt", "multipolygon", "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1)), ((5 0, 7 0, 6 3, 5 0)))\n")
    out("fuzz_wkt", "polygon-z", "POLYGON Z ((0 0 1, 3 0 1, 3 3 1, 0 3 1, 0 0 1))")
    out("fuzz_wkt", "polygon-zm", "polygon zm ((0 0 1 2, 1e1 0 1 2, 0.5 2.5e0 1 2, 0 0 1 2))")
    # a reproducer: a ring 2e-308 high once sent a double past size_t in checkWorkspace's row grid
    out("fuzz_wkt", "ring-of-no-height", "polygon zm ((5 0 1 2, 1e1 0 1 2, 0.5 2e-308, 0 0 1 2))")
    out("fuzz_geojson", "field-ring", read("field_ring.geojson"))
    out("fuzz_geojson", "multipolygon", '{"type":"MultiPolygon","coordinates":[[[[0,0],[3,0],[3,3],[0,0]]],[[[4,0],[6,0],[6,2],[4,2],[4,0]]]]}')
    out("fuzz_geojson", "lonlat", '{"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":'
        '[[[7.001,46.001],[7.002,46.001],[7.002,46.002],[7.001,46.002],[7.001,46.001]]]}}')
    out("fuzz_geojson", "collection-crs", '{"type":"GeometryCollection","crs":{"type":"name","properties":{"name":"EPSG:3857"}},'
        '"geometries":[{"type":"Polygon","coordinates":[[[0,0],[2.5,0],[2.5,1e0],[0,1],[0,0]]]}]}')
    out("fuzz_text_grid", "open-room", read("open_room.grid"))
    out("fuzz_text_grid", "rooms", read("rooms.grid"))
    out("fuzz_text_grid", "small", "; two rooms\r\nresolution 0.3\r\norigin -1 2.5\r\n#####\r\n#.#.#\r\n#...#\r\n#####\r\n")
    # path files (docs/formats.md)
    out("fuzz_path_json", "lines", '{"format":"coverkit.path/1","planner":"stc","status":"success","robot_radius":0.25,'
        '"robot_radius_exact":"1/4","cell_size":1,"cell_size_exact":"1","robots":[{"start":[0.5,0.5],"segments":['
        '{"type":"line","from":[0.5,0.5],"to":[1.5,0.5]},{"type":"line","from":[1.5,0.5],"to":[1.5,1.5]}]}],'
        '"metrics":{"length":2.0},"statistics":{"time_s":0.001}}\n')
    out("fuzz_path_json", "arcs", '{"format":"coverkit.path/1","planner":"smooth_stc","robot_radius":0.25,"robots":[{"segments":['
        '{"type":"line","from":[1,1],"to":[2,1]},{"type":"arc","from":[2,1],"to":[3,2],"center":[2,2],"ccw":true},'
        '{"type":"arc","from":[3,2],"to":[2,3],"center":[2,2],"ccw":false}]}]}\n')
    out("fuzz_path_json", "two-robots", '{"format":"coverkit.path/1","robots":[{"start":[1,1],"segments":[]},'
        '{"start":[2,2],"segments":[{"type":"line","from":[2,2],"to":[2,3e0]}]}]}\n')
    out("fuzz_scenario", "two-obstacles", "format: coverkit.scenario/1\ndynamic_obstacles:\n  - radius: 0.3\n    waypoints: [[0.0, 1.0, 1.0], [5.0, 4.0, 1.0], [9.0, 4.0, 6.0]]\n  - radius: 1/4\n    waypoints: [[2, 0.5, 0.5]]\n")
    out("fuzz_scenario", "none", "format: coverkit.scenario/1\n")
    out("fuzz_knowledge_base", "shipped", open(os.path.join(ROOT, "planners", "data", "multi_st_kb.yaml")).read())
    out("fuzz_knowledge_base", "empty", "format: coverkit.kb/1\nrules: []\n")
    out("fuzz_path_csv", "one-robot", "robot,seq,x,y\n0,0,0.5,0.5\n0,1,1.5,0.5\n0,2,1.5,1.5\n0,3,0.5,1.5\n")
    out("fuzz_path_csv", "two-robots", "robot,seq,x,y\r\n0,0,1,1\r\n1,0,2,2\r\n0,1,1e0,2.5\r\n1,1,-2,2\r\n")
    # experiment configs: the shipped ones
    cfg = os.path.join(ROOT, "experiments", "configs")
    for name in sorted(os.listdir(cfg)):
        with open(os.path.join(cfg, name), "rb") as f:
            out("fuzz_experiment_config", os.path.splitext(name)[0], f.read())
    out("fuzz_experiment_config", "flow", "{planners: [stc, 'bsa_spiral:side=right'], worlds: {count: 2, shape: stars}}\n")


if __name__ == "__main__":
    main()
