// Experiment config YAML (experiments/configs/*.yaml) → every kind's reader: the config read and
// checked exactly as `coverkit experiment run` reads it (experimentFromConfig, the kind named in
// the file), and as the sweep and coverage-vs-time kinds read it whatever its `kind:` says; nothing
// run. The config is a file, written to the scratch folder; each check is held to the contract on
// its own. A bsa-backtracking config is read but its kind is not made: making it scans up to
// seeds × size² cells for usable maps (seconds for 10^5 seeds of 1000² cells), which is the
// experiment's work, not the reader's.
#include "fuzz_common.h"

#include "experiment_registry.h"
#include "paper_experiments.h"

#include <yaml-cpp/yaml.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace coverkit::experiments;
  const std::string file = coverkit::fuzz::writeScratch("config.yaml", data, size);
  coverkit::fuzz::expectReadOrInputError([&] { checkSweepConfig(file); });
  coverkit::fuzz::expectReadOrInputError([&] { checkCoverageVsTimeConfig(file); });
  bool bsa = false;
  try {
    const YAML::Node root = YAML::LoadFile(file);
    bsa = root.IsMap() && root["kind"].IsScalar() && root["kind"].Scalar() == "bsa-backtracking";
  } catch (const YAML::Exception&) {
  }
  if (!bsa) coverkit::fuzz::expectReadOrInputError([&] { experimentFromConfig(file); });
  return 0;
}
