// ROS map images read as map_server reads them (docs/formats.md, "ROS map images"): every PNG flavour
// (grey 1/2/4/8/16 bits, grey+alpha, RGB, RGBA, palette with and without tRNS, tRNS on grey and RGB,
// Adam7) and PGM P2/P5 up to maxval 65535, written here with libpng's writer and by hand, compared
// pixel by pixel with a reference decode computed in this file from the samples written, in every
// mode, with and without negate and --unknown-free. Then the limits (memory before checks).
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/error.h>

#include <gtest/gtest.h>
#include <png.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

using namespace coverkit;
namespace fs = std::filesystem;

namespace {

fs::path dir() {
  fs::path d = fs::path(COVERKIT_TEST_TMP) / "map_images";
  fs::create_directories(d);
  return d;
}
std::string put(const std::string& name, const std::string& content) {
  const fs::path p = dir() / name;
  std::ofstream(p, std::ios::binary) << content;
  return p.string();
}
template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// ------------------------------------------------------------------ writing PNGs with libpng
struct PngSpec {
  int width = 0, height = 0;
  int colourType = PNG_COLOR_TYPE_GRAY;
  int depth = 8;
  bool adam7 = false;
  /// Samples as stored in the file, per pixel per channel (G, GA, RGB, RGBA, or a palette index).
  std::vector<unsigned> samples;
  std::vector<png_color> palette;
  std::vector<png_byte> paletteAlpha;  ///< tRNS of a palette image (may be shorter than the palette)
  bool trnsColour = false;             ///< tRNS of a grey or RGB image: this colour is transparent
  png_color_16 trns{};
};

int fileChannels(int colourType) {
  switch (colourType) {
    case PNG_COLOR_TYPE_GRAY: return 1;
    case PNG_COLOR_TYPE_GRAY_ALPHA: return 2;
    case PNG_COLOR_TYPE_RGB: return 3;
    case PNG_COLOR_TYPE_RGB_ALPHA: return 4;
    default: return 1;  // palette
  }
}

void writePng(const std::string& path, const PngSpec& s) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
    FAIL() << "libpng could not write " << path;
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, static_cast<png_uint_32>(s.width), static_cast<png_uint_32>(s.height), s.depth, s.colourType,
               s.adam7 ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (!s.palette.empty()) png_set_PLTE(png, info, s.palette.data(), static_cast<int>(s.palette.size()));
  if (!s.paletteAlpha.empty()) png_set_tRNS(png, info, s.paletteAlpha.data(), static_cast<int>(s.paletteAlpha.size()), nullptr);
  if (s.trnsColour) png_set_tRNS(png, info, nullptr, 0, &s.trns);
  png_set_gAMA(png, info, 1.0 / 2.2);  // a gamma chunk that the reader must ignore
  png_write_info(png, info);
  const int ch = fileChannels(s.colourType);
  const std::size_t rowBytes = (static_cast<std::size_t>(s.width) * ch * s.depth + 7) / 8;
  std::vector<std::vector<png_byte>> rows(static_cast<std::size_t>(s.height), std::vector<png_byte>(rowBytes, 0));
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      for (int c = 0; c < ch; ++c) {
        const unsigned v = s.samples[(static_cast<std::size_t>(y) * s.width + x) * ch + c];
        const std::size_t bit = (static_cast<std::size_t>(x) * ch + c) * s.depth;
        auto& row = rows[static_cast<std::size_t>(y)];
        if (s.depth == 16) {
          row[bit / 8] = static_cast<png_byte>(v >> 8);
          row[bit / 8 + 1] = static_cast<png_byte>(v & 255);
        } else {  // 1..8 bits, most significant first
          row[bit / 8] |= static_cast<png_byte>(v << (8 - s.depth - bit % 8));
        }
      }
  std::vector<png_bytep> pointers;
  for (auto& r : rows) pointers.push_back(r.data());
  png_write_image(png, pointers.data());  // handles the Adam7 passes
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  std::fclose(f);
}

