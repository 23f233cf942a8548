#include <coverkit/geometry/error.h>
#include <coverkit/graph/grid_search.h>
#include <coverkit/planners/planner.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace coverkit::planners {

const char* toString(ParamType t) {
  switch (t) {
    case ParamType::kInt: return "int";
    case ParamType::kDouble: return "double";
    case ParamType::kBool: return "bool";
    case ParamType::kChoice: return "choice";
    case ParamType::kPath: return "path";
  }
  return "?";
}

namespace {
std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep)) out.push_back(cur);
  return out;
}
}  // namespace

ParamSet::ParamSet(const std::vector<ParamSpec>& specs, const std::map<std::string, std::string>& given, const std::string& planner,
                   const std::string& kind) {
  for (const auto& entry : given) {
    const std::string& key = entry.first;  // not a structured binding: clang before 16 cannot capture one
    auto it = std::find_if(specs.begin(), specs.end(), [&](const ParamSpec& s) { return s.name == key; });
    if (it == specs.end()) {
      std::string known;
      for (const auto& s : specs) known += (known.empty() ? "" : ", ") + s.name;
      throw InputError("--param", key, "unknown parameter of " + kind + " '" + planner + "' (known: " + (known.empty() ? "none" : known) + ")");
    }
  }
  for (const ParamSpec& s : specs) {
    auto it = given.find(s.name);
    const std::string v = it == given.end() ? s.defaultValue : it->second;
    const std::string place = s.name + "=" + v;
    if (s.type == ParamType::kChoice) {
      const auto choices = split(s.range, '|');
      if (std::find(choices.begin(), choices.end(), v) == choices.end())
        throw InputError("--param", place, "must be one of " + s.range);
    } else if (s.type == ParamType::kPath) {
      if (v.empty()) throw InputError("--param", place, "must be one of " + s.range + " (FILE: the path of a file)");
    } else if (s.type == ParamType::kBool) {
      if (v != "true" && v != "false") throw InputError("--param", place, "must be true or false");
    } else {
      // "lo:hi" or "lo:hi|word|...": a number in range, or one of the words
      auto alternatives = split(s.range, '|');
      const std::string numeric = alternatives.empty() ? std::string() : alternatives.front();
      if (alternatives.size() > 1 && std::find(alternatives.begin() + 1, alternatives.end(), v) != alternatives.end()) {
        values_[s.name] = v;
        continue;
      }
      Rational q;
      try {
        q = parseRational(v, "--param", place);
      } catch (const InputError&) {
        if (alternatives.size() <= 1) throw;
        std::string words;
        for (std::size_t k = 1; k < alternatives.size(); ++k) words += (words.empty() ? "" : ", ") + alternatives[k];
        throw InputError("--param", place, "must be a number in [" + numeric + "] or " + words);
      }
      if (s.type == ParamType::kInt && q.get_den() != 1) throw InputError("--param", place, "must be an integer");
      const auto lim = split(numeric, ':');
      if (lim.size() == 2) {
        if ((!lim[0].empty() && q < parseRational(lim[0])) || (!lim[1].empty() && q > parseRational(lim[1])))
          throw InputError("--param", place, "out of range [" + numeric + "]");
      }
    }
    values_[s.name] = v;
  }
}

const std::string& ParamSet::text(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) throw std::logic_error("undeclared parameter " + name);
  return it->second;
}
double ParamSet::number(const std::string& name) const { return parseRational(text(name)).get_d(); }
long ParamSet::integer(const std::string& name) const { return static_cast<long>(parseRational(text(name)).get_d()); }
bool ParamSet::flag(const std::string& name) const { return text(name) == "true"; }

