#pragma once
// Small hand-made workspaces shared by the geometry tests (header-only: the assertion-checked test
// binary links the geometry library alone).
#include <coverkit/geometry/types.h>

#include <vector>

namespace coverkit::testing_helpers {

/// The box [0, w] × [0, h] with the given obstacles as holes, normalised.
inline Workspace boxWith(const std::vector<Ring>& holes, int w = 10, int h = 10) {
  Workspace ws;
  ws.name = "box";
  Region r;
  r.outer = {{0, 0}, {w, 0}, {w, h}, {0, h}};
  r.holes = holes;
  ws.regions.push_back(r);
  normalise(ws);
  return ws;
}

}  // namespace coverkit::testing_helpers