// ------------------------------------------------------------------ the reference decode
enum class Mode { kTrinary, kScale, kRaw };
struct Rules {
  Mode mode = Mode::kTrinary;
  bool negate = false;
  bool unknownFree = false;
  Rational occupied = ratio(65, 100), free = ratio(196, 1000);
  const char* name() const { return mode == Mode::kTrinary ? "trinary" : mode == Mode::kScale ? "scale" : "raw"; }
};

/// A pixel as the rules see it: colour samples (1 or 3) and alpha, on 0..maxval.
struct Pixel {
  std::vector<unsigned> colour;
  unsigned alpha;
  unsigned maxval;
};

/// docs/formats.md, written out directly (no table): shade = mean of the colour channels.
bool expectedBlocked(const Pixel& px, const Rules& r) {
  long sum = 0;
  for (unsigned c : px.colour) sum += c;
  const long D = static_cast<long>(px.colour.size()) * px.maxval;
  if (px.alpha == 0) return !r.unknownFree;
  if (r.mode == Mode::kScale && px.alpha != px.maxval) return !r.unknownFree;
  if (r.mode == Mode::kRaw) {
    const long s = r.negate ? D - sum : sum;       // s/D
    const long value = (2 * 255 * s + D) / (2 * D);  // round half up
    if (value > 100) return !r.unknownFree;
    const Rational v = ratio(value, 100);
    if (v > r.occupied) return true;
    if (v < r.free) return false;
    return true;  // partially occupied
  }
  const Rational p = r.negate ? ratio(sum, D) : ratio(D - sum, D);
  if (p > r.occupied) return true;
  if (p < r.free) return false;
  return r.mode == Mode::kTrinary ? !r.unknownFree : true;
}

/// The file's samples of pixel k turned into colour + alpha, independently of the reader.
Pixel pixelOf(const PngSpec& s, std::size_t k) {
  const int ch = fileChannels(s.colourType);
  const unsigned* v = &s.samples[k * ch];
  const unsigned maxval = s.colourType == PNG_COLOR_TYPE_PALETTE ? 255 : (1u << s.depth) - 1;
  Pixel p{{}, maxval, maxval};
  switch (s.colourType) {
    case PNG_COLOR_TYPE_PALETTE: {
      const png_color c = s.palette[v[0]];
      p.colour = {c.red, c.green, c.blue};
      p.alpha = v[0] < s.paletteAlpha.size() ? s.paletteAlpha[v[0]] : 255;
      break;
    }
    case PNG_COLOR_TYPE_GRAY:
      p.colour = {v[0]};
      if (s.trnsColour && v[0] == s.trns.gray) p.alpha = 0;
      break;
    case PNG_COLOR_TYPE_GRAY_ALPHA: p.colour = {v[0]}; p.alpha = v[1]; break;
    case PNG_COLOR_TYPE_RGB:
      p.colour = {v[0], v[1], v[2]};
      if (s.trnsColour && v[0] == s.trns.red && v[1] == s.trns.green && v[2] == s.trns.blue) p.alpha = 0;
      break;
    default: p.colour = {v[0], v[1], v[2]}; p.alpha = v[3]; break;
  }
  return p;
}

std::string yamlFor(const std::string& stem, const std::string& image, const Rules& r) {
  std::ostringstream y;
  y << "image: " << image << "\nresolution: 1\norigin: [0, 0, 0]\nnegate: " << (r.negate ? 1 : 0) << "\noccupied_thresh: 0.65\nfree_thresh: 0.196\nmode: "
    << r.name() << "\n";
  return put(stem + ".yaml", y.str());
}

std::vector<Rules> allRules() {
  std::vector<Rules> out;
  for (Mode m : {Mode::kTrinary, Mode::kScale, Mode::kRaw})
    for (bool negate : {false, true})
      for (bool unknownFree : {false, true}) {
        Rules r;
        r.mode = m;
        r.negate = negate;
        r.unknownFree = unknownFree;
        out.push_back(r);
      }
  return out;
}

