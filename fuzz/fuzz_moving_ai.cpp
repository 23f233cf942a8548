// Moving AI .map file → readMovingAi (path-taking only: the input is written to a scratch file).
#include "fuzz_common.h"

#include <coverkit/datasets/readers.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string file = coverkit::fuzz::writeScratch("fuzz.map", data, size);
  coverkit::fuzz::expectReadOrInputError([&] { coverkit::datasets::readMovingAi(file); });
  return 0;
}
