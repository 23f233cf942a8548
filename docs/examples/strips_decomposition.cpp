// A decomposition of one's own, written against coverkit's public API only
// (docs/adding-a-decomposition.md): vertical strips of a given width; each connected piece of
// C-free inside a strip is a cell. The tests compile this file, register the model and hold it to
// the contract every decomposition keeps.
#include <coverkit/geometry/decomposition.h>
#include <coverkit/planners/decomposition.h>
#include <coverkit/planners/registry.h>

#include <memory>

namespace example {

using namespace coverkit;

class StripsDecomposition : public planners::Decomposition {
public:
  std::string name() const override { return "strips"; }
  std::string description() const override {
    return "vertical strips of width `width` (default 4r) from the workspace's left edge; each piece of C-free in a strip is a cell";
  }
  std::vector<planners::ParamSpec> params() const override {
    return {{"width", planners::ParamType::kDouble, "0", "0:1e6", "strip width in map units (0: 4r)"}};
  }
  planners::DecompositionCapabilities capabilities() const override {
    return {false, false};   // a strip's piece may hold an obstacle: not monotone; no direction
  }
  planners::Decomposed decompose(const Workspace& w, const Rational& r, const planners::ParamSet& params) const override {
    planners::Decomposed d = planners::prepareFrame(w, r, Rotation{});   // the exact C-free, not rotated
    const Rational width = params.number("width") > 0 ? exactFromDouble(params.number("width")) : Rational(4 * r);
    const Box b = w.bbox();
    std::vector<Rational> xs;   // exact cutting lines: cells stay exact regions
    for (Rational x = b.xmin + width; x < b.xmax; x += width) xs.push_back(x);
    d.cells = decomposeAlongLines(*d.space, xs, {}, name());
    return d;
  }
};

/// The one registration line (a built-in model has it in planners/src/registry.cpp).
void registerStrips() {
  planners::DecompositionRegistry::instance().add("strips", [] { return std::make_unique<StripsDecomposition>(); });
}

}  // namespace example