/// Reads `image` under every rule set and compares each pixel with the reference.
template <class PixelAt>
void compareAll(const std::string& stem, const std::string& image, int width, int height, PixelAt pixelAt) {
  for (const Rules& r : allRules()) {
    datasets::MapOptions o;
    o.unknownIsFree = r.unknownFree;
    const datasets::OccupancyGrid g = datasets::readRosGrid(yamlFor(stem, image, r), o);
    ASSERT_EQ(g.width, width);
    ASSERT_EQ(g.height, height);
    int wrong = 0;
    for (int i = 0; i < height && wrong < 5; ++i)
      for (int j = 0; j < width && wrong < 5; ++j) {
        const Pixel px = pixelAt(static_cast<std::size_t>(i) * width + j);
        const bool want = expectedBlocked(px, r);
        if (g.at(j, height - 1 - i) != want) {
          ++wrong;
          std::ostringstream c;
          for (unsigned v : px.colour) c << v << ' ';
          ADD_FAILURE() << stem << " mode " << r.name() << " negate " << r.negate << " unknown-free " << r.unknownFree << ": pixel (row " << i
                        << ", column " << j << ") colour " << c.str() << "alpha " << px.alpha << "/" << px.maxval << ": expected "
                        << (want ? "blocked" : "free");
        }
      }
  }
}

/// Sample values: the extremes, values on and around the thresholds of every rule, random others.
std::vector<unsigned> interestingValues(unsigned maxval, std::mt19937_64& rng, std::size_t count) {
  std::vector<unsigned> v = {0, maxval, maxval / 2};
  for (double t : {0.35, 0.804, 0.65, 0.196, 100.0 / 255, 65.0 / 255, 19.6 / 255, 0.25, 0.75}) {
    const long c = std::lround(t * maxval);
    for (long d = -2; d <= 2; ++d)
      if (c + d >= 0 && c + d <= static_cast<long>(maxval)) v.push_back(static_cast<unsigned>(c + d));
  }
  while (v.size() < count) v.push_back(static_cast<unsigned>(rng() % (maxval + 1)));
  std::shuffle(v.begin(), v.end(), rng);
  return v;
}

struct Flavour {
  std::string name;
  int colourType, depth;
  bool trns;  // palette tRNS, or a transparent grey/RGB colour
};

}  // namespace