std::optional<Point> defaultStart(const CellGrid& cells) {
  // Largest 4-connected component over a predicate (the first of equal ones in row order); returns
  // its first cell in row order.
  auto firstOfLargest = [](int cols, int rows, auto&& ok) -> std::optional<CellIndex> {
    const std::vector<int> comp = graph::gridComponents(cols, rows, [&](int v) { return ok(v % cols, v / cols); });
    std::vector<std::size_t> size;
    std::vector<int> first;  // components are numbered in row order of their first cell
    for (int v = 0; v < cols * rows; ++v) {
      const int k = comp[static_cast<std::size_t>(v)];
      if (k < 0) continue;
      if (static_cast<std::size_t>(k) == size.size()) {
        size.push_back(0);
        first.push_back(v);
      }
      ++size[static_cast<std::size_t>(k)];
    }
    std::size_t bestSize = 0;
    int bestFirst = -1;
    for (std::size_t k = 0; k < size.size(); ++k)
      if (size[k] > bestSize) {
        bestSize = size[k];
        bestFirst = first[k];
      }
    if (bestFirst < 0) return std::nullopt;
    return CellIndex{bestFirst % cols, bestFirst / cols};
  };
  auto mega = firstOfLargest(cells.megaCols(), cells.megaRows(), [&](int c, int r) { return cells.mega(c, r) == CellState::kFree; });
  if (mega) {
    // first sub-cell in row order of that mega-cell: its bottom-left quadrant. Its centre is taken
    // as the double next to it towards the mega-cell's centre (the waypoint STC uses), so that the
    // start as written in a path file is exactly the start.
    const PointD w = stcWaypoint(cells, 2 * mega->col, 2 * mega->row);
    return Point{exactFromDouble(w.x), exactFromDouble(w.y)};
  }
  auto sub = firstOfLargest(cells.subCols(), cells.subRows(), [&](int c, int r) { return cells.sub(c, r) == CellState::kFree; });
  if (sub) {
    const Point c = cells.subCenter(sub->col, sub->row);
    return Point{exactFromDouble(toDouble(c.x)), exactFromDouble(toDouble(c.y))};
  }
  return std::nullopt;
}

PointD stcWaypoint(const CellGrid& cells, int col, int row) {
  const Point c = cells.subCenter(col, row), m = cells.megaCenter(col / 2, row / 2);
  return {roundToward(c.x, m.x), roundToward(c.y, m.y)};
}

