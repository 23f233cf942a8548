#pragma once
// The decomposition interface (issue 13), beside Planner and in its style: declared parameters with
// ranges, capabilities, one registration line in registry.cpp. A model splits the exact C-free of a
// disc robot (CSpace) into cells; geometry/decomposition.h has the engine the built-in models use
// and the contract every model must keep (docs/adding-a-decomposition.md):
//  - cells are interior-disjoint exact regions and their union is C-free, exactly;
//  - the adjacency is symmetric and complete: two cells are listed as neighbours exactly when they
//    share a piece of boundary of positive length (a wall);
//  - `monotone` models: every line of the sweep (vertical in the decomposition's frame) meets a
//    cell in one interval at most.
#include <coverkit/geometry/decomposition.h>
#include <coverkit/geometry/path.h>
#include <coverkit/planners/planner.h>

#include <memory>
#include <string>
#include <vector>

namespace coverkit::planners {

struct DecompositionCapabilities {
  bool monotone = false;      ///< cells are monotone along the sweep (sweep lines meet them once)
  bool rotatable = false;     ///< takes a `direction` parameter (degrees)
};

/// A decomposition with what it was made from: the C-space in the decomposition's frame (the
/// workspace rotated by cells.rotation) and the time it took.
struct Decomposed {
  CellDecomposition cells;
  std::shared_ptr<const CSpace> space;   ///< C-free of the rotated workspace, radius as asked
  Workspace frameWorkspace;              ///< the workspace in that frame
  double cspaceSeconds = 0, decomposeSeconds = 0;
};

class Decomposition {
public:
  virtual ~Decomposition() = default;
  virtual std::string name() const = 0;
  virtual std::string description() const = 0;
  virtual std::vector<ParamSpec> params() const = 0;
  virtual DecompositionCapabilities capabilities() const = 0;
  /// Decomposes the C-free of a disc of radius `radius` in `workspace`. Bad parameters were
  /// rejected before (ParamSet); a radius that leaves C-free empty gives zero cells.
  virtual Decomposed decompose(const Workspace& workspace, const Rational& radius, const ParamSet& params) const = 0;
};

/// The rotation a `direction` parameter asks for: the sweep runs along `degrees` (its lines are
/// perpendicular to it), so the workspace is turned by −degrees; exact (Rotation::nearest).
Rotation sweepRotation(double degrees);

/// The C-space of the rotated workspace and the timings: what a sweep model starts from.
Decomposed prepareFrame(const Workspace& workspace, const Rational& radius, const Rotation& rotation);

}  // namespace coverkit::planners
