// coverkit text grid → parseTextGrid (the reader behind readTextGrid, without the file).
#include "fuzz_common.h"

#include <coverkit/datasets/readers.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  coverkit::fuzz::expectReadOrInputError([&] { coverkit::datasets::parseTextGrid(text, "fuzz.grid"); });
  return 0;
}
