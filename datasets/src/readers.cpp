// Map readers: ROS map_server, Moving AI, WKT, GeoJSON, coverkit text grid.
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/error.h>

#include <nlohmann/json.hpp>
#include <png.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <memory>
#include <functional>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace coverkit::datasets {

namespace fs = std::filesystem;

std::string readTextFile(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, "", "file not found");
  if (fs::is_directory(path, ec)) throw InputError(path, "", "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot be read");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

namespace {

std::string readFile(const std::string& path) { return readTextFile(path); }

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// ---------------------------------------------------------------- ROS map images
//
// HOW A PIXEL IS READ (docs/formats.md, "ROS map images"), as ROS map_server reads it, with the
// deviations marked:
//  * Every sample at its full precision. PNG: 1/2/4-bit grey is expanded exactly (v·255/(2^b − 1),
//    the same shade), 8- and 16-bit samples are kept as written, a palette image reads its palette
//    colours (nav2 does; ROS1's SDL loader would read the indices), tRNS becomes alpha, Adam7
//    interlacing is undone. No gamma, no sRGB conversion. PGM P2/P5: maxval 1..65535 (two bytes,
//    big-endian, in P5 when maxval > 255).
//  * shade = the MEAN of the colour channels, (R + G + B)/(3·maxval), or v/maxval for grey: an exact
//    rational. map_server computes this mean too (not a luminance).
//  * Alpha is NOT averaged into the colour. ROS1 map_server and nav2 average alpha in trinary mode,
//    so an opaque grey 205 (unknown) reads (3·205 + 255)/4 = 217.5: free. We deviate, for safety.
//  * A pixel with alpha 0 is unknown, in every mode.
//  * trinary: p = 1 − shade (shade when negate); p > occupied_thresh occupied, p < free_thresh
//    free, else unknown. Compared exactly.
//  * scale: a pixel that is not fully opaque is unknown (nav2's rule); otherwise as trinary, except
//    that a pixel between the thresholds is partially occupied (map_server writes 1..99): blocked
//    for a coverage robot, whatever MapOptions::unknownIsFree says.
//  * raw: value = round(s·255), halves up, s = shade, or 1 − shade when negate (ROS1 applies negate
//    before raw; nav2 ignores negate there); value > 100 unknown; value/100 > occupied_thresh
//    occupied, value/100 < free_thresh free, else partially occupied (blocked).
//  * Unknown is blocked unless MapOptions::unknownIsFree.
// Memory: the header is checked against kMaxGridCells, and a PNG's size against what its file can
// hold (deflate compresses at most 1032:1), before the grid is allocated; rows are decoded one at a
// time (interlaced images pass by pass, straight into the grid), so no decoded image is ever held
// whole and a truncated stream fails at the row where it ends.

enum class MapMode { kTrinary, kScale, kRaw };

struct PixelRules {
  MapMode mode = MapMode::kTrinary;
  bool negate = false;
  Rational occupied = ratio(65, 100), free = ratio(196, 1000);
  bool unknownIsFree = false;
};

/// Blocked or not, for a sum of the colour samples of a pixel (exact rationals, computed once per sum
/// met: maps use few shades), and the alpha rules.
class PixelTable {
public:
  PixelTable(const PixelRules& rules, unsigned colourChannels, std::uint32_t maxval)
      : rules_(rules), denominator_(colourChannels * maxval), maxval_(maxval), scale_(rules.mode == MapMode::kScale),
        unknownBlocked_(!rules.unknownIsFree), blocked_(static_cast<std::size_t>(denominator_) + 1, kNotYet) {}
  /// `alpha` on the same 0..maxval scale (maxval for an image without alpha).
  bool blocked(std::uint32_t colourSum, std::uint32_t alpha) {
    if (alpha == 0 || (scale_ && alpha != maxval_)) return unknownBlocked_;
    std::uint8_t& b = blocked_[colourSum];
    if (b == kNotYet) b = compute(colourSum) ? 1 : 0;
    return b != 0;
  }

private:
  static constexpr std::uint8_t kNotYet = 2;
  bool compute(std::uint32_t sum) const {
    enum { kFree, kOccupied, kUnknown, kPartial };
    const Rational shade = ratio(static_cast<long>(sum), static_cast<long>(denominator_));
    int cls;
    if (rules_.mode == MapMode::kRaw) {
      const Rational s = rules_.negate ? Rational(1 - shade) : shade;
      const mpz_class value = (s.get_num() * 255 * 2 + s.get_den()) / (s.get_den() * 2);  // round(s·255), halves up
      Rational v(value, 100);
      v.canonicalize();
      cls = value > 100 ? kUnknown : v > rules_.occupied ? kOccupied : v < rules_.free ? kFree : kPartial;
    } else {
      const Rational p = rules_.negate ? shade : Rational(1 - shade);
      cls = p > rules_.occupied ? kOccupied : p < rules_.free ? kFree : rules_.mode == MapMode::kTrinary ? kUnknown : kPartial;
    }
    return cls == kOccupied || cls == kPartial || (cls == kUnknown && unknownBlocked_);
  }
  PixelRules rules_;
  std::uint32_t denominator_, maxval_;
  bool scale_, unknownBlocked_;
  std::vector<std::uint8_t> blocked_;
};

/// A grid of `width` × `height` pixels for an image whose row 0 is on top; cells not yet set.
OccupancyGrid emptyGrid(std::int64_t width, std::int64_t height) {
  OccupancyGrid g;
  g.width = static_cast<int>(width);
  g.height = static_cast<int>(height);
  g.blocked.assign(static_cast<std::size_t>(width * height), 1);
  return g;
}
void setPixel(OccupancyGrid& g, std::uint32_t row, std::uint32_t col, bool blocked) {
  g.blocked[static_cast<std::size_t>(g.height - 1 - static_cast<int>(row)) * g.width + col] = blocked;
}

OccupancyGrid readPgm(const std::string& path, const PixelRules& rules) {
  const std::string data = readFile(path);
  std::size_t p = 0;
  auto bad = [&](const std::string& why) { return InputError(path, "byte " + std::to_string(p), why); };
  if (data.size() < 2 || data[0] != 'P' || (data[1] != '5' && data[1] != '2')) throw InputError(path, "header", "not a PGM image (expected P5 or P2)");
  const bool binary = data[1] == '5';
  p = 2;
  auto skip = [&] {
    while (p < data.size()) {
      if (std::isspace(static_cast<unsigned char>(data[p]))) ++p;
      else if (data[p] == '#') { while (p < data.size() && data[p] != '\n') ++p; }
      else break;
    }
  };
  auto number = [&](const char* what) {
    skip();
    if (p >= data.size() || !std::isdigit(static_cast<unsigned char>(data[p]))) throw bad(std::string("truncated PGM: missing ") + what);
    std::int64_t v = 0;
    while (p < data.size() && std::isdigit(static_cast<unsigned char>(data[p]))) {
      v = v * 10 + (data[p++] - '0');
      if (v > 1'000'000'000L) throw bad(std::string("PGM ") + what + " too large");
    }
    return v;
  };
  const std::int64_t w = number("width"), h = number("height"), maxv = number("maxval");
  checkGridSize(path, "header", w, h);
  if (maxv <= 0 || maxv > 65535) throw InputError(path, "header", "bad PGM maxval " + std::to_string(maxv) + " (expected 1..65535)");
  const std::int64_t n = w * h;
  if (binary) {
    if (p >= data.size() || !std::isspace(static_cast<unsigned char>(data[p]))) throw bad("truncated PGM: expected one whitespace after maxval");
    ++p;  // exactly one whitespace after maxval
  }
  // The data length is checked before the grid is allocated.
  const std::int64_t have = static_cast<std::int64_t>(data.size() - std::min(data.size(), p));
  const std::int64_t bpp = maxv > 255 ? 2 : 1;
  if (binary && have < n * bpp)
    throw InputError(path, "pixel data", "truncated PGM: " + std::to_string(have / bpp) + " of " + std::to_string(n) + " pixels");
  if (!binary && have < 2 * n - 1)
    throw InputError(path, "pixel data", "truncated PGM: " + std::to_string(n) + " pixels need at least " + std::to_string(2 * n - 1) +
                                             " bytes, the file has " + std::to_string(have) + " after the header");
  PixelTable table(rules, 1, static_cast<std::uint32_t>(maxv));
  OccupancyGrid g = emptyGrid(w, h);
  for (std::int64_t i = 0; i < n; ++i) {
    std::int64_t v;
    if (binary) {
      const std::size_t at = p + static_cast<std::size_t>(i * bpp);
      v = bpp == 1 ? static_cast<unsigned char>(data[at]) : (static_cast<unsigned char>(data[at]) << 8 | static_cast<unsigned char>(data[at + 1]));
      if (v > maxv)
        throw InputError(path, "pixel (row " + std::to_string(i / w) + ", column " + std::to_string(i % w) + ")",
                         "value " + std::to_string(v) + " above maxval " + std::to_string(maxv));
    } else {
      v = number("pixel");
      if (v > maxv) throw bad("pixel value " + std::to_string(v) + " above maxval " + std::to_string(maxv));
    }
    setPixel(g, static_cast<std::uint32_t>(i / w), static_cast<std::uint32_t>(i % w), table.blocked(static_cast<std::uint32_t>(v), static_cast<std::uint32_t>(maxv)));
  }
  return g;
}

// libpng reports errors through a callback that must not return: it records the message and
// longjmps back to the setjmp of the function that called libpng. Those functions (pngReadHeader,
// pngReadRows) hold no C++ object with a destructor; pngRow runs between libpng calls, never inside
// one; the InputError is thrown by their caller.
struct PngState {
  char message[256] = "";
  std::uint32_t pass = 0, row = 0;  // where the decoder is (for the error message)
};
extern "C" void pngOnError(png_structp png, png_const_charp msg) {
  auto* st = static_cast<PngState*>(png_get_error_ptr(png));
  std::snprintf(st->message, sizeof st->message, "%s", msg ? msg : "libpng error");
  png_longjmp(png, 1);
}
extern "C" void pngOnWarning(png_structp, png_const_charp) {}
extern "C" void pngOnRead(png_structp png, png_bytep out, std::size_t n) {
  auto* f = static_cast<std::FILE*>(png_get_io_ptr(png));
  if (std::fread(out, 1, n, f) != n) png_error(png, "unexpected end of file");
}

bool pngReadHeader(png_structp png, png_infop info) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_info(png, info);
  return true;
}

struct PngRows {
  PixelTable* table;
  OccupancyGrid* grid;
  PngState* state;
  unsigned channels, colourChannels, bytes;  // after png_set_expand
  bool alpha;
  std::uint32_t maxval;
};

void pngRow(const PngRows& r, std::uint32_t x0, std::uint32_t dx, std::uint32_t count, std::uint32_t y, const png_byte* row) {
  for (std::uint32_t k = 0; k < count; ++k) {
    const png_byte* px = row + static_cast<std::size_t>(k) * r.channels * r.bytes;
    auto sample = [&](unsigned c) -> std::uint32_t { return r.bytes == 1 ? px[c] : (static_cast<std::uint32_t>(px[2 * c]) << 8 | px[2 * c + 1]); };
    std::uint32_t sum = 0;
    for (unsigned c = 0; c < r.colourChannels; ++c) sum += sample(c);
    const std::uint32_t a = r.alpha ? sample(r.channels - 1) : r.maxval;
    setPixel(*r.grid, y, x0 + k * dx, r.table->blocked(sum, a));
  }
}

bool pngReadRows(png_structp png, png_infop info, png_bytep buffer, std::size_t bufferSize, const PngRows& rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_expand(png);  // palette → RGB, grey of 1/2/4 bits → 8 bits (exactly), tRNS → alpha
  // No png_set_strip_16, no gamma, no png_set_interlace_handling: Adam7 passes are read one by one
  // below, straight into the grid, so the decoded image is never held whole.
  png_read_update_info(png, info);
  if (png_get_rowbytes(png, info) > bufferSize) png_error(png, "unexpected row size after the transformations");
  const std::uint32_t W = png_get_image_width(png, info), H = png_get_image_height(png, info);
  const bool adam7 = png_get_interlace_type(png, info) == PNG_INTERLACE_ADAM7;
  for (int pass = 0; pass < (adam7 ? 7 : 1); ++pass) {
    const std::uint32_t x0 = adam7 ? PNG_PASS_START_COL(pass) : 0, dx = adam7 ? PNG_PASS_COL_OFFSET(pass) : 1;
    const std::uint32_t y0 = adam7 ? PNG_PASS_START_ROW(pass) : 0, dy = adam7 ? PNG_PASS_ROW_OFFSET(pass) : 1;
    const std::uint32_t cols = adam7 ? PNG_PASS_COLS(W, pass) : W;
    if (cols == 0 || (adam7 && PNG_PASS_ROWS(H, pass) == 0)) continue;  // libpng skips empty passes
    rows.state->pass = static_cast<std::uint32_t>(pass);
    for (std::uint32_t y = y0; y < H; y += dy) {
      rows.state->row = y;
      png_read_row(png, buffer, nullptr);
      pngRow(rows, x0, dx, cols, y, buffer);
    }
  }
  rows.state->row = H;
  png_read_end(png, nullptr);
  return true;
}

OccupancyGrid readPng(const std::string& path, const PixelRules& rules) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, "", "file not found");
  if (fs::is_directory(path, ec)) throw InputError(path, "", "is a directory, not a file");
  const std::uintmax_t fileSize = fs::file_size(path, ec);
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file || ec) throw InputError(path, "", "cannot be read");
  png_byte sig[8];
  if (std::fread(sig, 1, 8, file.get()) != 8 || png_sig_cmp(sig, 0, 8)) throw InputError(path, "header", "not a PNG image");
  // The header (IHDR, the first chunk) is checked before libpng reads on: the size limit and what
  // the file can hold come first, whatever follows.
  png_byte ihdr[25];
  if (std::fread(ihdr, 1, 25, file.get()) == 25 && std::memcmp(ihdr + 4, "IHDR", 4) == 0) {
    auto be32 = [&](int at) { return static_cast<std::int64_t>(png_get_uint_32(ihdr + at)); };
    const std::int64_t W = be32(8), H = be32(12), depth = ihdr[16];
    checkGridSize(path, "header", W, H);
    const int type = ihdr[17];
    const std::int64_t samples = type == 2 ? 3 : type == 4 ? 2 : type == 6 ? 4 : 1;
    // A deflate stream holds at most 1032 bytes per byte: refuse what the file cannot contain.
    const std::int64_t rawBytes = H * ((W * samples * depth + 7) / 8 + 1);  // a filter byte per row
    if (depth >= 1 && depth <= 16 && rawBytes / 1032 > static_cast<std::int64_t>(fileSize))
      throw InputError(path, "pixel data", "truncated PNG: " + std::to_string(W) + " x " + std::to_string(H) + " pixels need at least " +
                                               std::to_string(rawBytes / 1032) + " bytes of compressed data, the file has " +
                                               std::to_string(fileSize) + " bytes");
  }
  if (std::fseek(file.get(), 8, SEEK_SET) != 0) throw InputError(path, "", "cannot be read");
  PngState state;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &state, &pngOnError, &pngOnWarning);
  if (!png) throw InputError(path, "", "cannot start the PNG decoder");
  png_infop info = png_create_info_struct(png);
  struct Guard {
    png_structp* png;
    png_infop* info;
    ~Guard() { png_destroy_read_struct(png, info, nullptr); }
  } guard{&png, &info};
  if (!info) throw InputError(path, "", "cannot start the PNG decoder");
  png_set_read_fn(png, file.get(), &pngOnRead);
  png_set_sig_bytes(png, 8);
  png_set_user_limits(png, 0x7fffffffU, 0x7fffffffU);  // our own limit below names itself
  if (!pngReadHeader(png, info)) throw InputError(path, "header", std::string("unreadable PNG: ") + state.message);
  const std::int64_t W = png_get_image_width(png, info), H = png_get_image_height(png, info);
  checkGridSize(path, "header", W, H);  // as read by libpng (checked above on the bytes)
  const int depth = png_get_bit_depth(png, info), type = png_get_color_type(png, info);
  const bool colour = (type & PNG_COLOR_MASK_COLOR) != 0;
  const bool alpha = (type & PNG_COLOR_MASK_ALPHA) != 0 || png_get_valid(png, info, PNG_INFO_tRNS) != 0;
  PngRows rows{};
  rows.colourChannels = colour ? 3 : 1;
  rows.channels = rows.colourChannels + (alpha ? 1 : 0);
  rows.bytes = depth == 16 ? 2 : 1;
  rows.alpha = alpha;
  rows.maxval = depth == 16 ? 65535 : 255;
  PixelTable table(rules, rows.colourChannels, rows.maxval);
  OccupancyGrid g = emptyGrid(W, H);
  std::vector<png_byte> buffer(static_cast<std::size_t>(W) * rows.channels * rows.bytes);
  rows.table = &table;
  rows.grid = &g;
  rows.state = &state;
  if (!pngReadRows(png, info, buffer.data(), buffer.size(), rows)) {
    const std::string where = state.row >= static_cast<std::uint32_t>(H) ? "end of the image"
                              : "row " + std::to_string(state.row) + (png_get_interlace_type(png, info) == PNG_INTERLACE_ADAM7
                                                                            ? " (Adam7 pass " + std::to_string(state.pass + 1) + ")"
                                                                            : std::string());
    throw InputError(path, where, std::string("truncated or corrupt PNG: ") + state.message);
  }
  return g;
}

