#include <coverkit/datasets/generators.h>
#include <coverkit/geometry/error.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace coverkit::datasets {

namespace {
/// Platform-independent uniform double in [0, 1) from a 64-bit engine.
double u01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }
double uniform(std::mt19937_64& rng, double a, double b) { return a + (b - a) * u01(rng); }
Rational lattice(double v) {
  Rational q(mpz_class(static_cast<long>(std::llround(v * 100))), 100);
  q.canonicalize();
  return q;
}
}  // namespace

bool parseObstacleShape(const std::string& s, ObstacleShape& out) {
  if (s == "rectangles" || s == "rectangle") out = ObstacleShape::kRectangle;
  else if (s == "convex") out = ObstacleShape::kConvex;
  else if (s == "nonconvex" || s == "non_convex") out = ObstacleShape::kNonConvex;
  else if (s == "stars" || s == "star") out = ObstacleShape::kStar;
  else if (s == "rotated" || s == "rotated_rectangles") out = ObstacleShape::kRotatedRectangle;
  else if (s == "discs" || s == "disc") out = ObstacleShape::kDisc;
  else if (s == "mixed") out = ObstacleShape::kMixed;
  else return false;
  return true;
}

Workspace generatePolygonWorld(const PolygonWorldSpec& spec) {
  if (spec.width <= 0 || spec.height <= 0 || spec.minSize <= 0 || spec.maxSize < spec.minSize || spec.count < 0)
    throw InputError("generator", "polygon world", "bad specification");
  std::mt19937_64 rng(spec.seed);
  Workspace w;
  w.name = "polygons(seed=" + std::to_string(spec.seed) + ")";
  Region reg;
  reg.outer = {{0, 0}, {spec.width, 0}, {spec.width, spec.height}, {0, spec.height}};
  struct Disc {
    double x, y, r;
  };
  std::vector<Disc> placed;
  const double margin = 0.25;
  for (int k = 0; k < spec.count; ++k) {
    for (int attempt = 0; attempt < 50; ++attempt) {
      const double size = uniform(rng, spec.minSize, spec.maxSize), R = size / 2;
      const double cx = uniform(rng, R + margin, spec.width - R - margin), cy = uniform(rng, R + margin, spec.height - R - margin);
      if (cx - R < margin || cy - R < margin) continue;
      bool clash = false;
      for (const Disc& d : placed) clash = clash || std::hypot(d.x - cx, d.y - cy) < d.r + R + margin;
      if (clash) continue;
      Ring ring;
      const ObstacleShape shape = spec.shape == ObstacleShape::kMixed ? static_cast<ObstacleShape>(rng() % 6) : spec.shape;
      if (shape == ObstacleShape::kRotatedRectangle) {
        const double a = uniform(rng, 0.4, 1.0) * R, b = std::sqrt(std::max(R * R - a * a, 0.04 * R * R));
        const double t = uniform(rng, 0, M_PI), c = std::cos(t), sn = std::sin(t);
        for (auto [u, v] : {std::pair{-a, -b}, std::pair{a, -b}, std::pair{a, b}, std::pair{-a, b}})
          ring.push_back({lattice(cx + u * c - v * sn), lattice(cy + u * sn + v * c)});
        if (signedArea2(ring) == 0) continue;
      } else if (shape == ObstacleShape::kRectangle) {
        const double a = uniform(rng, 0.4, 1.0) * R, b = std::sqrt(std::max(R * R - a * a, 0.04 * R * R));
        ring = {{lattice(cx - a), lattice(cy - b)}, {lattice(cx + a), lattice(cy - b)}, {lattice(cx + a), lattice(cy + b)}, {lattice(cx - a), lattice(cy + b)}};
      } else {
        const int n = shape == ObstacleShape::kStar ? 2 * (4 + static_cast<int>(rng() % 3)) : shape == ObstacleShape::kDisc ? 24 : 5 + static_cast<int>(rng() % 6);
        const double phase = shape == ObstacleShape::kDisc ? uniform(rng, 0, 2 * M_PI / n) : 0;
        std::vector<double> ang;
        for (int i = 0; i < n; ++i)
          ang.push_back(shape == ObstacleShape::kStar ? 2 * M_PI * i / n : shape == ObstacleShape::kDisc ? phase + 2 * M_PI * i / n : uniform(rng, 0, 2 * M_PI));
        std::sort(ang.begin(), ang.end());
        bool crowded = false;  // keep vertices apart so rounding to the lattice cannot fold the ring
        for (int i = 0; i < n; ++i) crowded = crowded || (i + 1 < n ? ang[static_cast<std::size_t>(i) + 1] - ang[static_cast<std::size_t>(i)] : ang[0] + 2 * M_PI - ang.back()) < 0.2;
        if (crowded) continue;
        for (int i = 0; i < n; ++i) {
          double rr = R;
          if (shape == ObstacleShape::kNonConvex) rr = R * uniform(rng, 0.35, 1.0);
          if (shape == ObstacleShape::kStar) rr = (i % 2 == 0) ? R : R * 0.4;
          Point p{lattice(cx + rr * std::cos(ang[static_cast<std::size_t>(i)])), lattice(cy + rr * std::sin(ang[static_cast<std::size_t>(i)]))};
          if (ring.empty() || !(ring.back() == p)) ring.push_back(p);
        }
        if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
        // drop collinear or folded vertices produced by rounding (a convex ring must stay convex)
        if (ring.size() < 3 || signedArea2(ring) == 0) continue;
      }
      try {  // the ring must be simple after rounding
        Workspace probe;
        probe.name = w.name;
        probe.regions.push_back({ring, {}});
        checkWorkspace(probe);
      } catch (const InputError&) {
        continue;
      }
      std::reverse(ring.begin(), ring.end());  // holes clockwise
      reg.holes.push_back(std::move(ring));
      placed.push_back({cx, cy, R});
      break;
    }
  }
  w.regions.push_back(std::move(reg));
  checkWorkspace(w);
  normalise(w);
  return w;
}

OccupancyGrid generateGridMap(const GridMapSpec& spec) {
  if (spec.width <= 0 || spec.height <= 0 || spec.density < 0 || spec.density >= 1)
    throw InputError("generator", "grid map", "bad specification");
  std::mt19937_64 rng(spec.seed);
  OccupancyGrid g;
  g.width = spec.width;
  g.height = spec.height;
  g.resolution = spec.resolution;
  g.blocked.assign(static_cast<std::size_t>(g.width) * g.height, 0);
  const std::size_t n = g.blocked.size();
  const auto target = static_cast<std::size_t>(spec.density * static_cast<double>(n));
  std::size_t count = 0;
  if (!spec.clustered) {
    for (std::size_t i = 0; i < n; ++i)
      if (u01(rng) < spec.density) { g.blocked[i] = 1; ++count; }
    return g;
  }
  while (count < target) {
    int c = static_cast<int>(rng() % static_cast<unsigned>(g.width)), r = static_cast<int>(rng() % static_cast<unsigned>(g.height));
    const int blob = 4 + static_cast<int>(rng() % 16);
    for (int k = 0; k < blob && count < target; ++k) {
      std::size_t i = static_cast<std::size_t>(r) * g.width + c;
      if (!g.blocked[i]) { g.blocked[i] = 1; ++count; }
      switch (rng() % 4) {
        case 0: c = std::min(c + 1, g.width - 1); break;
        case 1: c = std::max(c - 1, 0); break;
        case 2: r = std::min(r + 1, g.height - 1); break;
        default: r = std::max(r - 1, 0); break;
      }
    }
  }
  return g;
}

}  // namespace coverkit::datasets
