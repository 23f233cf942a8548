#pragma once
// The experiments' summaries: statistics of a list of values and plain SVG charts (no script, no
// font files: the report and docs/ embed them as they are). Internal to the experiments.
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace coverkit::experiments {

struct Stats {
  double mean = 0, median = 0, min = 0, max = 0;
};
/// Mean, median, min and max of `v` (all 0 when `v` is empty).
Stats stats(std::vector<double> v);

/// `x` with `digits` digits after the point.
std::string fmt(double x, int digits = 2);

/// Grouped histogram panels (one per measure; in each, series name → integer values), one colour per series.
std::string histogramSvg(const std::vector<std::string>& titles, const std::vector<std::map<std::string, std::vector<double>>>& panels);

/// Line chart panels (in each, series name → (x, y) points), one colour per series.
std::string lineChartSvg(const std::vector<std::string>& titles, const std::string& xLabel,
                         const std::vector<std::map<std::string, std::vector<std::pair<double, double>>>>& panels);

}  // namespace coverkit::experiments
