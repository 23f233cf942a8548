// Statistics and SVG charts of the experiments' summaries. See charts.h.
#include "charts.h"

#include <algorithm>
#include <iomanip>
#include <numeric>
#include <sstream>

namespace coverkit::experiments {

Stats stats(std::vector<double> v) {
  Stats s;
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.mean = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
  s.median = v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
  s.min = v.front();
  s.max = v.back();
  return s;
}

std::string fmt(double x, int digits) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(digits) << x;
  return os.str();
}

std::string histogramSvg(const std::vector<std::string>& titles, const std::vector<std::map<std::string, std::vector<double>>>& panels) {
  const int pw = 420, ph = 300, ml = 50, mb = 45, mt = 30;
  std::ostringstream svg;
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << pw * panels.size() << "' height='" << ph
      << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n";
  const char* colours[2] = {"#d95f02", "#1b9e77"};
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const int x0 = static_cast<int>(p) * pw + ml, y0 = ph - mb, w = pw - ml - 15, h = ph - mb - mt;
    int maxValue = 0;
    std::size_t maxCount = 1;
    std::vector<std::map<int, std::size_t>> counts;
    for (const auto& [name, values] : panels[p]) {
      std::map<int, std::size_t> c;
      for (double v : values) maxValue = std::max(maxValue, static_cast<int>(v)), ++c[static_cast<int>(v)];
      for (const auto& [k, n] : c) maxCount = std::max(maxCount, n);
      counts.push_back(c);
    }
    const double bw = static_cast<double>(w) / (maxValue + 1);
    svg << "<text x='" << x0 + w / 2 << "' y='18' text-anchor='middle'>" << titles[p] << "</text>\n";
    svg << "<line x1='" << x0 << "' y1='" << y0 << "' x2='" << x0 + w << "' y2='" << y0 << "' stroke='black'/>\n";
    svg << "<line x1='" << x0 << "' y1='" << y0 << "' x2='" << x0 << "' y2='" << y0 - h << "' stroke='black'/>\n";
    for (int k = 0; k <= maxValue; k += std::max(1, (maxValue + 1) / 10))
      svg << "<text x='" << x0 + (k + 0.5) * bw << "' y='" << y0 + 15 << "' text-anchor='middle'>" << k << "</text>\n";
    for (std::size_t k = 0; k <= maxCount; k += std::max<std::size_t>(1, maxCount / 5))
      svg << "<text x='" << x0 - 5 << "' y='" << y0 - static_cast<double>(k) / maxCount * h + 4 << "' text-anchor='end'>" << k << "</text>\n";
    svg << "<text x='" << x0 + w / 2 << "' y='" << ph - 8 << "' text-anchor='middle'>value per map</text>\n";
    svg << "<text x='14' y='" << y0 - h / 2 << "' transform='rotate(-90 14 " << y0 - h / 2 << ")' text-anchor='middle'>maps</text>\n";
    std::size_t series = 0;
    for (const auto& [name, values] : panels[p]) {
      for (const auto& [k, n] : counts[series]) {
        const double bh = static_cast<double>(n) / maxCount * h;
        svg << "<rect x='" << x0 + k * bw + series * bw / 2 << "' y='" << y0 - bh << "' width='" << bw / 2 - 1 << "' height='" << bh
            << "' fill='" << colours[series % 2] << "'/>\n";
      }
      svg << "<rect x='" << x0 + w - 110 << "' y='" << mt + 16 * series << "' width='10' height='10' fill='" << colours[series % 2] << "'/>";
      svg << "<text x='" << x0 + w - 95 << "' y='" << mt + 9 + 16 * series << "'>" << name << "</text>\n";
      ++series;
    }
  }
  svg << "</svg>\n";
  return svg.str();
}

std::string lineChartSvg(const std::vector<std::string>& titles, const std::string& xLabel,
                         const std::vector<std::map<std::string, std::vector<std::pair<double, double>>>>& panels) {
  const int pw = 440, ph = 320, ml = 55, mb = 45, mt = 30;
  const char* colours[6] = {"#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e", "#e6ab02"};
  std::ostringstream svg;
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << pw * panels.size() << "' height='" << ph
      << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n";
  for (std::size_t p = 0; p < panels.size(); ++p) {
    double x0v = 1e300, x1v = -1e300, y0v = 1e300, y1v = -1e300;
    for (const auto& [name, pts] : panels[p])
      for (auto [x, y] : pts) x0v = std::min(x0v, x), x1v = std::max(x1v, x), y0v = std::min(y0v, y), y1v = std::max(y1v, y);
    if (x1v <= x0v) x1v = x0v + 1;
    if (y1v <= y0v) y1v = y0v + 1e-3;
    const double pad = 0.05 * (y1v - y0v);
    y0v -= pad;
    y1v += pad;
    const int X = static_cast<int>(p) * pw + ml, Y = ph - mb, W = pw - ml - 20, H = ph - mb - mt;
    auto sx = [&](double x) { return X + (x - x0v) / (x1v - x0v) * W; };
    auto sy = [&](double y) { return Y - (y - y0v) / (y1v - y0v) * H; };
    svg << "<text x='" << X + W / 2 << "' y='18' text-anchor='middle'>" << titles[p] << "</text>\n";
    svg << "<rect x='" << X << "' y='" << Y - H << "' width='" << W << "' height='" << H << "' fill='none' stroke='black'/>\n";
    for (int k = 0; k <= 4; ++k) {
      const double yv = y0v + (y1v - y0v) * k / 4, xv = x0v + (x1v - x0v) * k / 4;
      svg << "<text x='" << X - 5 << "' y='" << sy(yv) + 4 << "' text-anchor='end'>" << fmt(yv, 3) << "</text>\n";
      svg << "<text x='" << sx(xv) << "' y='" << Y + 15 << "' text-anchor='middle'>" << fmt(xv, 2) << "</text>\n";
    }
    svg << "<text x='" << X + W / 2 << "' y='" << ph - 8 << "' text-anchor='middle'>" << xLabel << "</text>\n";
    std::size_t series = 0;
    for (const auto& [name, pts] : panels[p]) {
      const char* colour = colours[series % 6];
      svg << "<polyline fill='none' stroke='" << colour << "' stroke-width='2' points='";
      for (auto [x, y] : pts) svg << sx(x) << ',' << sy(y) << ' ';
      svg << "'/>\n";
      for (auto [x, y] : pts) svg << "<circle cx='" << sx(x) << "' cy='" << sy(y) << "' r='3' fill='" << colour << "'/>\n";
      svg << "<text x='" << X + 8 << "' y='" << Y - H + 16 + 15 * series << "' fill='" << colour << "'>" << name << "</text>\n";
      ++series;
    }
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace coverkit::experiments