Rational yamlNumber(const YAML::Node& node, const std::string& file, const std::string& key) {
  if (!node.IsScalar()) throw InputError(file, key, "expected a number");
  return parseRational(node.Scalar(), file, key);
}

}  // namespace

Workspace loadMap(const std::string& path, const MapOptions& options) {
  const std::string ext = lower(fs::path(path).extension().string());
  if (ext == ".yaml" || ext == ".yml") return readRosMap(path, options);
  if (ext == ".map") return readMovingAi(path);
  if (ext == ".wkt") return readWkt(path);
  if (ext == ".geojson" || ext == ".json") return readGeoJson(path);
  if (ext == ".grid" || ext == ".txt") return readTextGrid(path);
  readFile(path);  // a missing file is reported as such first
  throw InputError(path, "", "unknown map format '" + ext + "' (expected .yaml, .map, .wkt, .geojson, .grid)");
}

namespace {
OccupancyGrid readRosGridChecked(const std::string& yamlPath, const MapOptions& options);
}  // namespace

void checkGridSize(const std::string& file, const std::string& place, std::int64_t width, std::int64_t height) {
  const std::string size = std::to_string(width) + " x " + std::to_string(height);
  if (width <= 0 || height <= 0) throw InputError(file, place, "bad grid size " + size + " (both must be at least 1)");
  if (width > kMaxGridCells / height)
    throw InputError(file, place, "grid of " + size + " cells is too large (the limit is " + std::to_string(kMaxGridCells) + " = 2^28 cells)");
}

