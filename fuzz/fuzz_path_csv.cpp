// Path CSV file (robot,seq,x,y) → readPathFile (dispatches on the extension: .csv).
#include "fuzz_common.h"

#include <coverkit/datasets/path_io.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string file = coverkit::fuzz::writeScratch("fuzz.csv", data, size);
  coverkit::fuzz::expectReadOrInputError([&] { coverkit::datasets::readPathFile(file); });
  return 0;
}
