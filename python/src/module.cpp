// The Python module `coverkit._coverkit` (docs/python.md). It calls the same functions as the
// command line (experiments/src/runner.h), so a plan made here is the plan `coverkit plan` makes,
// byte for byte in its JSON. No CGAL here: the libraries are linked, their headers are CGAL-free.
//
// Decisions:
//  - Numbers that decide geometry (radius, start, resolution, origin) are exact rationals in the
//    library. A Python float is taken as the decimal it prints as (repr: 0.1 is 1/10, as
//    `--radius 0.1` on the command line); a str is parsed exactly ("1/4", "0.25"); an int is exact.
//  - Errors: coverkit.InputError (a ValueError) with the command line's message (file, place,
//    problem); TypeError for an argument of the wrong type (an array that is not bool, a start that
//    is not a pair). Never a crash.
//  - The GIL is released for everything that computes (reading, cells, C-space, planning,
//    validation, metrics), so Python threads plan in parallel.
#include "render.h"
#include "runner.h"

#include <coverkit/optimise/processor.h>
#include <coverkit/datasets/path_io.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/error.h>
#include <coverkit/planners/registry.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <optional>

namespace py = pybind11;
using namespace coverkit;

namespace {

using WorkspacePtr = std::shared_ptr<const Workspace>;

/// A number for the geometry: int exactly, float as the decimal it prints as, str parsed exactly.
Rational exactNumber(const py::handle& v, const std::string& what) {
  if (py::isinstance<py::bool_>(v)) throw py::type_error(what + ": expected a number, got a bool");
  if (py::isinstance<py::int_>(v)) return parseRational(py::str(v).cast<std::string>(), what);
  if (py::isinstance<py::float_>(v)) {
    const double d = v.cast<double>();
    if (!std::isfinite(d)) throw InputError(what, py::repr(v).cast<std::string>(), "must be a finite number");
    return parseRational(py::repr(v).cast<std::string>(), what);
  }
  if (py::isinstance<py::str>(v)) {
    const std::string s = v.cast<std::string>();
    return parseRational(s, what, s);
  }
  // numpy scalars and other numbers: through float
  if (py::hasattr(v, "__float__")) return exactNumber(py::float_(v.attr("__float__")()), what);
  throw py::type_error(what + ": expected a number (int, float or str), got " + py::str(py::type::of(v)).cast<std::string>());
}

Point exactPoint(const py::handle& v, const std::string& what) {
  if (py::isinstance<py::str>(v) || !py::isinstance<py::sequence>(v)) {
    if (py::isinstance<py::array>(v)) return exactPoint(v.attr("tolist")(), what);
    throw py::type_error(what + ": expected a pair (x, y)");
  }
  const py::sequence s = py::reinterpret_borrow<py::sequence>(v);
  if (s.size() != 2) throw InputError(what, py::repr(v).cast<std::string>(), "expected a pair (x, y)");
  return {exactNumber(s[0], what), exactNumber(s[1], what)};
}

std::string paramText(const py::handle& v) {
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::float_>(v)) return py::repr(v).cast<std::string>();
  return py::str(v).cast<std::string>();
}

std::map<std::string, std::string> paramMap(const std::optional<py::dict>& params) {
  std::map<std::string, std::string> out;
  if (!params) return out;
  for (const auto& [k, v] : *params) {
    if (!py::isinstance<py::str>(k)) throw py::type_error("params: keys must be str");
    out[k.cast<std::string>()] = paramText(v);
  }
  return out;
}

double timeLimitOf(const py::object& t) {
  if (t.is_none()) return 0;
  if (py::isinstance<py::bool_>(t) || !(py::isinstance<py::int_>(t) || py::isinstance<py::float_>(t)))
    throw py::type_error("time_limit: expected a number of seconds or None");
  const double s = t.cast<double>();
  if (!std::isfinite(s) || s < 0 || s > 1e9) throw InputError("time_limit", py::repr(t).cast<std::string>(), "must be a finite number of seconds in [0, 10^9] (0: no limit)");
  return s;
}

Rational radiusOf(const py::handle& v) {
  const Rational r = exactNumber(v, "radius");
  if (r <= 0) throw InputError("radius", r.get_str(), "robot radius must be > 0");
  return r;
}

py::tuple xy(PointD p) { return py::make_tuple(p.x, p.y); }

