// ROS map_server image → readRosMap with a fixed YAML naming it. Built twice: fuzz_ros_png
// (COVERKIT_FUZZ_IMAGE_EXT=".png") and fuzz_ros_pgm (".pgm").
//
// Input: one byte of options, then the image file's bytes. The options byte picks the YAML
// (bits 0-1: mode trinary / scale / raw / trinary, bit 2: negate, bit 3: MapOptions::unknownIsFree,
// bits 4-5: thresholds: defaults / 0 and 1 / equal / tight), so that every way of reading a pixel
// is reached with the same image.
#include "fuzz_common.h"

#include <coverkit/datasets/readers.h>

#ifndef COVERKIT_FUZZ_IMAGE_EXT
#error "define COVERKIT_FUZZ_IMAGE_EXT (\".png\" or \".pgm\")"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t opt = data[0];
  static const char* const modes[] = {"trinary", "scale", "raw", "trinary"};
  static const char* const thresholds[] = {"occupied_thresh: 0.65\nfree_thresh: 0.196\n", "occupied_thresh: 1\nfree_thresh: 0\n",
                                           "occupied_thresh: 0.5\nfree_thresh: 0.5\n", "occupied_thresh: 0.251\nfree_thresh: 0.25\n"};
  const std::string image = std::string("map") + COVERKIT_FUZZ_IMAGE_EXT;
  coverkit::fuzz::writeScratch(image, data + 1, size - 1);
  const std::string yaml = "image: " + image + "\nresolution: 0.05\norigin: [-1.0, -0.5, 0.0]\nnegate: " + ((opt & 4) ? "1" : "0") +
                           "\nmode: " + modes[opt & 3] + "\n" + thresholds[(opt >> 4) & 3];
  const std::string file = coverkit::fuzz::writeScratch("map.yaml", yaml);
  coverkit::datasets::MapOptions options;
  options.unknownIsFree = (opt & 8) != 0;
  coverkit::fuzz::expectReadOrInputError([&] { coverkit::datasets::readRosMap(file, options); });
  return 0;
}
