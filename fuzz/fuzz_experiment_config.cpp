// Experiment config YAML (experiments/configs/*.yaml) → the loader shared by `coverkit experiment
// sweep` and `coverage-vs-time` (planners, planner parameters, worlds), as the CLI runs it: the
// config is a file, written to the scratch folder.
//
// The loader is internal to paper_experiments.cpp and runSweep / runCoverageVsTime go on to run
// the whole experiment, far too slow for fuzzing; so the file is compiled into this target and the
// loader called directly. A public loader would make this include unnecessary.
#include "fuzz_common.h"

#include "../experiments/src/paper_experiments.cpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string file = coverkit::fuzz::writeScratch("config.yaml", data, size);
  coverkit::fuzz::expectReadOrInputError([&] { coverkit::experiments::loadExperimentConfig(file, 10); });
  return 0;
}
