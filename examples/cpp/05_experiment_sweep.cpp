// Example 05: a small experiment. Planners × robot radii × maps, every plan validated, one CSV row
// per run, and a chart of coverage against radius drawn as an SVG by hand (a few lines). The full
// engine is `coverkit experiment` (docs/experiments.md); this is what it does at its core.
//
//   05_experiment_sweep DATA_DIR OUT_DIR
#include "runner.h"

#include <coverkit/datasets/readers.h>
#include <coverkit/planners/registry.h>

#include <fstream>
#include <iostream>
#include <map>
#include <vector>

using namespace coverkit;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: 05_experiment_sweep DATA_DIR OUT_DIR\n";
    return 2;
  }
  const std::string data = argv[1], out = argv[2];
  const std::vector<std::string> maps{"rooms.grid", "pillars.wkt"}, planners{"stc", "full_stc", "boustrophedon"};
  const std::vector<std::string> radii{"0.125", "0.25", "0.375"};
  std::ofstream csv(out + "/05_sweep.csv");
  csv << "map,planner,radius,status,valid,coverable_coverage,length,turns,seconds\n";
  std::map<std::string, std::vector<std::pair<double, double>>> series;   // planner → (r, mean coverage over maps)
  int invalid = 0;
  try {
    for (const std::string& planner : planners)
      for (const std::string& r : radii) {
        double sum = 0;
        for (const std::string& map : maps) {
          Problem problem;
          problem.workspace = datasets::loadMap(data + "/" + map);
          problem.robots.push_back({parseRational(r), std::nullopt});
          const planners::PlanningContext context = planners::makeContext(problem);
          const experiments::RunResult run = experiments::runOnce(context, planner, {});
          invalid += succeeded(run.plan.status) && !run.validation.valid;
          csv << map << ',' << planner << ',' << r << ',' << toString(run.plan.status) << ',' << run.validation.valid << ','
              << run.metrics.coverableCoverage << ',' << run.metrics.length << ',' << run.metrics.turns << ',' << run.totalSeconds << '\n';
          sum += run.metrics.coverableCoverage;
        }
        series[planner].push_back({parseRational(r).get_d(), sum / static_cast<double>(maps.size())});
      }
  } catch (const InputError& e) {
    std::cerr << "05_experiment_sweep: " << e.what() << "\n";
    return 2;
  }
  // the chart: coverage (0.5 … 1) against radius (0.1 … 0.4), one polyline per planner
  std::ofstream svg(out + "/05_sweep.svg");
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='420' height='300'><rect width='420' height='300' fill='white'/>\n";
  const char* colours[] = {"#1b6ca8", "#d1495b", "#2e8b57"};
  int k = 0;
  for (const auto& [planner, pts] : series) {
    svg << "<polyline fill='none' stroke='" << colours[k % 3] << "' stroke-width='2' points='";
    for (const auto& [x, y] : pts) svg << 40 + (x - 0.1) / 0.3 * 360 << ',' << 270 - (y - 0.5) / 0.5 * 250 << ' ';
    svg << "'/><text x='50' y='" << 20 + 16 * k << "' fill='" << colours[k % 3] << "'>" << planner << "</text>\n";
    ++k;
  }
  svg << "<text x='200' y='295'>robot radius</text></svg>\n";
  std::cout << "wrote " << out << "/05_sweep.csv and 05_sweep.svg (" << planners.size() * radii.size() * maps.size() << " runs)\n";
  return invalid == 0 ? 0 : 1;
}
