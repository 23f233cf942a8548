// The built-in decompositions (decomposition.h): trapezoidal, boustrophedon and grid, all on the
// exact engine of geometry/decomposition.h.
#include <coverkit/geometry/error.h>
#include <coverkit/planners/decompositions.h>

#include <chrono>

namespace coverkit::planners {

namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

ParamSpec directionSpec() {
  return {"direction", ParamType::kDouble, "0", "-360:360",
          "sweep direction in degrees from +x: cells are cut by lines perpendicular to it; turned by the nearest rational "
          "rotation (exact), the angle used is reported"};
}

}  // namespace

Rotation sweepRotation(double degrees) { return Rotation::nearest(-degrees); }

Decomposed prepareFrame(const Workspace& workspace, const Rational& radius, const Rotation& rotation) {
  Decomposed d;
  d.frameWorkspace = rotation.c == 1 ? workspace : rotate(workspace, rotation);
  const auto t0 = std::chrono::steady_clock::now();
  d.space = std::make_shared<const CSpace>(d.frameWorkspace, radius);
  d.cspaceSeconds = secondsSince(t0);
  return d;
}

std::string SweepDecomposition::name() const { return rule_ == DecompositionRule::kBoustrophedon ? "boustrophedon" : "trapezoidal"; }

std::string SweepDecomposition::description() const {
  return rule_ == DecompositionRule::kBoustrophedon
             ? "boustrophedon (Choset & Pignon): walls only where the sweep line's connectivity changes; cells monotone"
             : "trapezoidal (vertical): a wall up and down from every vertex and every x-extreme point of an arc";
}

std::vector<ParamSpec> SweepDecomposition::params() const { return {directionSpec()}; }

DecompositionCapabilities SweepDecomposition::capabilities() const { return {true, true}; }

Decomposed SweepDecomposition::decompose(const Workspace& workspace, const Rational& radius, const ParamSet& params) const {
  const Rotation rot = sweepRotation(params.number("direction"));
  Decomposed d = prepareFrame(workspace, radius, rot);
  const auto t0 = std::chrono::steady_clock::now();
  d.cells = decomposeCSpace(*d.space, rule_, name());
  d.cells.rotation = rot;
  d.decomposeSeconds = secondsSince(t0);
  return d;
}

std::string GridDecomposition::name() const { return "grid"; }
std::string GridDecomposition::description() const {
  return "the mega-cell grid: C-free cut by the lines of the STC planners' mega-cells (side 4r from the bounding box's "
         "corner unless cell_size is given); the pieces of C-free in each mega-cell are the cells";
}
std::vector<ParamSpec> GridDecomposition::params() const {
  return {{"cell_size", ParamType::kDouble, "0", "0:1e15", "mega-cell side (0: 4r, the STC planners' mega-cell with D = 2r)"}};
}
DecompositionCapabilities GridDecomposition::capabilities() const { return {false, false}; }

Decomposed GridDecomposition::decompose(const Workspace& workspace, const Rational& radius, const ParamSet& params) const {
  Decomposed d = prepareFrame(workspace, radius, Rotation{});
  const Rational size = params.number("cell_size") > 0 ? exactFromDouble(params.number("cell_size")) : Rational(4 * radius);
  if (size <= 0) throw InputError("--radius", "0", "the grid decomposition needs a radius > 0 or cell_size > 0");
  const Box b = workspace.bbox();
  const auto t0 = std::chrono::steady_clock::now();
  d.cells = decomposeCSpace(*d.space, DecompositionRule::kGrid, name(), size, Point{b.xmin, b.ymin});
  d.decomposeSeconds = secondsSince(t0);
  return d;
}

}  // namespace coverkit::planners
