"""The Python module (docs/python.md): the same plans as the command line, byte for byte; numpy
grids equal to the same map read from a file; every error a Python exception; planning in threads."""
import json
import math
import os
import subprocess
import threading
import time

import numpy as np
import pytest

import coverkit

SRC = os.environ.get("COVERKIT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
CLI = os.environ.get("COVERKIT_CLI", "coverkit")
DATA = os.path.join(SRC, "datasets", "data")


def data(name):
    return os.path.join(DATA, name)


def cli(*args, check=True):
    return subprocess.run([CLI, *args], check=check, capture_output=True, text=True)


def read_text_grid(path):
    """rooms.grid's header and rows, read here independently of the C++ reader."""
    resolution, origin, rows = None, None, []
    for line in open(path):
        line = line.strip()
        if not line or line.startswith(";"):
            continue
        if line.startswith("resolution"):
            resolution = line.split()[1]
        elif line.startswith("origin"):
            origin = tuple(line.split()[1:3])
        else:
            rows.append([c == "." for c in line])
    return np.array(rows, dtype=bool), resolution, origin


# --- planners and the command line ------------------------------------------------------------

def test_planners_are_those_of_the_command_line():
    names = [p["name"] for p in coverkit.planners()]
    listed = [line.split(":")[0] for line in cli("list").stdout.splitlines() if line and not line.startswith(" ") and ":" in line]
    for n in names:
        assert n in listed
    assert "boustrophedon" in names and "stc" in names
    for p in coverkit.planners():
        assert p["description"]
        assert set(p["capabilities"]) == {"online", "multi_robot", "needs_cells", "output", "coverage"}
        for q in p["parameters"]:
            assert set(q) == {"name", "type", "default", "range", "help"}
    assert {d["name"] for d in coverkit.decompositions()} >= {"boustrophedon", "trapezoidal", "grid"}


@pytest.mark.parametrize("planner", [p["name"] for p in coverkit.planners()])
def test_every_planner_gives_the_command_lines_plan_byte_for_byte(planner, tmp_path):
    out = tmp_path / "cli.json"
    cli("plan", "--map", data("rooms.grid"), "--radius", "0.125", "--planner", planner, "--out", str(out), "--metrics", "full", check=False)
    w = coverkit.load_map(data("rooms.grid"))
    plan = coverkit.plan(w, planner, radius=0.125)
    assert plan.to_json() == out.read_text()
    assert plan.valid is True, plan.violations
    assert plan.status in ("exact_solution", "approximate_solution", "partial_coverage")
    assert plan.metrics["length"] == pytest.approx(sum(p.length for p in plan.paths))
    # the path's numbers as numpy arrays
    v = plan.paths[0].vertices
    assert v.dtype == np.float64 and v.ndim == 2 and v.shape[1] == 2 and v.shape[0] == len(plan.paths[0]) + 1


def test_parameters_start_and_exact_numbers_as_on_the_command_line(tmp_path):
    out = tmp_path / "cli.json"
    cli("plan", "--map", data("pillars.wkt"), "--radius", "0.3", "--planner", "boustrophedon", "--start", "1.5,1.5",
        "--param", "direction=30", "--out", str(out), "--metrics", "full")
    w = coverkit.load_map(data("pillars.wkt"))
    a = coverkit.plan(w, "boustrophedon", radius=0.3, start=(1.5, 1.5), params={"direction": 30})
    b = coverkit.plan(w, "boustrophedon", radius="3/10", start=("3/2", 1.5), params={"direction": 30.0})
    assert a.to_json() == out.read_text() == b.to_json()
    assert a.radius_exact == "3/10"
    assert a.statistics["direction_degrees"] == pytest.approx(30, abs=1e-3)


def test_path_processors_as_on_the_command_line(tmp_path):
    out = tmp_path / "cli.json"
    cli("plan", "--map", data("pillars.wkt"), "--radius", "0.25", "--planner", "stc", "--post", "fillet",
        "--post", "smooth:max_move=0.1", "--out", str(out), "--metrics", "full")
    w = coverkit.load_map(data("pillars.wkt"))
    plan = coverkit.plan(w, "stc", radius=0.25, post=["fillet", "smooth:max_move=0.1"])
    assert plan.to_json() == out.read_text()
    assert plan.valid is True
    assert plan.statistics["post_fillet_rounded"] > 0 and plan.statistics["post_smooth_reverted"] == 0
    assert plan.metrics["turns"] < coverkit.plan(w, "stc", radius=0.25).metrics["turns"]


# --- maps ---------------------------------------------------------------------------------------

def test_a_numpy_grid_is_the_map_read_from_its_file():
    grid, resolution, origin = read_text_grid(data("rooms.grid"))
    a = coverkit.Workspace.from_grid(grid, resolution=resolution, origin=origin)
    b = coverkit.load_map(data("rooms.grid"))
    assert [r.tolist() for r in a.rings()] == [r.tolist() for r in b.rings()]
    pa = coverkit.plan(a, "stc", radius=0.125)
    pb = coverkit.plan(b, "stc", radius=0.125)
    assert pa.to_json() == pb.to_json()
    # floats are taken as the decimals they print as: 0.25 and "0.25" are the same grid
    c = coverkit.Workspace.from_grid(grid, resolution=0.25, origin=(-3.0, -2))
    assert [r.tolist() for r in c.rings()] == [r.tolist() for r in b.rings()]


def test_a_numpy_grid_is_a_ros_map_of_the_same_pixels(tmp_path):
    rng = np.random.default_rng(7)
    free = np.ones((40, 60), dtype=bool)
    free[0, :] = free[-1, :] = free[:, 0] = free[:, -1] = False
    free[rng.integers(1, 39, 30), rng.integers(1, 59, 30)] = False
    pixels = np.where(free, 254, 0).astype(np.uint8)
    (tmp_path / "m.pgm").write_bytes(b"P5\n60 40\n255\n" + pixels.tobytes())
    (tmp_path / "m.yaml").write_text("image: m.pgm\nresolution: 0.05\norigin: [-1.5, 2.0, 0.0]\nnegate: 0\n"
                                     "occupied_thresh: 0.65\nfree_thresh: 0.196\n")
    a = coverkit.Workspace.from_grid(free, resolution=0.05, origin=(-1.5, 2.0))
    b = coverkit.load_map(str(tmp_path / "m.yaml"))
    assert [r.tolist() for r in a.rings()] == [r.tolist() for r in b.rings()]
    assert a.bbox == pytest.approx((-1.5 + 0.05, 2.0 + 0.05, -1.5 + 59 * 0.05, 2.0 + 39 * 0.05))


def test_wkt_and_geojson_workspaces():
    wkt = "POLYGON((0 0,10 0,10 6,0 6,0 0),(4 2,6 2,6 4,4 4,4 2))"
    a = coverkit.Workspace.from_wkt(wkt)
    gj = {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 6], [0, 6], [0, 0]], [[4, 2], [6, 2], [6, 4], [4, 4], [4, 2]]]}
    b = coverkit.Workspace.from_geojson(gj)
    c = coverkit.Workspace.from_geojson(json.dumps(gj))
    assert a.free_area == pytest.approx(56) and b.free_area == pytest.approx(56) and c.free_area == pytest.approx(56)
    assert a.hole_count == 1 and a.region_count == 1
    assert coverkit.plan(a, "boustrophedon", 0.5).to_json() == coverkit.plan(b, "boustrophedon", 0.5).to_json()