OccupancyGrid readRosGrid(const std::string& yamlPath, const MapOptions& options) {
  try {
    return readRosGridChecked(yamlPath, options);
  } catch (const YAML::Exception& e) {  // a node access not checked: still bad input
    throw InputError(yamlPath, "line " + std::to_string(e.mark.line + 1), "unexpected YAML: " + e.msg);
  }
}

namespace {
OccupancyGrid readRosGridChecked(const std::string& yamlPath, const MapOptions& options) {
  const std::string text = readFile(yamlPath);
  YAML::Node y;
  try {
    y = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(yamlPath, "line " + std::to_string(e.mark.line + 1), "YAML does not parse: " + e.msg);
  }
  if (!y.IsMap()) throw InputError(yamlPath, "", "not a map_server YAML (expected a mapping)");
  if (!y["resolution"]) throw InputError(yamlPath, "resolution", "missing");
  if (!y["image"]) throw InputError(yamlPath, "image", "missing");
  const Rational res = yamlNumber(y["resolution"], yamlPath, "resolution");
  if (res <= 0) throw InputError(yamlPath, "resolution", "must be > 0");
  Rational ox = 0, oy = 0;
  if (y["origin"]) {  // map_server requires it; a missing origin is [0, 0, 0] here
    const YAML::Node o = y["origin"];
    if (!o.IsSequence() || o.size() != 3)
      throw InputError(yamlPath, "origin", "expected [x, y, yaw]" + (o.IsSequence() ? ", found " + std::to_string(o.size()) + " numbers" : std::string()));
    ox = yamlNumber(o[0], yamlPath, "origin[0]");
    oy = yamlNumber(o[1], yamlPath, "origin[1]");
    if (yamlNumber(o[2], yamlPath, "origin[2]") != 0) throw InputError(yamlPath, "origin[2]", "a rotated map (yaw != 0) is not supported");
  }
  PixelRules rules;
  rules.unknownIsFree = options.unknownIsFree;
  if (y["negate"]) {
    const std::string v = y["negate"].IsScalar() ? y["negate"].Scalar() : "";
    rules.negate = v == "true" || v == "True" ? true : v == "false" || v == "False" ? false : yamlNumber(y["negate"], yamlPath, "negate") != 0;
  }
  if (y["occupied_thresh"]) rules.occupied = yamlNumber(y["occupied_thresh"], yamlPath, "occupied_thresh");
  if (y["free_thresh"]) rules.free = yamlNumber(y["free_thresh"], yamlPath, "free_thresh");
  if (rules.occupied < 0 || rules.occupied > 1 || rules.free < 0 || rules.free > 1 || rules.free > rules.occupied)
    throw InputError(yamlPath, "free_thresh/occupied_thresh", "must satisfy 0 <= free_thresh <= occupied_thresh <= 1");
  if (y["mode"]) {
    const std::string mode = y["mode"].IsScalar() ? y["mode"].Scalar() : "";
    if (mode == "trinary") rules.mode = MapMode::kTrinary;
    else if (mode == "scale") rules.mode = MapMode::kScale;
    else if (mode == "raw") rules.mode = MapMode::kRaw;
    else throw InputError(yamlPath, "mode", "unknown mode '" + mode + "' (trinary, scale or raw)");
  }
  if (!y["image"].IsScalar() || y["image"].Scalar().empty()) throw InputError(yamlPath, "image", "expected a file name");
  fs::path img = y["image"].Scalar();
  if (img.is_relative()) img = fs::path(yamlPath).parent_path() / img;
  const std::string ext = lower(img.extension().string());
  std::error_code ec;
  if (!fs::exists(img, ec)) throw InputError(yamlPath, "image", "image file '" + img.string() + "' not found");
  OccupancyGrid g;
  if (ext == ".png") g = readPng(img.string(), rules);
  else if (ext == ".pgm") g = readPgm(img.string(), rules);
  else throw InputError(yamlPath, "image", "unsupported image type '" + ext + "' (PGM or PNG)");
  // pixel (row i, column j) of an H-row image is the square origin + res·[j, j+1] × res·[H−1−i, H−i]
  g.resolution = res;
  g.originX = ox;
  g.originY = oy;
  return g;
}
}  // namespace

