#pragma once
// The built-in decomposition models (registered in registry.cpp).
#include <coverkit/planners/decomposition.h>

namespace coverkit::planners {

/// trapezoidal and boustrophedon: the sweep models, with a `direction`.
class SweepDecomposition : public Decomposition {
public:
  explicit SweepDecomposition(DecompositionRule rule) : rule_(rule) {}
  std::string name() const override;
  std::string description() const override;
  std::vector<ParamSpec> params() const override;
  DecompositionCapabilities capabilities() const override;
  Decomposed decompose(const Workspace& workspace, const Rational& radius, const ParamSet& params) const override;

private:
  DecompositionRule rule_;
};

/// grid: today's mega-cells as cells (C-free ∩ each mega-cell, piece by piece).
class GridDecomposition : public Decomposition {
public:
  std::string name() const override;
  std::string description() const override;
  std::vector<ParamSpec> params() const override;
  DecompositionCapabilities capabilities() const override;
  Decomposed decompose(const Workspace& workspace, const Rational& radius, const ParamSet& params) const override;
};

}  // namespace coverkit::planners
