#pragma once
// Small fixed images for the ROS map targets: a 6×5 map with a wall, a free area and unknown
// pixels, as 8-bit PGM and 8-bit grey PNG (made with libpng, nothing read from disk).
#include <png.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace coverkit::fuzz {

inline std::vector<std::uint8_t> smallMapPixels() {
  // 254 free, 0 occupied, 205 unknown (map_server's colours)
  return {0, 0,   0,   0,   0,   0,
          0, 254, 254, 254, 205, 0,
          0, 254, 0,   254, 254, 0,
          0, 254, 254, 254, 254, 0,
          0, 0,   0,   0,   0,   0};
}

inline std::string smallMapPgm() {
  const std::vector<std::uint8_t> px = smallMapPixels();
  std::string s = "P5\n6 5\n255\n";
  s.append(px.begin(), px.end());
  return s;
}

inline std::string smallMapPng() {
  std::vector<std::uint8_t> px = smallMapPixels();
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  img.width = 6;
  img.height = 5;
  img.format = PNG_FORMAT_GRAY;
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&img, nullptr, &size, 0, px.data(), 0, nullptr)) std::abort();
  std::string out(size, '\0');
  if (!png_image_write_to_memory(&img, out.data(), &size, 0, px.data(), 0, nullptr)) std::abort();
  out.resize(size);
  return out;
}

}  // namespace coverkit::fuzz