// Every PNG flavour, plain and Adam7, in every mode, against the reference decode.
TEST(MapImages, EveryPngFlavourReadsAsTheReference) {
  const std::vector<Flavour> flavours = {
      {"grey1", PNG_COLOR_TYPE_GRAY, 1, false},       {"grey2", PNG_COLOR_TYPE_GRAY, 2, false},
      {"grey4", PNG_COLOR_TYPE_GRAY, 4, false},       {"grey8", PNG_COLOR_TYPE_GRAY, 8, false},
      {"grey16", PNG_COLOR_TYPE_GRAY, 16, false},     {"grey2_trns", PNG_COLOR_TYPE_GRAY, 2, true},
      {"grey8_trns", PNG_COLOR_TYPE_GRAY, 8, true},   {"grey16_trns", PNG_COLOR_TYPE_GRAY, 16, true},
      {"ga8", PNG_COLOR_TYPE_GRAY_ALPHA, 8, false},   {"ga16", PNG_COLOR_TYPE_GRAY_ALPHA, 16, false},
      {"rgb8", PNG_COLOR_TYPE_RGB, 8, false},         {"rgb16", PNG_COLOR_TYPE_RGB, 16, false},
      {"rgb8_trns", PNG_COLOR_TYPE_RGB, 8, true},     {"rgb16_trns", PNG_COLOR_TYPE_RGB, 16, true},
      {"rgba8", PNG_COLOR_TYPE_RGB_ALPHA, 8, false},  {"rgba16", PNG_COLOR_TYPE_RGB_ALPHA, 16, false},
      {"pal1", PNG_COLOR_TYPE_PALETTE, 1, false},     {"pal2", PNG_COLOR_TYPE_PALETTE, 2, false},
      {"pal4", PNG_COLOR_TYPE_PALETTE, 4, false},     {"pal8", PNG_COLOR_TYPE_PALETTE, 8, false},
      {"pal2_trns", PNG_COLOR_TYPE_PALETTE, 2, true}, {"pal8_trns", PNG_COLOR_TYPE_PALETTE, 8, true},
  };
  std::mt19937_64 rng(12);
  for (const Flavour& fl : flavours)
    for (bool adam7 : {false, true})
      for (auto [w, h] : {std::pair{13, 11}, std::pair{1, 1}, std::pair{3, 2}, std::pair{9, 17}}) {
        PngSpec s;
        s.width = w;
        s.height = h;
        s.colourType = fl.colourType;
        s.depth = fl.depth;
        s.adam7 = adam7;
        const int ch = fileChannels(fl.colourType);
        const std::size_t n = static_cast<std::size_t>(w) * h;
        const unsigned maxval = (1u << fl.depth) - 1;
        if (fl.colourType == PNG_COLOR_TYPE_PALETTE) {
          const std::size_t entries = std::size_t{1} << fl.depth;
          const std::vector<unsigned> c = interestingValues(255, rng, 3 * entries);
          for (std::size_t e = 0; e < entries; ++e)
            s.palette.push_back({static_cast<png_byte>(c[3 * e]), static_cast<png_byte>(c[3 * e + 1]), static_cast<png_byte>(c[3 * e + 2])});
          s.palette[0] = {205, 205, 205};  // unknown grey, opaque
          if (fl.trns) {
            for (std::size_t e = 0; e + 1 < entries; ++e) s.paletteAlpha.push_back(static_cast<png_byte>(e % 3 == 0 ? 0 : e % 3 == 1 ? 255 : 128));
            if (s.paletteAlpha.size() > 1) s.paletteAlpha[0] = 255;
          }
          for (std::size_t k = 0; k < n; ++k) s.samples.push_back(static_cast<unsigned>(rng() % entries));
        } else {
          const bool alphaChannel = (fl.colourType & PNG_COLOR_MASK_ALPHA) != 0;
          const int colourCh = alphaChannel ? ch - 1 : ch;
          const std::vector<unsigned> values = interestingValues(maxval, rng, n * colourCh);
          for (std::size_t k = 0; k < n; ++k) {
            // mostly grey pixels (the case of floor plans), some of unequal channels
            const bool grey = rng() % 3 != 0;
            for (int c = 0; c < colourCh; ++c) s.samples.push_back(values[k * colourCh + (grey ? 0 : c)]);
            if (alphaChannel) {
              const unsigned a[4] = {0, maxval, maxval, static_cast<unsigned>(rng() % (maxval + 1))};
              s.samples.push_back(a[rng() % 4]);
            }
          }
          if (fl.trns) {
            s.trnsColour = true;
            const unsigned* first = &s.samples[0];
            s.trns.gray = static_cast<png_uint_16>(first[0]);
            if (colourCh == 3) s.trns = png_color_16{0, static_cast<png_uint_16>(first[0]), static_cast<png_uint_16>(first[1]), static_cast<png_uint_16>(first[2]), 0};
          }
        }
        const std::string stem = fl.name + (adam7 ? "_adam7_" : "_") + std::to_string(w) + "x" + std::to_string(h);
        writePng((dir() / (stem + ".png")).string(), s);
        compareAll(stem, stem + ".png", w, h, [&](std::size_t k) { return pixelOf(s, k); });
      }
}

