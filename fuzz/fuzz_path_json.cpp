// coverkit.path/1 JSON file → readPathFile (dispatches on the extension: .json).
#include "fuzz_common.h"

#include <coverkit/datasets/path_io.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string file = coverkit::fuzz::writeScratch("fuzz.json", data, size);
  coverkit::fuzz::expectReadOrInputError([&] { coverkit::datasets::readPathFile(file); });
  return 0;
}