Workspace readRosMap(const std::string& yamlPath, const MapOptions& options) {
  Workspace w = gridToWorkspace(readRosGrid(yamlPath, options), yamlPath);
  if (w.regions.empty()) throw InputError(yamlPath, "image", "empty free space: no free pixel");
  return w;
}

// Moving AI: the header is exactly "type", "height", "width", "map", sizes plain positive integers;
// then exactly `height` rows of exactly `width` cells. After them only empty (or blank) lines may
// follow. The grid grows with the rows read, so a header announcing more than the file holds costs
// nothing before the missing row is reported.
Workspace readMovingAi(const std::string& path) {
  const std::string text = readFile(path);
  std::istringstream in(text);
  std::string line, key;
  int lineNo = 0;
  auto header = [&](const char* want) {
    ++lineNo;
    if (!std::getline(in, line)) throw InputError(path, "line " + std::to_string(lineNo), std::string("truncated header: expected '") + want + "'");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream ls(line);
    key.clear();
    ls >> key;
    if (key != want) throw InputError(path, "line " + std::to_string(lineNo), std::string("bad Moving AI header: expected '") + want + "', found '" + line + "'");
    return std::string(std::istreambuf_iterator<char>(ls), {});
  };
  header("type");
  auto dim = [&](const char* what) {
    std::string v = header(what);
    const std::size_t b = v.find_first_not_of(" \t"), e = v.find_last_not_of(" \t");
    v = b == std::string::npos ? std::string() : v.substr(b, e - b + 1);
    const bool digits = !v.empty() && v.size() <= 10 && std::all_of(v.begin(), v.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!digits) throw InputError(path, "line " + std::to_string(lineNo), std::string("bad ") + what + " '" + v + "' (expected a positive integer)");
    const std::int64_t x = std::stoll(v);
    if (x <= 0) throw InputError(path, "line " + std::to_string(lineNo), std::string("bad ") + what + " '" + v + "' (expected a positive integer)");
    return x;
  };
  const std::int64_t height = dim("height");
  const std::int64_t width = dim("width");
  checkGridSize(path, "header", width, height);
  header("map");
  // rows top to bottom, as read; at most what the file can hold is reserved
  std::vector<std::uint8_t> rows;
  rows.reserve(static_cast<std::size_t>(std::min<std::int64_t>(width * height, static_cast<std::int64_t>(text.size()))));
  for (std::int64_t i = 0; i < height; ++i) {
    ++lineNo;
    if (!std::getline(in, line)) throw InputError(path, "line " + std::to_string(lineNo), "missing map row " + std::to_string(i + 1) + " of " + std::to_string(height));
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (static_cast<std::int64_t>(line.size()) != width)
      throw InputError(path, "line " + std::to_string(lineNo), "row has " + std::to_string(line.size()) + " cells, width is " + std::to_string(width));
    for (std::size_t j = 0; j < line.size(); ++j) {
      const char c = line[j];
      if (c == '.' || c == 'G' || c == 'S') rows.push_back(0);
      else if (c == '@' || c == 'O' || c == 'T' || c == 'W') rows.push_back(1);
      else throw InputError(path, "line " + std::to_string(lineNo) + " column " + std::to_string(j + 1), std::string("unknown terrain '") + c + "'");
    }
  }
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.find_first_not_of(" \t\r") != std::string::npos)
      throw InputError(path, "line " + std::to_string(lineNo), "extra row beyond the height of " + std::to_string(height) + " rows");
  }
  OccupancyGrid g;
  g.width = static_cast<int>(width);
  g.height = static_cast<int>(height);
  g.blocked.resize(rows.size());
  for (std::int64_t i = 0; i < height; ++i)  // first row on top
    std::copy_n(rows.begin() + i * width, width, g.blocked.begin() + (height - 1 - i) * width);
  Workspace w = gridToWorkspace(g, path);
  if (w.regions.empty()) throw InputError(path, "map", "empty free space: no passable cell");
  return w;
}