// The issue's image: 5×5 16-bit RGBA, white and opaque but for one grey 49151/65535 pixel
// (p = 0.25: unknown, hence an obstacle): 24 free pixels, as in 8 bits, not 25.
TEST(MapImages, SixteenBitGreyIsNotGammaConverted) {
  for (int depth : {16, 8}) {
    PngSpec s;
    s.width = s.height = 5;
    s.colourType = PNG_COLOR_TYPE_RGB_ALPHA;
    s.depth = depth;
    const unsigned white = depth == 16 ? 65535 : 255, grey = depth == 16 ? 49151 : 191;
    for (int k = 0; k < 25; ++k)
      for (int c = 0; c < 4; ++c) s.samples.push_back(k == 12 && c < 3 ? grey : white);
    const std::string name = "issue_rgba" + std::to_string(depth);
    writePng((dir() / (name + ".png")).string(), s);
    const std::string yaml = put(name + ".yaml", "image: " + name + ".png\nresolution: 1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
    EXPECT_EQ(freeArea(datasets::readRosMap(yaml)), Rational(24)) << depth << "-bit";
    datasets::MapOptions o;
    o.unknownIsFree = true;
    EXPECT_EQ(freeArea(datasets::readRosMap(yaml, o)), Rational(25)) << depth << "-bit";
  }
}

// Deviation from map_server, for safety: alpha is not averaged into the colour in trinary mode. An
// opaque grey 205 (p = 0.196..., unknown) would read (3·205 + 255)/4 = 217.5 there: free.
TEST(MapImages, OpaqueAlphaDoesNotMakeUnknownFree) {
  PngSpec s;
  s.width = 2;
  s.height = 1;
  s.colourType = PNG_COLOR_TYPE_RGB_ALPHA;
  s.samples = {205, 205, 205, 255, 254, 254, 254, 255};
  writePng((dir() / "alpha205.png").string(), s);
  const datasets::OccupancyGrid g = datasets::readRosGrid(put("alpha205.yaml", "image: alpha205.png\nresolution: 1\norigin: [0, 0, 0]\n"));
  EXPECT_TRUE(g.at(0, 0));
  EXPECT_FALSE(g.at(1, 0));
}

// Palette images read their colours: index 0 is white here (free), index 1 black.
TEST(MapImages, PaletteColoursNotIndices) {
  PngSpec s;
  s.width = 2;
  s.height = 1;
  s.colourType = PNG_COLOR_TYPE_PALETTE;
  s.palette = {{255, 255, 255}, {0, 0, 0}};
  s.samples = {0, 1};
  writePng((dir() / "palette.png").string(), s);
  const datasets::OccupancyGrid g = datasets::readRosGrid(put("palette.yaml", "image: palette.png\nresolution: 1\norigin: [0, 0, 0]\n"));
  EXPECT_FALSE(g.at(0, 0));
  EXPECT_TRUE(g.at(1, 0));
}

// PGM: P2 and P5 with maxval 1 .. 65535 (two bytes, big-endian, above 255), against the reference.
TEST(MapImages, PgmEveryMaxval) {
  std::mt19937_64 rng(5);
  for (unsigned maxval : {1u, 15u, 100u, 255u, 256u, 1000u, 65535u})
    for (bool binary : {true, false}) {
      const int w = 7, h = 5;
      const std::vector<unsigned> v = interestingValues(maxval, rng, static_cast<std::size_t>(w) * h);
      std::string data = std::string(binary ? "P5" : "P2") + "\n# a comment\n" + std::to_string(w) + " " + std::to_string(h) + "\n" + std::to_string(maxval) + "\n";
      for (int k = 0; k < w * h; ++k) {
        if (!binary) data += std::to_string(v[static_cast<std::size_t>(k)]) + (k % w == w - 1 ? "\n" : " ");
        else if (maxval > 255) data += std::string{static_cast<char>(v[static_cast<std::size_t>(k)] >> 8), static_cast<char>(v[static_cast<std::size_t>(k)] & 255)};
        else data += static_cast<char>(v[static_cast<std::size_t>(k)]);
      }
      const std::string stem = std::string(binary ? "p5_" : "p2_") + std::to_string(maxval);
      put(stem + ".pgm", data);
      compareAll(stem, stem + ".pgm", w, h, [&](std::size_t k) { return Pixel{{v[k]}, maxval, maxval}; });
    }
}

TEST(MapImages, ModesByExample) {
  // grey values 254 (free), 0 (occupied), 205 (unknown), 150 (p ≈ 0.41: between the thresholds)
  put("modes.pgm", std::string("P5\n4 1\n255\n") + static_cast<char>(254) + static_cast<char>(0) + static_cast<char>(205) + static_cast<char>(150));
  auto read = [](const std::string& mode, int negate, bool unknownFree) {
    datasets::MapOptions o;
    o.unknownIsFree = unknownFree;
    const datasets::OccupancyGrid g = datasets::readRosGrid(
        put("modes.yaml", "image: modes.pgm\nresolution: 1\norigin: [0, 0, 0]\nmode: " + mode + "\nnegate: " + std::to_string(negate) + "\n"), o);
    std::string s;
    for (int j = 0; j < 4; ++j) s += g.at(j, 0) ? '#' : '.';
    return s;
  };
  EXPECT_EQ(read("trinary", 0, false), ".###");
  EXPECT_EQ(read("trinary", 0, true), ".#..");   // unknown free: 205 and 150 are unknown
  EXPECT_EQ(read("scale", 0, true), ".###");     // 205 and 150 are partially occupied: blocked
  EXPECT_EQ(read("trinary", 1, false), "#.##");  // negate: 0 is free, 254 occupied
  // raw: value = round(shade·255) = the grey value; > 100 unknown; 0 free
  EXPECT_EQ(read("raw", 0, true), "....");
  EXPECT_EQ(read("raw", 0, false), "#.##");
  // raw with negate: value = 255 − v: 1 (free), 255 (unknown), 50 (p = 0.5: partial), 105 (unknown)
  EXPECT_EQ(read("raw", 1, true), "..#.");
}

// ------------------------------------------------------------------ limits and truncation
TEST(MapImages, HugePngHeaderRefusedBeforeAllocating) {
  // A PNG announcing 100000 × 100000 grey pixels, with one row of data: about 150 bytes.
  const std::string path = (dir() / "huge.png").string();
  {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    ASSERT_EQ(setjmp(png_jmpbuf(png)), 0);
    png_init_io(png, f);
    png_set_user_limits(png, 0x7fffffff, 0x7fffffff);
    png_set_IHDR(png, info, 100000, 100000, 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    std::vector<png_byte> row(100000, 255);
    png_write_row(png, row.data());
    png_write_flush(png);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
  }
  EXPECT_LT(fs::file_size(path), 400u);
  put("huge.yaml", "image: huge.png\nresolution: 1\n");
  // refused from the header, before anything is allocated (the message names the header)
  const std::string e = errorOf([] { datasets::readRosGrid((dir() / "huge.yaml").string()); });
  EXPECT_NE(e.find("huge.png: header: grid of 100000 x 100000 cells is too large (the limit is 268435456 = 2^28 cells)"), std::string::npos) << e;

  // Within the pixel limit but more than the file can hold (deflate compresses at most 1032:1).
  const std::string path2 = (dir() / "big.png").string();
  {
    std::FILE* f = std::fopen(path2.c_str(), "wb");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    ASSERT_EQ(setjmp(png_jmpbuf(png)), 0);
    png_init_io(png, f);
    png_set_IHDR(png, info, 16000, 16000, 8, PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_ADAM7, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
  }
  put("big.yaml", "image: big.png\nresolution: 1\n");
  const std::string e2 = errorOf([] { datasets::readRosGrid((dir() / "big.yaml").string()); });
  EXPECT_NE(e2.find("big.png: pixel data: truncated PNG: 16000 x 16000 pixels need at least"), std::string::npos) << e2;
}

TEST(MapImages, TruncatedAndCorruptPngFailAtTheRow) {
  PngSpec s;
  s.width = 64;
  s.height = 64;
  s.depth = 8;
  std::mt19937_64 rng(3);
  for (int k = 0; k < 64 * 64; ++k) s.samples.push_back(static_cast<unsigned>(rng() % 256));  // incompressible
  for (bool adam7 : {false, true}) {
    s.adam7 = adam7;
    const std::string full = (dir() / "full.png").string();
    writePng(full, s);
    std::ifstream in(full, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), {});
    put("cut.png", bytes.substr(0, bytes.size() / 2));
    const std::string y = put("cut.yaml", "image: cut.png\nresolution: 1\n");
    const std::string e = errorOf([&] { datasets::readRosGrid(y); });
    EXPECT_NE(e.find("cut.png: row "), std::string::npos) << e;
    EXPECT_NE(e.find("truncated or corrupt PNG: "), std::string::npos) << e;
    if (adam7) {
      EXPECT_NE(e.find("(Adam7 pass "), std::string::npos) << e;
    }
    // a flipped byte inside the image data: a CRC error
    std::string bad = bytes;
    bad[bytes.size() / 2] = static_cast<char>(bad[bytes.size() / 2] ^ 0x55);
    put("crc.png", bad);
    const std::string e2 = errorOf([&] { datasets::readRosGrid(put("crc.yaml", "image: crc.png\nresolution: 1\n")); });
    EXPECT_NE(e2.find("crc.png: "), std::string::npos) << e2;
    EXPECT_NE(e2.find("corrupt PNG"), std::string::npos) << e2;
  }
  // only the signature and part of the header
  put("stub.png", std::string("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16));
  const std::string e3 = errorOf([] { datasets::readRosGrid(put("stub.yaml", "image: stub.png\nresolution: 1\n")); });
  EXPECT_NE(e3.find("stub.png: header: unreadable PNG"), std::string::npos) << e3;
}

TEST(MapImages, PgmLimitsCheckedBeforeAllocating) {
  // within the limit, without the data: the data length is compared before anything is allocated
  put("p5big.pgm", "P5\n16000 16000\n255\n");
  EXPECT_NE(errorOf([] { datasets::readRosGrid(put("p5big.yaml", "image: p5big.pgm\nresolution: 1\n")); })
                .find("p5big.pgm: pixel data: truncated PGM: 0 of 256000000 pixels"),
            std::string::npos);
  put("p2big.pgm", "P2\n16000 16000\n255\n1 2 3\n");
  EXPECT_NE(errorOf([] { datasets::readRosGrid(put("p2big.yaml", "image: p2big.pgm\nresolution: 1\n")); }).find("p2big.pgm: pixel data: truncated PGM"),
            std::string::npos);
  for (const char* size : {"20000 20000", "100000 100000"}) {
    put("p5huge.pgm", std::string("P5\n") + size + "\n255\n");
    EXPECT_NE(errorOf([] { datasets::readRosGrid(put("p5huge.yaml", "image: p5huge.pgm\nresolution: 1\n")); }).find("the limit is 268435456 = 2^28 cells"),
              std::string::npos);
  }
  put("p5zero.pgm", "P5\n0 3\n255\n");
  EXPECT_NE(errorOf([] { datasets::readRosGrid(put("p5zero.yaml", "image: p5zero.pgm\nresolution: 1\n")); }).find("bad grid size 0 x 3"), std::string::npos);
  put("p5over.pgm", std::string("P5\n2 1\n100\n") + static_cast<char>(50) + static_cast<char>(101));
  EXPECT_NE(errorOf([] { datasets::readRosGrid(put("p5over.yaml", "image: p5over.pgm\nresolution: 1\n")); })
                .find("p5over.pgm: pixel (row 0, column 1): value 101 above maxval 100"),
            std::string::npos);
  put("p5max.pgm", "P5\n2 1\n70000\n");
  EXPECT_NE(errorOf([] { datasets::readRosGrid(put("p5max.yaml", "image: p5max.pgm\nresolution: 1\n")); }).find("bad PGM maxval 70000"), std::string::npos);
}