/// Pieces as rows x0, y0, x1, y1, cx, cy, kind (0 line, 1 counter-clockwise arc, -1 clockwise arc).
py::array_t<double> piecesArray(const std::vector<PathSegment>& pieces) {
  py::array_t<double> a({static_cast<py::ssize_t>(pieces.size()), static_cast<py::ssize_t>(7)});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const PathSegment& s = pieces[i];
    const bool arc = s.kind == PathSegment::Kind::kArc;
    const double row[7] = {s.from.x, s.from.y, s.to.x, s.to.y, arc ? s.center.x : 0, arc ? s.center.y : 0, arc ? (s.ccw ? 1.0 : -1.0) : 0};
    for (int k = 0; k < 7; ++k) m(static_cast<py::ssize_t>(i), k) = row[k];
  }
  return a;
}

py::dict regionDict(const CurveRegion& r) {
  py::dict d;
  d["area"] = r.area;
  d["outer"] = piecesArray(r.outer.pieces);
  py::list holes;
  for (const CurveLoop& h : r.holes) holes.append(piecesArray(h.pieces));
  d["holes"] = holes;
  return d;
}

py::array_t<double> pointsArray(const std::vector<PointD>& pts) {
  py::array_t<double> a({static_cast<py::ssize_t>(pts.size()), static_cast<py::ssize_t>(2)});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    m(static_cast<py::ssize_t>(i), 0) = pts[i].x;
    m(static_cast<py::ssize_t>(i), 1) = pts[i].y;
  }
  return a;
}

/// A plan as Python sees it: the path file's content, and (for plans made here) the context it was
/// made in and the validator's report.
struct PyPlan {
  datasets::PathDocument doc;
  std::string message;
  std::vector<std::pair<std::string, double>> timings;
  std::optional<ValidationReport> validation;
  std::shared_ptr<const planners::PlanningContext> context;   ///< none for a plan read from a file
  std::vector<std::pair<PointD, PointD>> tree;

  /// The path document with the workspace it was planned in, for the writers (arcs sampled on
  /// their checked safe side in CSV and GeoJSON).
  datasets::PathDocument document() const {
    datasets::PathDocument d = doc;
    d.workspace = context ? &context->problem.workspace : nullptr;
    return d;
  }
  std::string content(const std::string& extension) const { return datasets::pathFileContent("plan" + extension, document()); }
};

/// Paths given as (n, 2) arrays of float64 (polylines), or a Plan's paths.
std::vector<Path> pathsOf(const py::handle& v, Rational& radius, bool radiusGiven) {
  if (py::isinstance<PyPlan>(v)) {
    const PyPlan& p = v.cast<const PyPlan&>();
    if (!radiusGiven) radius = p.doc.robotRadius;
    return p.doc.paths;
  }
  if (!radiusGiven) throw InputError("radius", "", "missing: give radius= with paths that are arrays");
  py::list items;
  if (py::isinstance<py::array>(v)) items.append(v);
  else if (py::isinstance<py::sequence>(v) && !py::isinstance<py::str>(v)) items = py::list(py::reinterpret_borrow<py::object>(v));
  else throw py::type_error("paths: expected a Plan, an (n, 2) float array or a list of them");
  std::vector<Path> out;
  for (const auto& item : items) {
    if (!py::isinstance<py::array>(item)) throw py::type_error("paths: every path must be an (n, 2) numpy array");
    const py::array arr = py::reinterpret_borrow<py::array>(item);
    if (!arr.dtype().is(py::dtype::of<double>())) throw py::type_error("paths: expected dtype float64, got " + py::str(arr.dtype()).cast<std::string>());
    if (arr.ndim() != 2 || arr.shape(1) != 2) throw py::type_error("paths: expected an (n, 2) array");
    if (arr.shape(0) < 1) throw InputError("paths", "path " + std::to_string(out.size()), "no points");
    const auto a = py::array_t<double>(arr).unchecked<2>();
    std::vector<PointD> pts;
    for (py::ssize_t i = 0; i < a.shape(0); ++i) {
      if (!std::isfinite(a(i, 0)) || !std::isfinite(a(i, 1)))
        throw InputError("paths", "path " + std::to_string(out.size()) + ", point " + std::to_string(i), "not a finite number");
      pts.push_back({a(i, 0), a(i, 1)});
    }
    out.push_back(Path::fromPoints(pts));
  }
  if (out.empty()) throw InputError("paths", "", "no path given");
  return out;
}