// ---------------------------------------------------------------- WKT
namespace {
class WktParser {
public:
  WktParser(const std::string& t, const std::string& name) : t_(t), name_(name) {}
  Workspace parse() {
    Workspace w;
    w.name = name_;
    const std::string kw = word();
    const std::size_t save = p_;
    const std::string dims = word();  // optional Z, M or ZM
    if (dims == "EMPTY") fail("empty geometry: no free space");
    if (!dims.empty() && dims != "Z" && dims != "M" && dims != "ZM") fail("unexpected '" + dims + "'");
    if (dims.empty()) p_ = save;
    if (kw == "POLYGON") {
      w.regions.push_back(polygon());
    } else if (kw == "MULTIPOLYGON") {
      expect('(');
      do w.regions.push_back(polygon());
      while (accept(','));
      expect(')');
    } else {
      fail("expected POLYGON or MULTIPOLYGON, found '" + kw + "'");
    }
    skip();
    if (p_ < t_.size()) fail("unexpected text after the geometry");
    return w;
  }

private:
  [[noreturn]] void fail(const std::string& why) const {
    int line = 1, col = 1;
    for (std::size_t i = 0; i < p_ && i < t_.size(); ++i) {
      if (t_[i] == '\n') { ++line; col = 1; } else ++col;
    }
    throw InputError(name_, "line " + std::to_string(line) + " column " + std::to_string(col), "WKT does not parse: " + why);
  }
  void skip() { while (p_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[p_]))) ++p_; }
  std::string word() {
    skip();
    std::string s;
    while (p_ < t_.size() && std::isalpha(static_cast<unsigned char>(t_[p_]))) s += static_cast<char>(std::toupper(static_cast<unsigned char>(t_[p_++])));
    return s;
  }
  bool accept(char c) {
    skip();
    if (p_ < t_.size() && t_[p_] == c) { ++p_; return true; }
    return false;
  }
  void expect(char c) {
    if (!accept(c)) fail(std::string("expected '") + c + "'");
  }
  Rational number() {
    skip();
    const std::size_t s = p_;
    while (p_ < t_.size() && (std::isalnum(static_cast<unsigned char>(t_[p_])) || t_[p_] == '.' || t_[p_] == '-' || t_[p_] == '+')) ++p_;
    if (s == p_) fail("expected a number");
    try {
      return parseRational(t_.substr(s, p_ - s), name_, "");
    } catch (const InputError& e) {
      p_ = s;
      fail(e.problem());
    }
  }
  Ring ring() {
    expect('(');
    Ring r;
    do {
      Rational x = number(), y = number();
      skip();
      skip();
      if (p_ < t_.size() && t_[p_] != ',' && t_[p_] != ')') number();  // ignore Z (or M)
      skip();
      if (p_ < t_.size() && t_[p_] != ',' && t_[p_] != ')') number();  // ignore M of ZM
      r.push_back({x, y});
    } while (accept(','));
    expect(')');
    if (r.size() > 1 && r.front() == r.back()) r.pop_back();
    return r;
  }
  Region polygon() {
    expect('(');
    Region reg;
    reg.outer = ring();
    while (accept(',')) reg.holes.push_back(ring());
    expect(')');
    return reg;
  }
  const std::string& t_;
  std::string name_;
  std::size_t p_ = 0;
};
}  // namespace

