// `coverkit demo`. See cmd_demo.h.
#include "cmd_demo.h"

#include "cmd_experiment.h"

namespace coverkit::experiments {

namespace {

struct Options {
  std::string out = "coverkit-demo";
  unsigned jobs = 0;
  bool quiet = false;
};
Options& options() {
  static Options o;
  return o;
}

}  // namespace

CLI::App* addDemoCommand(CLI::App& app) {
  Options& o = options();
  auto* demo = app.add_subcommand("demo", "plan every built-in scenario with every planner, validate, write a report");
  demo->add_option("--out", o.out, "output folder (default: coverkit-demo)");
  demo->add_option("--jobs", o.jobs, "plans run at once; 0, the default: every core")->check(CLI::Range(0u, 1024u));
  demo->add_flag("--quiet", o.quiet, "no summary line");
  return demo;
}

int runDemoCommand(const std::string& commandLine) {
  const Options& o = options();
  return runDemo(o.out, o.jobs, o.quiet, commandLine);
}

}  // namespace coverkit::experiments
