// Experiment config YAML (experiments/configs/*.yaml) → checkSweepConfig and
// checkCoverageVsTimeConfig: the config read and checked exactly as `coverkit experiment sweep` and
// `coverage-vs-time` read it, nothing run. The config is a file, written to the scratch folder;
// each check is held to the contract on its own.
#include "fuzz_common.h"

#include "paper_experiments.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string file = coverkit::fuzz::writeScratch("config.yaml", data, size);
  coverkit::fuzz::expectReadOrInputError([&] { coverkit::experiments::checkSweepConfig(file); });
  coverkit::fuzz::expectReadOrInputError([&] { coverkit::experiments::checkCoverageVsTimeConfig(file); });
  return 0;
}