Workspace parseWkt(const std::string& text, const std::string& name) {
  Workspace w = WktParser(text, name).parse();
  checkWorkspace(w);
  normalise(w);
  return w;
}
Workspace readWkt(const std::string& path) { return parseWkt(readFile(path), path); }

// ---------------------------------------------------------------- GeoJSON
// Every member is checked for its JSON type before it is used, and a problem names its place as a
// path into the document ("features[2].geometry.coordinates[0][5]"). Decisions:
//  * a Feature's geometry member is required (RFC 7946); null (an unlocated feature) adds nothing;
//  * a FeatureCollection's features must be Feature objects;
//  * GeometryCollections nest at most kMaxGeoJsonDepth deep;
//  * frame: see decideFrame below and docs/formats.md.
namespace {
constexpr int kMaxGeoJsonDepth = 64;

struct GeoPolygon {
  std::string place;  // of its coordinates (an array of rings)
  const nlohmann::json* rings;
};

class GeoJsonReader {
public:
  explicit GeoJsonReader(const std::string& name) : name_(name) {}

  void document(const nlohmann::json& j) {
    if (!j.is_object()) fail("", "not GeoJSON: expected an object");
    const std::string type = typeOf(j, "");
    if (type == "FeatureCollection") {
      const nlohmann::json* fs = member(j, "features", "");
      if (!fs || !fs->is_array()) fail("features", fs ? "expected an array of Features" : "missing");
      for (std::size_t i = 0; i < fs->size(); ++i) feature((*fs)[i], "features[" + std::to_string(i) + "]");
    } else if (type == "Feature") {
      feature(j, "");
    } else {
      geometry(j, "", 0);
    }
  }
  std::vector<GeoPolygon> polygons;

