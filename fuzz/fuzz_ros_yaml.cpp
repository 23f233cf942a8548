// ROS map_server YAML → readRosMap. The YAML is fuzzed; beside it in the scratch folder lie two
// fixed images it can name, map.pgm and map.png (fuzz_ros_image fuzzes the images).
#include "fuzz_common.h"
#include "ros_images.h"

#include <coverkit/datasets/readers.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool images = [] {
    coverkit::fuzz::writeScratch("map.pgm", coverkit::fuzz::smallMapPgm());
    coverkit::fuzz::writeScratch("map.png", coverkit::fuzz::smallMapPng());
    return true;
  }();
  (void)images;
  const std::string file = coverkit::fuzz::writeScratch("fuzz.yaml", data, size);
  coverkit::datasets::MapOptions options;
  coverkit::fuzz::expectReadOrInputError([&] { coverkit::datasets::readRosMap(file, options); });
  return 0;
}
