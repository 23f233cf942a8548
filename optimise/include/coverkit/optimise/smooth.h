#pragma once
// The `smooth` path processor (issue 15): Ceres least squares on a path's waypoints.
//
// Each stretch of a path made of line pieces only (between the path's ends and its arcs, which stay
// as they are) has its inner vertices moved to minimise
//   Σ |q[i−1] − 2 q[i] + q[i+1]|² / r²                     (turning: the second differences)
//   + w_dev Σ |q[i] − q0[i]|² / r²                          (staying where the plan put them)
//   + w_bar Σ max(0, r + margin − d(p, e))² / r²            (a barrier on clearance)
// where p runs over the vertices and the pieces' midpoints and e over the workspace's obstacle
// edges (walls included) near them, solved with SPARSE_NORMAL_CHOLESKY. Decisions:
//  - The soft barrier does not guarantee clearance (../shared/notes/measurements.md: "The soft
//    penalty does not guarantee clearance"): every new piece is checked exactly (the validator's
//    own test, ClearanceChecker). The two vertices of a piece that is not clear stay where they
//    were and the stretch is solved again, the margin doubled.
//  - No vertex moves more than max_move × r (default 0.25): moves are clamped after the solve,
//    then checked like the rest. Coverage is kept as the fillet processor keeps it (fillet.h): with
//    keep_coverage, free points within r of the old pieces of a stretch (sampled at their start,
//    a quarter, half and three quarters, on both sides at (1 − rim)·r and half that, and around
//    their start at (1 − rim)·r) must stay within r of the path; the vertices of a piece whose
//    sweep is not kept stay where they were and the stretch is solved again. After 8 solves, a
//    stretch still not clear or not covered is left as it was (stretches_reverted_clearance,
//    stretches_reverted_coverage).
//  - Total turning must not grow, nor the reversals: a stretch whose turning (its inner joints and
//    its two ends) grows, or that turns by more than 150° at more joints, is left as it was
//    (stretches_reverted_turning). Smoothing spreads a corner over the
//    vertices beside it and straightens zigzags; it does not lower the turning of a single corner
//    between fixed neighbours (an arc or a polyline turns by the same net angle).
//  - Vertices where the path reverses (turning by 150° or more) stay: they are lane ends whose
//    sweep the path needs, and no small move smooths a reversal.
//  - The path's start and end stay where they are; so do the joints with arcs.
// Reported: stretches, vertices, iterations (Ceres, summed), cost_before and cost_after (the
// objective summed over the stretches kept), and the three counts of stretches reverted.
#include <coverkit/optimise/processor.h>

namespace coverkit::optimise {

class SmoothProcessor : public PathProcessor {
public:
  std::string name() const override { return "smooth"; }
  std::string description() const override;
  std::vector<planners::ParamSpec> params() const override;
  Plan process(const Problem& problem, const Plan& plan, const planners::ParamSet& params) const override;
};

}  // namespace coverkit::optimise