  [[noreturn]] void fail(const std::string& place, const std::string& why) const { throw InputError(name_, place, why); }
  static std::string join(const std::string& place, const std::string& key) { return place.empty() ? key : place + "." + key; }

private:
  const nlohmann::json* member(const nlohmann::json& obj, const char* key, const std::string&) const {
    const auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }
  std::string typeOf(const nlohmann::json& obj, const std::string& place) const {
    const nlohmann::json* t = member(obj, "type", place);
    if (!t) fail(join(place, "type"), "missing");
    if (!t->is_string()) fail(join(place, "type"), "expected a string, found " + std::string(t->type_name()));
    return t->get<std::string>();
  }
  void feature(const nlohmann::json& f, const std::string& place) {
    if (!f.is_object()) fail(place, "expected a Feature object, found " + std::string(f.type_name()));
    const std::string type = typeOf(f, place);
    if (type != "Feature") fail(join(place, "type"), "expected 'Feature', found '" + type + "'");
    const nlohmann::json* g = member(f, "geometry", place);
    if (!g) fail(join(place, "geometry"), "missing (a Feature without a location has \"geometry\": null)");
    if (g->is_null()) return;  // an unlocated feature: no free space from it
    geometry(*g, join(place, "geometry"), 0);
  }
  void geometry(const nlohmann::json& g, const std::string& place, int depth) {
    if (!g.is_object()) fail(place, "expected a geometry object, found " + std::string(g.type_name()));
    const std::string type = typeOf(g, place);
    auto array = [&](const char* key, const char* what) -> const nlohmann::json& {
      const nlohmann::json* c = member(g, key, place);
      if (!c) fail(join(place, key), std::string("missing: ") + type + " without " + what);
      if (!c->is_array()) fail(join(place, key), std::string("expected an array (") + what + "), found " + c->type_name());
      return *c;
    };
    if (type == "Polygon") {
      polygons.push_back({join(place, "coordinates"), &array("coordinates", "rings")});
    } else if (type == "MultiPolygon") {
      const nlohmann::json& c = array("coordinates", "polygons");
      for (std::size_t i = 0; i < c.size(); ++i) polygons.push_back({join(place, "coordinates") + "[" + std::to_string(i) + "]", &c[i]});
    } else if (type == "GeometryCollection") {
      if (depth >= kMaxGeoJsonDepth) fail(place, "GeometryCollections nested more than " + std::to_string(kMaxGeoJsonDepth) + " deep");
      const nlohmann::json& gs = array("geometries", "geometries");
      for (std::size_t i = 0; i < gs.size(); ++i) geometry(gs[i], join(place, "geometries") + "[" + std::to_string(i) + "]", depth + 1);
    } else {
      fail(join(place, "type"), "unsupported geometry type '" + type + "' (Polygon, MultiPolygon, GeometryCollection)");
    }
  }
  std::string name_;
};
}  // namespace