Problem problemFor(const Workspace& w, const std::vector<Path>& paths, const Rational& r, const std::optional<Rational>& cellSize) {
  Problem problem;
  problem.workspace = w;
  problem.cellSize = cellSize;
  for (const Path& p : paths) problem.robots.push_back({r, Point{exactFromDouble(p.start.x), exactFromDouble(p.start.y)}});
  return problem;
}

py::dict reportDict(const ValidationReport& v) {
  py::dict d;
  d["valid"] = v.valid;
  py::list vs;
  for (const Violation& x : v.violations) {
    py::dict e;
    e["kind"] = x.kind;
    e["robot"] = x.robot;
    e["segment"] = x.segment;
    e["detail"] = x.detail;
    vs.append(e);
  }
  d["violations"] = vs;
  d["segments_checked"] = v.segmentsChecked;
  return d;
}

/// Declared parameters: name, type, default, range, help.
py::list paramList(const std::vector<planners::ParamSpec>& specs) {
  py::list out;
  for (const planners::ParamSpec& s : specs) {
    py::dict q;
    q["name"] = s.name;
    q["type"] = planners::toString(s.type);
    q["default"] = s.defaultValue;
    q["range"] = s.range;
    q["help"] = s.help;
    out.append(q);
  }
  return out;
}

/// Every entry of a registry: name, description, parameters, and what `more` adds.
template <class Registry, class More>
py::list describe(const Registry& registry, More more) {
  py::list out;
  for (const std::string& name : registry.names()) {
    const auto entry = registry.create(name);
    py::dict d;
    d["name"] = name;
    d["description"] = entry->description();
    d["parameters"] = paramList(entry->params());
    more(*entry, d);
    out.append(d);
  }
  return out;
}

py::dict pairsDict(const std::vector<std::pair<std::string, double>>& kv) {
  py::dict d;
  for (const auto& [k, v] : kv) d[py::str(k)] = v;
  return d;
}

Workspace fromGrid(const py::array& array, const py::object& resolution, const py::object& origin) {
  if (!array.dtype().is(py::dtype::of<bool>())) throw py::type_error("from_grid: expected a numpy array of dtype bool (True = free), got " + py::str(array.dtype()).cast<std::string>());
  if (array.ndim() != 2) throw py::type_error("from_grid: expected a 2-D array, got " + std::to_string(array.ndim()) + " dimension(s)");
  datasets::OccupancyGrid g;
  datasets::checkGridSize("<array>", "shape", array.shape(1), array.shape(0));
  g.width = static_cast<int>(array.shape(1));
  g.height = static_cast<int>(array.shape(0));
  g.resolution = exactNumber(resolution, "resolution");
  if (g.resolution <= 0) throw InputError("<array>", "resolution", "must be > 0");
  const Point o = exactPoint(origin, "origin");
  g.originX = o.x;
  g.originY = o.y;
  const auto a = py::array_t<bool>(array).unchecked<2>();
  g.blocked.resize(static_cast<std::size_t>(g.width) * static_cast<std::size_t>(g.height));
  for (int row = 0; row < g.height; ++row)   // row 0 of the array is the top row
    for (int col = 0; col < g.width; ++col)
      g.blocked[static_cast<std::size_t>(g.height - 1 - row) * static_cast<std::size_t>(g.width) + static_cast<std::size_t>(col)] = a(row, col) ? 0 : 1;
  Workspace w;
  {
    py::gil_scoped_release release;
    w = datasets::gridToWorkspace(g, "<array>");
  }
  if (w.regions.empty()) throw InputError("<array>", "", "empty free space: no True cell");
  return w;
}

}  // namespace

