"""coverkit: coverage path planning for disc robots on exact geometry.

The Python face of the C++ library (docs/python.md): maps in, plans out, numpy arrays where there
are coordinates. Every plan is checked by the exact validator, as on the command line.

    import coverkit
    w = coverkit.load_map("datasets/data/rooms.grid")
    plan = coverkit.plan(w, "boustrophedon", radius=0.25)
    print(plan.status, plan.valid, plan.metrics["coverable_coverage"])
"""
import json as _json

from ._coverkit import (  # noqa: F401  (re-exported)
    InputError,
    Path,
    Plan,
    Workspace,
    cspace,
    decompose,
    load_map,
    metrics,
    plan,
    read_plan,
    validate,
)
from . import _coverkit

__all__ = [
    "InputError", "Path", "Plan", "Workspace", "cspace", "decompose", "decompositions", "load_map",
    "metrics", "plan", "planners", "read_plan", "validate",
]
__version__ = "0.1.0"


def planners():
    """Every registered planner: name, description, parameters (name, type, default, range, help)
    and capabilities (online, multi_robot, needs_cells, output, coverage)."""
    return _coverkit._planners()


def decompositions():
    """Every registered decomposition: name, description and parameters."""
    return _coverkit._decompositions()


def _from_geojson(obj, name="<geojson>"):
    """A workspace from GeoJSON: a Polygon, MultiPolygon, Feature or FeatureCollection, given as a
    dict (as json.load returns it) or as text."""
    text = obj if isinstance(obj, str) else _json.dumps(obj)
    return Workspace._from_geojson_text(text, name)


Workspace.from_geojson = staticmethod(_from_geojson)


def _plot(self, ax=None, workspace=None, pieces_tolerance=1e-3, **style):
    """Draws the plan's paths (and the workspace's rings when given) on a matplotlib Axes.
    matplotlib is imported here only: the module never needs it otherwise."""
    if ax is None:
        import matplotlib.pyplot as plt  # noqa: PLC0415

        ax = plt.gca()
    if workspace is not None:
        for ring in workspace.rings():
            closed = list(ring) + [ring[0]]
            ax.plot([p[0] for p in closed], [p[1] for p in closed], color="black", linewidth=1)
    style.setdefault("linewidth", 0.8)
    for path in self.paths:
        pts = path.polyline(pieces_tolerance)
        ax.plot(pts[:, 0], pts[:, 1], **style)
    ax.set_aspect("equal")
    return ax


Plan.plot = _plot