Workspace parseGeoJson(const std::string& text, const std::string& name) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(name, "byte " + std::to_string(e.byte), std::string("GeoJSON does not parse: ") + e.what());
  } catch (const nlohmann::json::exception& e) {
    throw InputError(name, "", std::string("GeoJSON does not parse: ") + e.what());
  }
  try {
    GeoJsonReader reader(name);
    reader.document(j);
    if (reader.polygons.empty()) throw InputError(name, "", "no Polygon in the GeoJSON: empty free space");
    // Collect the positions as doubles first, to decide the frame.
    struct RawPosition {
      double x, y;
    };
    std::vector<std::vector<std::vector<RawPosition>>> raw;  // polygon, ring, position
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    for (const GeoPolygon& poly : reader.polygons) {
      if (!poly.rings->is_array()) reader.fail(poly.place, "expected an array of rings, found " + std::string(poly.rings->type_name()));
      std::vector<std::vector<RawPosition>> rings;
      for (std::size_t r = 0; r < poly.rings->size(); ++r) {
        const auto& ring = (*poly.rings)[r];
        const std::string rp = poly.place + "[" + std::to_string(r) + "]";
        if (!ring.is_array()) reader.fail(rp, "expected a ring (an array of positions), found " + std::string(ring.type_name()));
        std::vector<RawPosition> rr;
        for (std::size_t k = 0; k < ring.size(); ++k) {
          const auto& pt = ring[k];
          const std::string at = rp + "[" + std::to_string(k) + "]";
          if (!pt.is_array() || pt.size() < 2 || !pt[0].is_number() || !pt[1].is_number()) reader.fail(at, "position is not [x, y]");
          for (std::size_t c = 2; c < pt.size(); ++c)
            if (!pt[c].is_number()) reader.fail(at + "[" + std::to_string(c) + "]", "expected a number (an altitude)");
          const double x = pt[0].get<double>(), y = pt[1].get<double>();
          if (!std::isfinite(x) || !std::isfinite(y)) reader.fail(at, "non-finite coordinate");
          rr.push_back({x, y});
          xmin = std::min(xmin, x); xmax = std::max(xmax, x); ymin = std::min(ymin, y); ymax = std::max(ymax, y);
        }
        rings.push_back(std::move(rr));
      }
      raw.push_back(std::move(rings));
    }
    // Frame. A "crs" member (GeoJSON 2008) decides when present and not null: CRS84 / EPSG:4326 say
    // longitude/latitude (every position must then lie in [-180, 180] × [-90, 90], else an error
    // names it); any other CRS says metric coordinates as written. Without one, positions are
    // longitude/latitude (RFC 7946) when every one lies in [-180, 180] × [-90, 90] AND the extent is
    // below half a degree in both axes; otherwise they are metric coordinates as written (a position
    // out of the longitude/latitude range, or a wide extent, means metric).
    int crsSaysLonLat = -1;
    if (const auto it = j.find("crs"); it != j.end() && !it->is_null()) {
      if (!it->is_object()) reader.fail("crs", "expected an object (GeoJSON 2008 crs) or null");
      const std::string crs = it->dump();
      crsSaysLonLat = (crs.find("CRS84") != std::string::npos || crs.find("4326") != std::string::npos) ? 1 : 0;
    }
    const bool inRange = xmin >= -180 && xmax <= 180 && ymin >= -90 && ymax <= 90;
    if (crsSaysLonLat == 1 && !inRange) {
      for (std::size_t pi = 0; pi < raw.size(); ++pi)
        for (std::size_t r = 0; r < raw[pi].size(); ++r)
          for (std::size_t k = 0; k < raw[pi][r].size(); ++k) {
            const auto [x, y] = raw[pi][r][k];
            const std::string at = reader.polygons[pi].place + "[" + std::to_string(r) + "][" + std::to_string(k) + "]";
            if (x < -180 || x > 180) reader.fail(at, "longitude " + formatDouble(x) + " outside [-180, 180] (the crs says longitude/latitude)");
            if (y < -90 || y > 90) reader.fail(at, "latitude " + formatDouble(y) + " outside [-90, 90] (the crs says longitude/latitude)");
          }
    }
    const bool lonlat = crsSaysLonLat == 1 ? true : crsSaysLonLat == 0 ? false : inRange && (xmax - xmin) < 0.5 && (ymax - ymin) < 0.5;
    const double lon0 = (xmin + xmax) / 2, lat0 = (ymin + ymax) / 2;
    constexpr double kEarth = 6371008.8;  // mean Earth radius (m)
    Workspace w;
    w.name = name;
    for (std::size_t pi = 0; pi < raw.size(); ++pi) {
      Region reg;
      for (std::size_t r = 0; r < raw[pi].size(); ++r) {
        Ring ring;
        for (auto [x, y] : raw[pi][r]) {
          if (lonlat) {
            // local equirectangular projection about the extent's centre, millimetre resolution
            const double ex = kEarth * std::cos(lat0 * M_PI / 180) * (x - lon0) * M_PI / 180;
            const double ny = kEarth * (y - lat0) * M_PI / 180;
            ring.push_back({Rational(mpz_class(static_cast<long>(std::llround(ex * 1000))), 1000), Rational(mpz_class(static_cast<long>(std::llround(ny * 1000))), 1000)});
            ring.back().x.canonicalize();
            ring.back().y.canonicalize();
          } else {
            ring.push_back({decimalFromDouble(x), decimalFromDouble(y)});
          }
        }
        if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
        if (r == 0) reg.outer = std::move(ring);
        else reg.holes.push_back(std::move(ring));
      }
      w.regions.push_back(std::move(reg));
    }
    w.units = lonlat ? "m (projected from lon/lat)" : "m";
    checkWorkspace(w);
    normalise(w);
    return w;
  } catch (const nlohmann::json::exception& e) {  // a type not checked above: still bad input
    throw InputError(name, "", std::string("GeoJSON: ") + e.what());
  }
}
Workspace readGeoJson(const std::string& path) { return parseGeoJson(readFile(path), path); }

// ---------------------------------------------------------------- text grid
Workspace parseTextGrid(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> rows;
  Rational res = 1, ox = 0, oy = 0;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == ';') continue;  // comment
    const std::string place = "line " + std::to_string(lineNo);
    if (line.rfind("resolution", 0) == 0) {
      res = parseRational(line.substr(line.find(' ') == std::string::npos ? line.size() : line.find(' ')), name, place);
      if (res <= 0) throw InputError(name, place, "resolution must be > 0");
      continue;
    }
    if (line.rfind("origin", 0) == 0) {
      std::istringstream ls(line.substr(6));
      std::string a, b;
      ls >> a >> b;
      ox = parseRational(a, name, place);
      oy = parseRational(b, name, place);
      continue;
    }
    for (std::size_t c = 0; c < line.size(); ++c)
      if (line[c] != '.' && line[c] != '#')
        throw InputError(name, place + " column " + std::to_string(c + 1), std::string("unknown cell '") + line[c] + "' (use '.' free, '#' blocked)");
    if (!rows.empty() && line.size() != rows.front().size())
      throw InputError(name, place, "row has " + std::to_string(line.size()) + " cells, the first row " + std::to_string(rows.front().size()));
    rows.push_back(line);
  }
  if (rows.empty()) throw InputError(name, "", "no grid rows");
  checkGridSize(name, "", static_cast<std::int64_t>(rows.front().size()), static_cast<std::int64_t>(rows.size()));
  OccupancyGrid g;
  g.height = static_cast<int>(rows.size());
  g.width = static_cast<int>(rows.front().size());
  g.resolution = res;
  g.originX = ox;
  g.originY = oy;
  g.blocked.resize(static_cast<std::size_t>(g.width) * g.height);
  for (int i = 0; i < g.height; ++i)
    for (int j = 0; j < g.width; ++j)
      g.blocked[static_cast<std::size_t>(g.height - 1 - i) * g.width + j] = rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] == '#';
  Workspace w = gridToWorkspace(g, name);
  if (w.regions.empty()) throw InputError(name, "", "empty free space: no '.' cell");
  return w;
}
Workspace readTextGrid(const std::string& path) { return parseTextGrid(readFile(path), path); }

}  // namespace coverkit::datasets