PYBIND11_MODULE(_coverkit, m) {
  m.doc() = "coverkit: coverage path planning for disc robots on exact geometry (docs/python.md)";
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);

  py::class_<Workspace, std::shared_ptr<Workspace>>(m, "Workspace", "A workspace: polygons with holes (exact coordinates).")
      .def_static("from_grid", &fromGrid, py::arg("array"), py::arg("resolution") = 1, py::arg("origin") = py::make_tuple(0, 0),
                  "A grid map as a workspace: array[row, col] True = free, row 0 the top row (as in image files), "
                  "origin the lower-left corner (as in ROS maps), resolution the side of a cell.")
      .def_static("from_wkt", [](const std::string& text, const std::string& name) {
            py::gil_scoped_release release;
            return datasets::parseWkt(text, name);
          }, py::arg("text"), py::arg("name") = "<wkt>", "A workspace from WKT (POLYGON or MULTIPOLYGON).")
      .def_static("_from_geojson_text", [](const std::string& text, const std::string& name) {
            py::gil_scoped_release release;
            return datasets::parseGeoJson(text, name);
          }, py::arg("text"), py::arg("name") = "<geojson>")
      .def_property_readonly("name", [](const Workspace& w) { return w.name; })
      .def_property_readonly("bbox", [](const Workspace& w) {
            const Box b = w.bbox();
            return py::make_tuple(b.xmin.get_d(), b.ymin.get_d(), b.xmax.get_d(), b.ymax.get_d());
          }, "(xmin, ymin, xmax, ymax)")
      .def_property_readonly("free_area", [](const Workspace& w) { return freeArea(w).get_d(); })
      .def_property_readonly("vertex_count", &Workspace::vertexCount)
      .def_property_readonly("region_count", [](const Workspace& w) { return w.regions.size(); })
      .def_property_readonly("hole_count", [](const Workspace& w) {
            std::size_t n = 0;
            for (const Region& r : w.regions) n += r.holes.size();
            return n;
          })
      .def("rings", [](const Workspace& w) {
            py::list out;
            for (const Ring* ring : w.rings()) {
              std::vector<PointD> pts;
              for (const Point& p : *ring) pts.push_back({p.x.get_d(), p.y.get_d()});
              out.append(pointsArray(pts));
            }
            return out;
          }, "Every ring (outer rings and holes) as an (n, 2) array.")
      .def("__repr__", [](const Workspace& w) {
            return "<coverkit.Workspace '" + w.name + "': " + std::to_string(w.regions.size()) + " region(s), " + std::to_string(w.vertexCount()) + " vertices>";
          });

  m.def("load_map", [](const std::string& path, bool unknownFree) {
        py::gil_scoped_release release;
        datasets::MapOptions o;
        o.unknownIsFree = unknownFree;
        return datasets::loadMap(path, o);
      }, py::arg("path"), py::arg("unknown_free") = false,
      "Reads a map (.yaml ROS map, .map Moving AI, .wkt, .geojson, .grid), as `coverkit plan --map` does.");

  py::class_<Path>(m, "Path", "One robot's path: lines and circular arcs.")
      .def_property_readonly("start", [](const Path& p) { return xy(p.start); })
      .def_property_readonly("vertices", [](const Path& p) {
            std::vector<PointD> pts{p.start};
            for (const PathSegment& s : p.segments) pts.push_back(s.to);
            return pointsArray(pts);
          }, "The start and the end of every piece, an (n, 2) float64 array (arcs: see segments).")
      .def_property_readonly("segments", [](const Path& p) {
            py::list out;
            for (const PathSegment& s : p.segments) {
              py::dict d;
              d["kind"] = s.kind == PathSegment::Kind::kArc ? "arc" : "line";
              d["from"] = xy(s.from);
              d["to"] = xy(s.to);
              if (s.kind == PathSegment::Kind::kArc) {
                d["center"] = xy(s.center);
                d["ccw"] = s.ccw;
              }
              out.append(d);
            }
            return out;
          }, "Every piece: kind 'line' or 'arc', from, to; arcs also center and ccw.")
      .def_property_readonly("pieces", [](const Path& p) { return piecesArray(p.segments); },
                             "Every piece as a row x0, y0, x1, y1, cx, cy, kind (0 line, 1 ccw arc, -1 cw arc).")
      .def("polyline", [](const Path& p, double tolerance) {
            if (!(tolerance > 0) || !std::isfinite(tolerance)) throw InputError("tolerance", std::to_string(tolerance), "must be a finite number > 0");
            return pointsArray(p.polyline(tolerance));
          }, py::arg("tolerance") = 1e-3, "Points along the path, arcs sampled with chord error <= tolerance.")
      .def_property_readonly("length", &Path::length)
      .def("__len__", [](const Path& p) { return p.segments.size(); });

  py::class_<PyPlan>(m, "Plan", "A coverage plan: status, paths, metrics, statistics, and the validator's verdict.")
      .def_property_readonly("planner", [](const PyPlan& p) { return p.doc.planner; })
      .def_property_readonly("status", [](const PyPlan& p) { return p.doc.status; })
      .def_property_readonly("message", [](const PyPlan& p) { return p.message; })
      .def_property_readonly("radius", [](const PyPlan& p) { return p.doc.robotRadius.get_d(); })
      .def_property_readonly("radius_exact", [](const PyPlan& p) { return p.doc.robotRadius.get_str(); })
      .def_property_readonly("paths", [](const PyPlan& p) { return p.doc.paths; })
      .def_property_readonly("metrics", [](const PyPlan& p) { return pairsDict(p.doc.metrics); })
      .def_property_readonly("statistics", [](const PyPlan& p) { return pairsDict(p.doc.statistics); })
      .def_property_readonly("timings", [](const PyPlan& p) { return pairsDict(p.timings); })
      .def_property_readonly("valid", [](const PyPlan& p) -> py::object {
            if (!p.validation) return py::none();
            return py::bool_(p.validation->valid);
          }, "The exact validator's verdict (None for a plan read from a file: see coverkit.validate).")
      .def_property_readonly("violations", [](const PyPlan& p) {
            return p.validation ? reportDict(*p.validation)["violations"] : py::object(py::list());
          })
      .def_property_readonly("tree_edges", [](const PyPlan& p) {
            py::list out;
            for (const auto& [a, b] : p.tree) out.append(py::make_tuple(xy(a), xy(b)));
            return out;
          })
      .def("to_json", [](const PyPlan& p) { return p.content(".json"); }, "The path file (coverkit.path/1), as `coverkit plan --out x.json` writes it.")
      .def("to_geojson", [](const PyPlan& p) { return p.content(".geojson"); }, "The paths as GeoJSON LineStrings (arcs sampled on their safe side).")
      .def("to_csv", [](const PyPlan& p) { return p.content(".csv"); })
      .def("write", [](const PyPlan& p, const std::string& file) {
            datasets::checkOutputFile(file, "file", {".json", ".csv", ".geojson"});
            datasets::writePathFile(file, p.document());
          }, py::arg("file"), "Writes the path file by extension (.json, .csv, .geojson), all or nothing.")
      .def("picture", [](const PyPlan& p, const std::string& file, const std::shared_ptr<Workspace>& w, const std::string& title) {
            experiments::checkPictureOutput(file, "file");
            const Workspace* ws = w ? w.get() : (p.context ? &p.context->problem.workspace : nullptr);
            if (!ws) throw InputError("workspace", "", "a plan read from a file needs the workspace to draw");
            experiments::PictureContent pc;
            pc.workspace = ws;
            pc.cells = p.context && !w ? &p.context->cells : nullptr;
            pc.tree = &p.tree;
            pc.paths = &p.doc.paths;
            pc.radius = p.doc.robotRadius.get_d();
            pc.title = title.empty() ? p.doc.planner : title;
            std::string bytes;
            {
              py::gil_scoped_release release;
              bytes = experiments::pictureBytes(file, pc);
            }
            datasets::writeFileAtomically(file, bytes);
          }, py::arg("file"), py::arg("workspace") = nullptr, py::arg("title") = "",
          "Draws the plan (PNG or SVG by extension) with coverkit's renderer, as `coverkit plan --picture`.")
      .def("__repr__", [](const PyPlan& p) {
            return "<coverkit.Plan " + p.doc.planner + ": " + p.doc.status + ", " + std::to_string(p.doc.paths.size()) + " path(s)>";
          });

  m.def("_planners", [] {
    return describe(planners::Registry::instance(), [](const planners::Planner& planner, py::dict& d) {
      const planners::Capabilities c = planner.capabilities();
      py::dict caps;
      caps["online"] = c.online;
      caps["multi_robot"] = c.multiRobot;
      caps["needs_cells"] = c.needsCells;
      caps["output"] = c.output;
      caps["coverage"] = c.coverage;
      d["capabilities"] = caps;
    });
  });
  m.def("_decompositions", [] { return describe(planners::DecompositionRegistry::instance(), [](const auto&, py::dict&) {}); });

  m.def("plan", [](const std::shared_ptr<Workspace>& w, const std::string& planner, const py::object& radius, const py::object& start,
                   const std::optional<py::dict>& params, const py::object& post, const py::object& timeLimit, const py::object& cellSize) {
        if (!w) throw py::type_error("plan: workspace must be a coverkit.Workspace");
        planners::Registry::instance().create(planner);   // unknown planner: before any work
        Problem problem;
        problem.workspace = *w;
        Robot robot{radiusOf(radius), std::nullopt};
        if (!start.is_none()) robot.start = exactPoint(start, "start");
        if (!cellSize.is_none()) problem.cellSize = exactNumber(cellSize, "cell_size");
        problem.robots.push_back(robot);
        const auto kv = paramMap(params);
        // path processors as `coverkit plan --post` takes them: "NAME" or "NAME:k=v;...", checked before any work
        std::vector<optimise::PostStep> steps;
        if (!post.is_none()) {
          if (py::isinstance<py::str>(post)) throw py::type_error("plan: post must be a list of strings, e.g. [\"fillet\"]");
          for (const py::handle& step : post) {
            if (!py::isinstance<py::str>(step)) throw py::type_error("plan: each post step must be a string \"NAME[:KEY=VALUE;...]\"");
            steps.push_back(optimise::parsePostStep(step.cast<std::string>()));
          }
          optimise::checkPostSteps(steps);
        }
        const double limit = timeLimitOf(timeLimit);
        PyPlan out;
        {
          py::gil_scoped_release release;
          auto ctx = std::make_shared<planners::PlanningContext>(planners::makeContext(std::move(problem)));
          const experiments::RunResult r = experiments::runOnce(*ctx, planner, kv, limit, {}, experiments::defaultMetricOptions(), steps);
          out.doc = experiments::pathDocument(*ctx, r);
          out.doc.workspace = nullptr;
          out.message = r.plan.message;
          out.timings = r.plan.timings;
          out.validation = r.validation;
          out.tree = r.plan.treeEdges;
          out.context = std::move(ctx);
        }
        return out;
      }, py::arg("workspace"), py::arg("planner"), py::arg("radius"), py::arg("start") = py::none(), py::arg("params") = py::none(),
      py::arg("post") = py::none(), py::arg("time_limit") = py::none(), py::arg("cell_size") = py::none(),
      "Plans a coverage path as `coverkit plan` does: the plan, validated exactly, with its metrics.");

  m.def("read_plan", [](const std::string& file) {
        PyPlan out;
        {
          py::gil_scoped_release release;
          out.doc = datasets::readPathFile(file);
        }
        return out;
      }, py::arg("file"), "Reads a path file (.json, or .csv as line segments).");

  m.def("validate", [](const std::shared_ptr<Workspace>& w, const py::object& plan, const py::object& radius) {
        if (!w) throw py::type_error("validate: workspace must be a coverkit.Workspace");
        Rational r = radius.is_none() ? Rational(0) : radiusOf(radius);
        const std::vector<Path> paths = pathsOf(plan, r, !radius.is_none());
        ValidationReport v;
        {
          py::gil_scoped_release release;
          v = validatePaths(problemFor(*w, paths, r, std::nullopt), paths);
        }
        return reportDict(v);
      }, py::arg("workspace"), py::arg("plan"), py::arg("radius") = py::none(),
      "The exact validator (continuity, clearance at radius r, start) on a Plan or on (n, 2) polylines.");

  m.def("metrics", [](const std::shared_ptr<Workspace>& w, const py::object& plan, const py::object& radius, const py::object& cellSize) {
        if (!w) throw py::type_error("metrics: workspace must be a coverkit.Workspace");
        Rational r = radius.is_none() ? Rational(0) : radiusOf(radius);
        const std::vector<Path> paths = pathsOf(plan, r, !radius.is_none());
        std::optional<Rational> cs;
        if (!cellSize.is_none()) cs = exactNumber(cellSize, "cell_size");
        else if (py::isinstance<PyPlan>(plan) && plan.cast<const PyPlan&>().doc.cellSize > 0) cs = plan.cast<const PyPlan&>().doc.cellSize;
        Metrics mt;
        {
          py::gil_scoped_release release;
          const planners::PlanningContext ctx = planners::makeContext(problemFor(*w, paths, r, cs));
          MetricOptions o = experiments::defaultMetricOptions();
          o.pathsKnownClear = validatePaths(ctx.problem, paths).valid;
          mt = computeMetrics(ctx.problem, ctx.cells, paths, o);
        }
        return pairsDict(datasets::metricFields(mt));
      }, py::arg("workspace"), py::arg("plan"), py::arg("radius") = py::none(), py::arg("cell_size") = py::none(),
      "The metrics `coverkit evaluate` prints (coverage of sub-cells and of the coverable region, length, turns, ...).");

  m.def("cspace", [](const std::shared_ptr<Workspace>& w, const py::object& radius, double epsilon, const py::object& start) {
        if (!w) throw py::type_error("cspace: workspace must be a coverkit.Workspace");
        Problem problem;
        problem.workspace = *w;
        problem.robots.push_back({radiusOf(radius), std::nullopt});
        if (!start.is_none()) problem.robots[0].start = exactPoint(start, "start");
        if (!(epsilon > 0) || !(epsilon < 1)) throw InputError("epsilon", std::to_string(epsilon), "must be in (0, 1)");
        std::optional<CSpace> cs;
        datasets::CSpaceDocument doc;
        {
          py::gil_scoped_release release;
          planners::checkProblem(problem);
          cs.emplace(problem.workspace, problem.robots[0].radius, epsilon);
          doc = experiments::cspaceDocument(w->name, problem, *cs);
        }
        py::dict d;
        d["radius"] = doc.robotRadius.get_d();
        d["epsilon"] = doc.epsilon;
        d["free_area"] = doc.freeArea;
        d["cfree_area"] = doc.cfreeArea;
        py::list comps, obs;
        for (const CurveRegion& r : doc.components) comps.append(regionDict(r));
        for (const CurveRegion& r : doc.obstacles) obs.append(regionDict(r));
        d["components"] = comps;
        d["obstacles"] = obs;
        d["start_component"] = doc.start ? py::object(py::int_(doc.startComponent)) : py::object(py::none());
        return d;
      }, py::arg("workspace"), py::arg("radius"), py::arg("epsilon") = 1e-6, py::arg("start") = py::none(),
      "The exact C-space of the disc robot: C-free components and C-obstacles, each with its area and its boundary "
      "as rows x0, y0, x1, y1, cx, cy, kind (0 line, 1 ccw arc, -1 cw arc).");

  m.def("decompose", [](const std::shared_ptr<Workspace>& w, const py::object& radius, const std::string& method, const std::optional<py::dict>& params) {
        if (!w) throw py::type_error("decompose: workspace must be a coverkit.Workspace");
        const auto kv = paramMap(params);
        {
          auto d = planners::DecompositionRegistry::instance().create(method);
          planners::ParamSet(d->params(), kv, method, "decomposition");
        }
        Problem problem;
        problem.workspace = *w;
        problem.robots.push_back({radiusOf(radius), std::nullopt});
        datasets::CellsDocument doc;
        std::string json;
        {
          py::gil_scoped_release release;
          planners::checkProblem(problem);
          const planners::Decomposed dec = planners::runDecomposition(method, problem, kv);
          if (!dec.cells.cells.empty()) {
            doc = experiments::cellsDocument(w->name, method, kv, problem, dec, false);
            json = datasets::cellsFileContent("cells.json", doc);
          }
        }
        if (doc.cells.empty()) throw InputError("radius", problem.robots[0].radius.get_str(), "C-free is empty: a disc of this radius fits nowhere in " + w->name + " (no cells)");
        py::dict d;
        d["method"] = method;
        d["direction_degrees"] = doc.directionDegrees;
        d["cfree_area"] = doc.cfreeArea;
        py::list cells;
        for (std::size_t i = 0; i < doc.cells.size(); ++i) {
          py::dict c = regionDict(doc.cells[i].region);
          c["index"] = i;
          c["neighbours"] = doc.cells[i].neighbours;
          cells.append(c);
        }
        d["cells"] = cells;
        py::list walls;
        for (const auto& wl : doc.walls) {
          py::dict e;
          e["a"] = wl.a;
          e["b"] = wl.b;
          e["from"] = xy(wl.from);
          e["to"] = xy(wl.to);
          walls.append(e);
        }
        d["walls"] = walls;
        d["json"] = json;
        return d;
      }, py::arg("workspace"), py::arg("radius"), py::arg("method") = "boustrophedon", py::arg("params") = py::none(),
      "Decomposes the exact C-free into cells (boustrophedon, trapezoidal, grid) as `coverkit decompose` does.");
}
