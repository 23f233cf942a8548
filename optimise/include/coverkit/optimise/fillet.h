#pragma once
// The `fillet` path processor (issue 15).
//
// Every corner of a path (a joint where the heading turns by more than 1° and less than 179°,
// between two lines, a line and an arc, or two arcs) becomes the largest tangent circular arc of radius at
// most max_radius × r that keeps exact clearance and, with keep_coverage (the default), the
// coverage: the arc and the two shortened pieces are checked exactly (ClearanceChecker, the
// validator's own test) and written as exact arcs. Decisions:
//  - Any fillet gives up part of what the corner swept: the disc at the corner reaches r beyond
//    it, the disc on the arc ρ(1/cos(θ/2) − 1) less far (θ the turn). Unguarded, fillets of
//    0.25 r lost up to 1.1 percentage points of the coverable region on the contract worlds. So
//    the guard: free points within r of the parts cut off must stay within r of the new pieces or
//    of the rest of the path, but for an outer rim of width rim × r (default 0.04); sampled
//    around the corner (24 directions at 1/3, 2/3 and all of (1 − rim)·r) and beside the cut-off
//    parts, free space read from the workspace's sub-cells of r/2 (at least 1/4096 of the map's
//    extent; a partial sub-cell counts as free). A corner that nothing else sweeps gets a fillet
//    of about rim·r/(1/cos(θ/2) − 1) (0.1 r at 90°); one whose sweep the path repeats nearby gets
//    up to max_radius × r. Coverage is measured, not decided, here (doubles); clearance is decided
//    exactly.
//  - max_radius is in robot radii, so one value suits every map; default 1.
//  - "Largest": halving from max_radius until an arc is clear and kept (at most 10 times), then 5
//    steps of bisection between it and the radius above.
//  - A piece gives at most half its length to each of its two ends, so fillets never overlap.
//  - Corners between two arcs are rounded too (they were left before): on a grid map the C-space
//    contour is a scallop of arcs about the pixel corners meeting in notches, and those notches
//    were every turn Smooth-STC had left on ros/turtlebot3_world.yaml (146 at r = 0.25, 0 after).
//    The guard reads the cut-off part of an arc along the arc. Reversals (179° and more) stay.
// Where a line meets a line, total turning is unchanged (the arc turns by the corner's angle).
// At a notch between two arcs that turn the other way, it falls: the fillet shortens them (on
// turtlebot3_world at r = 0.25 Smooth-STC's total turning goes from 15,072° to 12,746°). Turns
// fall, and so does the robot time (metrics.h) where the arcs are wide enough to drive fast.
#include <coverkit/optimise/processor.h>

namespace coverkit::optimise {

class FilletProcessor : public PathProcessor {
public:
  std::string name() const override { return "fillet"; }
  std::string description() const override;
  std::vector<planners::ParamSpec> params() const override;
  Plan process(const Problem& problem, const Plan& plan, const planners::ParamSet& params) const override;
};

}  // namespace coverkit::optimise