void spreadStarts(const CellGrid& cells, std::vector<Robot>& robots, const std::vector<MovingObstacle>& obstacles) {
  // the sub-cells of free mega-cells, as a 4-connected grid of sub-cells
  const int cols = cells.subCols(), rows = cells.subRows();
  auto usable = [&](int c, int r) { return c >= 0 && r >= 0 && c < cols && r < rows && cells.mega(c / 2, r / 2) == CellState::kFree; };
  auto waypoint = [&](long v) { return stcWaypoint(cells, static_cast<int>(v % cols), static_cast<int>(v / cols)); };
  auto exactly = [](PointD p) { return Point{exactFromDouble(p.x), exactFromDouble(p.y)}; };
  std::vector<long> placed;
  auto cellOf = [&](const Point& p) -> long {
    CellIndex ci;
    if (!cells.locateSub(p, ci) || !usable(ci.col, ci.row)) return -1;
    return static_cast<long>(ci.row) * cols + ci.col;
  };
  for (const Robot& r : robots)
    if (r.start && cellOf(*r.start) >= 0) placed.push_back(cellOf(*r.start));
  // within r + a moving obstacle's radius of where it is in the first kPlacementClearSeconds (with
  // a margin; checkProblem decides the first place exactly): a robot placed where an obstacle
  // arrives at once could not leave in time (its first step, onto its sub-cell's centre, would
  // meet it); one clear for that long has ten steps of 0.1 s to get out of the way
  constexpr double kPlacementClearSeconds = 1.0;
  auto nearObstacle = [&](long v, const Rational& radius) {
    if (obstacles.empty()) return false;
    const PointD c = waypoint(v);
    for (const MovingObstacle& m : obstacles) {
      if (m.waypoints.empty()) continue;
      const double reach = Rational(radius + m.radius).get_d() * (1 + 1e-9) + 1e-9;
      // the obstacle's way over [0, kPlacementClearSeconds]: straight between its waypoints
      std::vector<PointD> way{m.at(0)};
      for (const TimedPoint& w : m.waypoints)
        if (w.t > 0 && w.t < kPlacementClearSeconds) way.push_back(w.p);
      way.push_back(m.at(kPlacementClearSeconds));
      for (std::size_t i = 0; i + 1 < way.size(); ++i) {
        const PointD a = way[i], b = way[i + 1];
        const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
        const double u = len2 > 0 ? std::clamp(((c.x - a.x) * dx + (c.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
        const double ex = a.x + u * dx - c.x, ey = a.y + u * dy - c.y;
        if (ex * ex + ey * ey < reach * reach) return true;
      }
    }
    return false;
  };
  if (placed.empty()) {   // the documented default start first, or the nearest sub-cell to it clear of the obstacles' first places
    const std::optional<Point> d = defaultStart(cells);
    if (!d || cellOf(*d) < 0) throw InputError("--robots", std::to_string(robots.size()), "no free mega-cell to place the robots in");
    long first = cellOf(*d);
    Robot* r0 = nullptr;
    for (Robot& r : robots)
      if (!r.start) {
        r0 = &r;
        break;
      }
    if (r0 && nearObstacle(first, r0->radius)) {
      const std::vector<int> dist = graph::gridDistances(cols, rows, {first}, [&](int v) { return usable(v % cols, v / cols); });
      long best = -1;
      for (long v = 0; v < static_cast<long>(dist.size()); ++v)
        if (dist[static_cast<std::size_t>(v)] > 0 && (best < 0 || dist[static_cast<std::size_t>(v)] < dist[static_cast<std::size_t>(best)]) &&
            !nearObstacle(v, r0->radius))
          best = v;
      if (best < 0)
        throw InputError("--robots", std::to_string(robots.size()),
                         "no sub-cell of free mega-cells reachable from the default start is clear of the moving obstacles' first places");
      first = best;
    }
    placed.push_back(first);
    if (r0) r0->start = exactly(waypoint(first));
  }
  for (Robot& r : robots) {
    if (r.start) continue;
    // the farthest reachable sub-cell from those placed, first in row order, not where a moving
    // obstacle starts
    const std::vector<int> dist = graph::gridDistances(cols, rows, placed, [&](int v) { return usable(v % cols, v / cols); });
    long best = -1;
    for (long v = 0; v < static_cast<long>(dist.size()); ++v)
      if (dist[static_cast<std::size_t>(v)] > 0 && (best < 0 || dist[static_cast<std::size_t>(v)] > dist[static_cast<std::size_t>(best)]) && !nearObstacle(v, r.radius))
        best = v;
    if (best < 0) throw InputError("--robots", std::to_string(robots.size()), "more robots than sub-cells of free mega-cells reachable from the first" +
                                                                  std::string(obstacles.empty() ? "" : " and clear of the moving obstacles' first places"));
    placed.push_back(best);
    r.start = exactly(waypoint(best));
  }
}

namespace {
/// A rational for messages: the nearest double when it is one, else the leading digits of its text.
std::string shortText(const Rational& q) {
  const double d = q.get_d();
  if (q == 0 || (std::isfinite(d) && d != 0 && std::fabs(d) < 1e300)) return formatDouble(toDouble(q));
  const std::string t = q.get_str();
  if (t.size() <= 40) return t;
  const long e = static_cast<long>(mpz_sizeinbase(q.get_num_mpz_t(), 10)) - static_cast<long>(mpz_sizeinbase(q.get_den_mpz_t(), 10));
  return std::string(q < 0 ? "-" : "") + "about 10^" + std::to_string(e);
}
}  // namespace

void checkProblem(const Problem& problem, bool teamStarts) {
  const std::string& name = problem.workspace.name;
  if (problem.robots.empty()) throw InputError(name, "robots", "no robot");
  if (problem.workspace.regions.empty()) throw InputError(name, "workspace", "empty free space");
  const Box b = problem.workspace.bbox();
  // paths, pictures and metrics are doubles: at 1e15 a double's spacing is 0.125 map units (the
  // polygon readers refuse such coordinates already, checkWorkspace; grid maps are checked here)
  static const Rational coordinateLimit(mpz_class("1" + std::string(15, '0')));
  for (const Rational* v : {&b.xmin, &b.xmax, &b.ymin, &b.ymax})
    if (abs(*v) > coordinateLimit)
      throw InputError(name, "coordinates", "a coordinate of magnitude about 10^" + std::to_string(mpz_sizeinbase(mpz_class(abs(*v)).get_mpz_t(), 10) - 1) +
                                                " is beyond the limit of 10^15 (paths are written in doubles, which cannot resolve the map out there)");
  for (std::size_t i = 0; i < problem.robots.size(); ++i) {
    const Robot& r = problem.robots[i];
    if (r.radius <= 0) throw InputError("--radius", shortText(r.radius), "robot radius must be > 0");
    if (2 * r.radius > b.xmax - b.xmin || 2 * r.radius > b.ymax - b.ymin)
      throw InputError("--radius", shortText(r.radius), "robot is larger than the workspace (" + name + ")");
    if (r.start && !strictlyInside(problem.workspace, *r.start))
      throw InputError("--start", shortText(r.start->x) + "," + shortText(r.start->y), "start is outside the workspace or inside an obstacle of " + name);
  }
  if (problem.cellSize && *problem.cellSize <= 0) throw InputError("--cell-size", shortText(*problem.cellSize), "must be > 0");
  // a team: no two robots start nearer than the sum of their radii, no moving obstacle starts on a
  // robot (exactly; touching is allowed, as the validator allows it); a plan being evaluated is
  // judged on them by the validator instead
  if (!teamStarts) return;
  auto dist2 = [](const Point& a, const Point& b) { return Rational((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y)); };
  for (std::size_t i = 0; i < problem.robots.size(); ++i) {
    const Robot& a = problem.robots[i];
    if (!a.start) continue;
    for (std::size_t j = i + 1; j < problem.robots.size(); ++j) {
      const Robot& b = problem.robots[j];
      if (b.start && dist2(*a.start, *b.start) < (a.radius + b.radius) * (a.radius + b.radius))
        throw InputError("--start", "robots " + std::to_string(i) + " and " + std::to_string(j),
                         "start closer than the sum of their radii (" + shortText(Rational(a.radius + b.radius)) + ")");
    }
    for (std::size_t o = 0; o < problem.movingObstacles.size(); ++o) {
      const MovingObstacle& m = problem.movingObstacles[o];
      if (m.waypoints.empty()) throw InputError("--scenario", "dynamic_obstacles[" + std::to_string(o) + "]", "no waypoints");
      const Point at{exactFromDouble(m.waypoints.front().p.x), exactFromDouble(m.waypoints.front().p.y)};
      if (dist2(*a.start, at) < (a.radius + m.radius) * (a.radius + m.radius))
        throw InputError("--scenario", "dynamic_obstacles[" + std::to_string(o) + "]",
                         "starts on robot " + std::to_string(i) + " (nearer than r + its radius to the robot's start)");
    }
  }
}

void checkCellGridSize(const Problem& problem) {
  const Rational D = problem.subCellSize();
  const Box b = problem.workspace.bbox();
  // mega-cells of side 2D over the bounding box, counted exactly (no overflow for any D > 0)
  auto megaCells = [&](const Rational& extent) {
    const Rational q = extent / (2 * D);
    mpz_class c;
    mpz_cdiv_q(c.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
    return c < 1 ? mpz_class(1) : c;
  };
  const mpz_class cols = 2 * megaCells(b.xmax - b.xmin), rows = 2 * megaCells(b.ymax - b.ymin);
  if (cols * rows <= kMaxSubCells) return;
  auto approx = [](const mpz_class& n) {
    std::ostringstream os;
    if (n < 1000000) os << n.get_str();
    else if (std::isfinite(n.get_d())) os << std::setprecision(3) << n.get_d();
    else os << "10^" << mpz_sizeinbase(n.get_mpz_t(), 10) - 1;
    return os.str();
  };
  const bool byCellSize = problem.cellSize.has_value();
  const std::string option = byCellSize ? "--cell-size" : "--radius";
  const std::string value = shortText(byCellSize ? *problem.cellSize : problem.robots.at(0).radius);
  throw InputError(option, value,
                   "the sub-cell grid would have " + approx(cols) + " × " + approx(rows) + " sub-cells of size D = " + shortText(D) +
                       (byCellSize ? "" : " (2r)") + " over the " + shortText(Rational(b.xmax - b.xmin)) + " × " +
                       shortText(Rational(b.ymax - b.ymin)) + " bounding box of " + problem.workspace.name + ", more than the limit of " +
                       approx(mpz_class(kMaxSubCells)) + " sub-cells: use a larger " + (byCellSize ? "cell size" : "radius or cell size"));
}

namespace {

/// Whether every sub-cell centre x0 + (i + 1/2)·D, i < n, is a double.
bool centresAreDoubles(const Rational& x0, const Rational& D, const Rational& extent) {
  const Rational q = extent / (2 * D);
  mpz_class mega;
  mpz_cdiv_q(mega.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  const long n = 2 * std::max(1L, mega.get_si());
  for (long i = 0; i < n; ++i) {
    const Rational c = x0 + ratio(2 * i + 1, 2) * D;
    if (Rational(toDouble(c)) != c) return false;
  }
  return true;
}

}  // namespace

std::optional<Rational> teamSubCellSize(const Problem& problem) {
  if ((problem.robots.size() < 2 && problem.movingObstacles.empty()) || problem.cellSize) return std::nullopt;
  const Rational twoR = 2 * problem.robots[0].radius;
  const Box b = problem.workspace.bbox();
  if (centresAreDoubles(b.xmin, twoR, b.xmax - b.xmin) && centresAreDoubles(b.ymin, twoR, b.ymax - b.ymin)) return std::nullopt;
  // δ: the power of two at or above the map's largest coordinate magnitude (at least 1), times 2^-30
  double far = 1;
  for (const Rational* v : {&b.xmin, &b.xmax, &b.ymin, &b.ymax}) far = std::max(far, std::abs(toDouble(*v)));
  int e = 0;
  std::frexp(far, &e);   // far < 2^e
  const Rational delta = e - 30 >= 0 ? Rational(mpz_class(1) << static_cast<unsigned>(e - 30)) : Rational(mpz_class(1), mpz_class(1) << static_cast<unsigned>(30 - e));
  const Rational q = twoR / delta;
  mpz_class steps;
  mpz_cdiv_q(steps.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return Rational(mpz_class(steps + 1)) * delta;
}

PlanningContext makeContext(Problem problem, bool teamStarts) {
  checkProblem(problem, teamStarts);
  checkCellGridSize(problem);  // before the grid is allocated
  if (std::optional<Rational> D = teamSubCellSize(problem)) problem.cellSize = *D;
  PlanningContext ctx;
  const auto t0 = std::chrono::steady_clock::now();
  ctx.cells = classifyCells(problem.workspace, problem.subCellSize());
  ctx.cellSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::size_t unplaced = 0;
  for (const Robot& r : problem.robots) unplaced += !r.start;
  if (problem.robots.size() > 1 && unplaced > 0) {
    spreadStarts(ctx.cells, problem.robots, problem.movingObstacles);
    checkProblem(problem, teamStarts);   // the placed starts against the moving obstacles
  } else {
    for (Robot& r : problem.robots)
      if (!r.start) r.start = defaultStart(ctx.cells);
    if (unplaced > 0 && !problem.movingObstacles.empty()) checkProblem(problem, teamStarts);   // the default start against the obstacles
  }
  ctx.problem = std::move(problem);
  return ctx;
}

}  // namespace coverkit::planners