# --- validation, metrics, files -----------------------------------------------------------------

def test_validate_and_metrics_agree_with_the_plan():
    w = coverkit.load_map(data("pillars.wkt"))
    plan = coverkit.plan(w, "boustrophedon", radius=0.25)
    report = coverkit.validate(w, plan)
    assert report["valid"] is True and report["violations"] == [] and report["segments_checked"] > 0
    m = coverkit.metrics(w, plan)
    for k, v in plan.metrics.items():
        assert m[k] == pytest.approx(v, rel=1e-12, abs=1e-12), k


def test_validate_finds_a_path_through_an_obstacle():
    w = coverkit.Workspace.from_wkt("POLYGON((0 0,10 0,10 6,0 6,0 0),(4 2,6 2,6 4,4 4,4 2))")
    through = np.array([[1.0, 3.0], [9.0, 3.0]])
    around = np.array([[1.0, 1.0], [9.0, 1.0]])
    bad = coverkit.validate(w, through, radius=0.5)
    assert bad["valid"] is False and any(v["kind"] == "clearance" for v in bad["violations"])
    good = coverkit.validate(w, [around], radius=0.5)
    assert good["valid"] is True
    # a disc of radius 1 at y = 1 touches the wall y = 0: still valid (closed C-free); 1.01 is not
    assert coverkit.validate(w, around, radius=1)["valid"] is True
    assert coverkit.validate(w, around, radius=1.01)["valid"] is False
    m = coverkit.metrics(w, around, radius=0.5)
    assert m["length"] == pytest.approx(8)


