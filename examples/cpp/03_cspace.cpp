// Example 03: the exact C-space of a disc robot. The C-obstacles are the obstacles grown by the
// disc (segments and circular arcs); C-free is where the robot's centre may be. Components, areas,
// and which component the robot starts in; a picture of both.
//
//   03_cspace DATA_DIR OUT_DIR
#include "render.h"

#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/error.h>

#include <iostream>

using namespace coverkit;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: 03_cspace DATA_DIR OUT_DIR\n";
    return 2;
  }
  const std::string data = argv[1], out = argv[2];
  try {
    const Workspace w = datasets::loadMap(data + "/pillars.wkt");
    const Rational r = parseRational("0.4");
    const CSpace cs(w, r);   // exact: arcs of radius r about every convex corner

    std::cout << "free area " << freeArea(w).get_d() << ", C-free area " << cs.area() << ", " << cs.componentCount()
              << " component(s)\n";
    const std::vector<CurveRegion> components = cs.components(), obstacles = cs.obstacles();
    std::size_t arcs = 0;
    for (const CurveRegion& c : obstacles)
      for (const PathSegment& s : c.outer.pieces) arcs += s.kind == PathSegment::Kind::kArc;
    std::cout << obstacles.size() << " C-obstacle(s) with " << arcs << " arc(s) on their outer boundaries\n";

    // exact questions: is the disc at p free? is the segment a → b clear for it?
    const Point p{1, 1}, q{9, 1};
    std::cout << "start (1, 1) in component " << cs.componentOf(p) << "; segment (1, 1) -> (9, 1) clear: "
              << (cs.segmentClear(p, q) ? "yes" : "no") << "\n";

    experiments::PictureContent picture;
    picture.workspace = &w;
    picture.cfree = &components;
    picture.cobstacles = &obstacles;
    picture.title = "C-space of pillars.wkt, r = 0.4";
    experiments::renderPicture(out + "/03_cspace.png", picture);
    return 0;
  } catch (const InputError& e) {
    std::cerr << "03_cspace: " << e.what() << "\n";
    return 2;
  }
}
