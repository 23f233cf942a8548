// Scenario YAML (coverkit.scenario/1, moving obstacles) → parseScenario (the reader behind
// readScenario, without the file).
#include "fuzz_common.h"

#include <coverkit/datasets/scenario.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  coverkit::fuzz::expectReadOrInputError([&] { coverkit::datasets::parseScenario(text, "fuzz.yaml"); });
  return 0;
}