def test_files_round_trip(tmp_path):
    w = coverkit.load_map(data("pillars.wkt"))
    plan = coverkit.plan(w, "boustrophedon", radius=0.25)
    assert any(s["kind"] == "arc" for p in plan.paths for s in p.segments)
    f = tmp_path / "p.json"
    plan.write(str(f))
    assert f.read_text() == plan.to_json()
    back = coverkit.read_plan(str(f))
    assert back.valid is None
    assert back.status == plan.status and back.planner == plan.planner
    assert np.array_equal(back.paths[0].pieces, plan.paths[0].pieces)
    assert coverkit.validate(w, back)["valid"] is True
    g = json.loads(plan.to_geojson())
    assert g["type"] == "FeatureCollection" and g["features"][0]["geometry"]["type"] == "LineString"
    png = tmp_path / "p.png"
    plan.picture(str(png))
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    svg = tmp_path / "p.svg"
    back.picture(str(svg), workspace=w)
    assert b"<svg" in svg.read_bytes()[:400]


def test_cspace_and_decompose_as_arrays():
    w = coverkit.load_map(data("pillars.wkt"))
    cs = coverkit.cspace(w, 0.25, start=(1.0, 1.0))
    assert cs["cfree_area"] == pytest.approx(sum(c["area"] for c in cs["components"]), rel=1e-9)
    assert 0 < cs["cfree_area"] < cs["free_area"]
    assert cs["start_component"] == 0 or cs["start_component"] > 0
    outer = cs["components"][0]["outer"]
    assert outer.dtype == np.float64 and outer.shape[1] == 7
    loops = np.vstack([outer, *cs["components"][0]["holes"]])
    assert set(np.unique(loops[:, 6])) <= {-1.0, 0.0, 1.0} and (loops[:, 6] != 0).any()   # arcs about the pillars' corners
    # consecutive pieces of a loop meet
    assert np.allclose(outer[:-1, 2:4], outer[1:, 0:2]) and np.allclose(outer[-1, 2:4], outer[0, 0:2])
    d = coverkit.decompose(w, 0.25, "boustrophedon")
    assert sum(c["area"] for c in d["cells"]) == pytest.approx(d["cfree_area"], rel=1e-9)
    for c in d["cells"]:
        for n in c["neighbours"]:
            assert c["index"] in d["cells"][n]["neighbours"]
    t = coverkit.decompose(w, 0.25, "trapezoidal")
    assert len(t["cells"]) >= len(d["cells"])


def test_decompose_gives_the_command_lines_cells_file(tmp_path):
    out = tmp_path / "cells.json"
    path = data("pillars.wkt")
    cli("decompose", "--map", path, "--radius", "0.25", "--method", "boustrophedon", "--param", "direction=20", "--out", str(out))
    d = coverkit.decompose(coverkit.load_map(path), 0.25, "boustrophedon", {"direction": 20})
    assert d["json"] == out.read_text()


def test_plot_draws_with_matplotlib():
    mpl = pytest.importorskip("matplotlib")
    mpl.use("Agg")
    import matplotlib.pyplot as plt

    w = coverkit.load_map(data("pillars.wkt"))
    plan = coverkit.plan(w, "stc", radius=0.25)
    fig, ax = plt.subplots()
    plan.plot(ax, workspace=w)
    assert len(ax.lines) == len(w.rings()) + len(plan.paths)
    plt.close(fig)


# --- errors -------------------------------------------------------------------------------------

def test_input_error_is_a_value_error_with_the_command_lines_message(tmp_path):
    assert issubclass(coverkit.InputError, ValueError)
    missing = str(tmp_path / "nope.yaml")
    with pytest.raises(coverkit.InputError) as e:
        coverkit.load_map(missing)
    r = cli("plan", "--map", missing, "--radius", "0.25", "--planner", "stc", "--out", str(tmp_path / "o.json"), check=False)
    assert r.returncode == 2
    assert str(e.value) in r.stderr
    assert not (tmp_path / "o.json").exists()


