#pragma once
// Smooth-STC: V.-H. Pham, T. Moore, T.-T. Truong (Pham, Moore, Truong), "Proposed Smooth-STC
// Algorithm for Enhanced Coverage Path Planning Performance in Mobile Robot Applications",
// Robotics 8(2):44, 2019, doi:10.3390/robotics8020044; sections 4.4-4.5, Algorithms 1 and 2.
// The construction, our reading of the paper and what we added to it are in smooth_stc.cpp and
// docs/smooth-stc.md.
#include <coverkit/planners/stc_skeleton.h>

namespace coverkit::planners {

/// Offline Smooth-STC (Algorithm 1): DFS counter-clockwise tree over the free mega-cells; each
/// partially occupied mega-cell beside the tree is a leaf, swept along the exact C-space contour
/// from the right of its input edge to its left.
class SmoothStcPlanner : public StcSkeleton {
public:
  std::string name() const override { return "smooth_stc"; }
  std::string description() const override;
  std::vector<ParamSpec> params() const override;
  Capabilities capabilities() const override;
  /// `post=fillet` (the default): the fillet processor, its coverage guard on.
  std::vector<std::string> postProcessing(const ParamSet& params) const override;

protected:
  void refinePath(const PlanningContext& context, const std::vector<CellIndex>& walk, const ParamSet& params, Path& path,
                  Plan& plan) const override;
  std::string coverageClaim() const override;
  graph::SpanningTree growTree(const graph::GridGraph& g, int root, const ParamSet& params, int rootFirst) const override;
  bool planWithoutTree(const PlanningContext& context, const ParamSet& params, const Point& start, Plan& plan) const override;
};

/// Online Smooth-STC (Algorithm 2): the Spiral-STC robot (senses the four neighbouring mega-cells,
/// grows the tree counter-clockwise as it goes); when it finds a partially occupied neighbour it
/// sweeps its C-space contour, built from the obstacles near it, before going on.
class SmoothStcOnlinePlanner : public SpiralStcPlanner {
public:
  std::string name() const override { return "smooth_stc_online"; }
  std::string description() const override;
  std::vector<ParamSpec> params() const override;
  Capabilities capabilities() const override;

protected:
  void refinePath(const PlanningContext& context, const std::vector<CellIndex>& walk, const ParamSet& params, Path& path,
                  Plan& plan) const override;
  std::string coverageClaim() const override;
  bool planWithoutTree(const PlanningContext& context, const ParamSet& params, const Point& start, Plan& plan) const override;
};

}  // namespace coverkit::planners
