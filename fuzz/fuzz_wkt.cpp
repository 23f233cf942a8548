// WKT POLYGON / MULTIPOLYGON text → parseWkt (the reader behind readWkt, without the file).
#include "fuzz_common.h"

#include <coverkit/datasets/readers.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  coverkit::fuzz::expectReadOrInputError([&] { coverkit::datasets::parseWkt(text, "fuzz.wkt"); });
  return 0;
}