@pytest.mark.parametrize("call, error, words", [
    (lambda w: coverkit.plan(w, "no_such_planner", 0.25), coverkit.InputError, "unknown planner"),
    (lambda w: coverkit.plan(w, "stc", -0.25), coverkit.InputError, "radius"),
    (lambda w: coverkit.plan(w, "stc", 0), coverkit.InputError, "radius"),
    (lambda w: coverkit.plan(w, "stc", float("nan")), coverkit.InputError, "finite"),
    (lambda w: coverkit.plan(w, "stc", "abc"), coverkit.InputError, "radius"),
    (lambda w: coverkit.plan(w, "stc", True), TypeError, "bool"),
    (lambda w: coverkit.plan(w, "stc", 0.25, start=(float("nan"), 1.0)), coverkit.InputError, "start"),
    (lambda w: coverkit.plan(w, "stc", 0.25, start=(1.0,)), coverkit.InputError, "start"),
    (lambda w: coverkit.plan(w, "stc", 0.25, start="1,2"), TypeError, "start"),
    (lambda w: coverkit.plan(w, "stc", 0.25, params={"nope": 1}), coverkit.InputError, "nope"),
    (lambda w: coverkit.plan(w, "boustrophedon", 0.25, params={"direction": "north"}), coverkit.InputError, "direction"),
    (lambda w: coverkit.plan(w, "stc", 0.25, post=["smoothen"]), coverkit.InputError, "processor"),
    (lambda w: coverkit.plan(w, "stc", 0.25, post=["fillet:radius=1"]), coverkit.InputError, "radius"),
    (lambda w: coverkit.plan(w, "stc", 0.25, post="fillet"), TypeError, "list"),
    (lambda w: coverkit.plan(w, "stc", 0.25, time_limit=-1), coverkit.InputError, "time_limit"),
    (lambda w: coverkit.plan(None, "stc", 0.25), TypeError, "workspace"),
    (lambda w: coverkit.Workspace.from_grid(np.ones((4, 4), dtype=np.uint8)), TypeError, "bool"),
    (lambda w: coverkit.Workspace.from_grid(np.ones(16, dtype=bool)), TypeError, "2-D"),
    (lambda w: coverkit.Workspace.from_grid(np.zeros((4, 4), dtype=bool)), coverkit.InputError, "empty free space"),
    (lambda w: coverkit.Workspace.from_grid(np.ones((4, 4), dtype=bool), resolution=-1), coverkit.InputError, "resolution"),
    (lambda w: coverkit.Workspace.from_grid([[True]]), TypeError, ""),
    (lambda w: coverkit.Workspace.from_wkt("POLYGON((0 0,1 0"), coverkit.InputError, "<wkt>"),
    (lambda w: coverkit.Workspace.from_geojson({"type": "Point", "coordinates": [0, 0]}), coverkit.InputError, ""),
    (lambda w: coverkit.validate(w, np.array([[0, 0], [1, 1]]), radius=0.25), TypeError, "float64"),
    (lambda w: coverkit.validate(w, np.array([[0.0, 0.0], [1.0, 1.0]])), coverkit.InputError, "radius"),
    (lambda w: coverkit.validate(w, np.array([[0.0, math.inf]]), radius=0.25), coverkit.InputError, "finite"),
    (lambda w: coverkit.decompose(w, 0.25, "nope"), coverkit.InputError, "unknown decomposition"),
    (lambda w: coverkit.decompose(coverkit.Workspace.from_wkt("POLYGON((0 0,4 0,4 4,0 4,0 0),(1 1,3 1,3 3,1 3,1 1))"), 0.6),
     coverkit.InputError, "C-free is empty"),
    (lambda w: coverkit.plan(w, "stc", 50), coverkit.InputError, "larger than the workspace"),
    (lambda w: coverkit.read_plan("/nonexistent/p.json"), coverkit.InputError, "p.json"),
])
def test_every_bad_argument_is_a_python_exception(call, error, words):
    w = coverkit.load_map(data("pillars.wkt"))
    with pytest.raises(error) as e:
        call(w)
    assert words in str(e.value)


def test_writing_to_a_bad_place_leaves_nothing(tmp_path):
    w = coverkit.load_map(data("pillars.wkt"))
    plan = coverkit.plan(w, "stc", 0.25)
    with pytest.raises(coverkit.InputError):
        plan.write(str(tmp_path / "no_folder" / "p.json"))
    with pytest.raises(coverkit.InputError):
        plan.write(str(tmp_path / "p.txt"))
    assert list(tmp_path.iterdir()) == []


# --- threads ------------------------------------------------------------------------------------

def test_threads_plan_in_parallel_with_the_same_results():
    w = coverkit.load_map(data("rooms.grid"))
    jobs = [("boustrophedon", 0.125), ("smooth_stc", 0.125), ("stc", 0.125), ("bsa_spiral", 0.125)]
    alone = [coverkit.plan(w, p, r).to_json() for p, r in jobs]
    together = [None] * len(jobs)

    def run(i):
        together[i] = coverkit.plan(w, *jobs[i]).to_json()

    threads = [threading.Thread(target=run, args=(i,)) for i in range(len(jobs))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert together == alone


def test_the_gil_is_released_while_planning():
    w = coverkit.load_map(data("pillars.wkt"))
    ticks = 0
    done = threading.Event()

    def count():
        nonlocal ticks
        while not done.is_set():
            ticks += 1
            time.sleep(0.001)

    t = threading.Thread(target=count)
    t.start()
    time.sleep(0.05)
    before = ticks
    start = time.perf_counter()
    plan = coverkit.plan(w, "boustrophedon", 0.1, params={"decomposition": "trapezoidal"})
    elapsed = time.perf_counter() - start
    during = ticks - before
    done.set()
    t.join()
    assert plan.valid
    # the counter thread ran while the plan was made (with the GIL held it could not run at all)
    if elapsed > 0.05:
        assert during >= 5
