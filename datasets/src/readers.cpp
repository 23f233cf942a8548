// Map readers: ROS map_server, Moving AI, WKT, GeoJSON, coverkit text grid.
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/error.h>

#include <nlohmann/json.hpp>
#include <png.h>
#include <yaml-cpp/yaml.h>

#include <cctype>
#include <cstring>
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

/// A grey image: value per pixel (0..255), alpha (0..255); row 0 at the TOP as in the file.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> value, alpha;
};

Image readPgm(const std::string& path) {
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
    long v = 0;
    while (p < data.size() && std::isdigit(static_cast<unsigned char>(data[p]))) {
      v = v * 10 + (data[p++] - '0');
      if (v > 1'000'000'000L) throw bad(std::string("PGM ") + what + " too large");
    }
    return v;
  };
  Image im;
  const long w = number("width"), h = number("height"), maxv = number("maxval");
  if (w <= 0 || h <= 0 || w * h > 400'000'000L) throw InputError(path, "header", "bad PGM size " + std::to_string(w) + "x" + std::to_string(h));
  if (maxv <= 0 || maxv > 65535) throw InputError(path, "header", "bad PGM maxval " + std::to_string(maxv));
  im.width = static_cast<int>(w);
  im.height = static_cast<int>(h);
  const std::size_t n = static_cast<std::size_t>(w * h);
  im.value.resize(n);
  im.alpha.assign(n, 255);
  if (binary) {
    ++p;  // exactly one whitespace after maxval
    const std::size_t bpp = maxv > 255 ? 2 : 1;
    if (data.size() < p + n * bpp)
      throw InputError(path, "pixel data", "truncated PGM: " + std::to_string((data.size() - std::min(data.size(), p)) / bpp) + " of " + std::to_string(n) + " pixels");
    for (std::size_t i = 0; i < n; ++i) {
      long v = bpp == 1 ? static_cast<unsigned char>(data[p + i]) : (static_cast<unsigned char>(data[p + 2 * i]) << 8 | static_cast<unsigned char>(data[p + 2 * i + 1]));
      im.value[i] = static_cast<std::uint8_t>(std::lround(255.0 * v / maxv));
    }
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      long v = number("pixel");
      if (v > maxv) throw bad("pixel value above maxval");
      im.value[i] = static_cast<std::uint8_t>(std::lround(255.0 * v / maxv));
    }
  }
  return im;
}

Image readPng(const std::string& path) {
  const std::string data = readFile(path);
  if (data.size() < 8 || png_sig_cmp(reinterpret_cast<png_const_bytep>(data.data()), 0, 8))
    throw InputError(path, "header", "not a PNG image");
  png_image img;
  std::memset(&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&img, data.data(), data.size()))
    throw InputError(path, "header", std::string("unreadable PNG: ") + img.message);
  img.format = PNG_FORMAT_GA;  // grey + alpha; colour is converted by libpng (sRGB luminance)
  std::vector<std::uint8_t> buf(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, nullptr, buf.data(), 0, nullptr)) {
    std::string msg = img.message;
    png_image_free(&img);
    throw InputError(path, "pixel data", "truncated or corrupt PNG: " + msg);
  }
  Image im;
  im.width = static_cast<int>(img.width);
  im.height = static_cast<int>(img.height);
  const std::size_t n = static_cast<std::size_t>(im.width) * im.height;
  im.value.resize(n);
  im.alpha.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    im.value[i] = buf[2 * i];
    im.alpha[i] = buf[2 * i + 1];
  }
  return im;
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

Workspace readRosMap(const std::string& yamlPath, const MapOptions& options) {
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
  if (y["origin"]) {
    const YAML::Node o = y["origin"];
    if (!o.IsSequence() || o.size() < 2) throw InputError(yamlPath, "origin", "expected [x, y, yaw]");
    ox = yamlNumber(o[0], yamlPath, "origin[0]");
    oy = yamlNumber(o[1], yamlPath, "origin[1]");
    if (o.size() > 2 && yamlNumber(o[2], yamlPath, "origin[2]") != 0)
      throw InputError(yamlPath, "origin[2]", "a rotated map (yaw != 0) is not supported");
  }
  bool negate = false;
  if (y["negate"]) {
    const std::string v = y["negate"].IsScalar() ? y["negate"].Scalar() : "";
    negate = v == "true" || v == "True" ? true : v == "false" || v == "False" ? false : yamlNumber(y["negate"], yamlPath, "negate") != 0;
  }
  const Rational occ = y["occupied_thresh"] ? yamlNumber(y["occupied_thresh"], yamlPath, "occupied_thresh") : ratio(65, 100);
  const Rational fre = y["free_thresh"] ? yamlNumber(y["free_thresh"], yamlPath, "free_thresh") : ratio(196, 1000);
  if (occ < 0 || occ > 1 || fre < 0 || fre > 1 || fre > occ) throw InputError(yamlPath, "free_thresh/occupied_thresh", "must satisfy 0 <= free_thresh <= occupied_thresh <= 1");
  const std::string mode = y["mode"] ? y["mode"].Scalar() : "trinary";
  if (mode != "trinary" && mode != "scale" && mode != "raw") throw InputError(yamlPath, "mode", "unknown mode '" + mode + "'");
  fs::path img = y["image"].Scalar();
  if (img.is_relative()) img = fs::path(yamlPath).parent_path() / img;
  const std::string ext = lower(img.extension().string());
  std::error_code ec;
  if (!fs::exists(img, ec)) throw InputError(yamlPath, "image", "image file '" + img.string() + "' not found");
  Image im;
  if (ext == ".png") im = readPng(img.string());
  else if (ext == ".pgm") im = readPgm(img.string());
  else throw InputError(yamlPath, "image", "unsupported image type '" + ext + "' (PGM or PNG)");
  OccupancyGrid g;
  g.width = im.width;
  g.height = im.height;
  g.resolution = res;
  g.originX = ox;
  g.originY = oy;
  g.blocked.resize(static_cast<std::size_t>(g.width) * g.height);
  for (int i = 0; i < im.height; ++i)
    for (int j = 0; j < im.width; ++j) {
      const std::size_t k = static_cast<std::size_t>(i) * im.width + j;
      const int v = im.value[k];
      bool blocked;
      if (im.alpha[k] == 0) {
        blocked = !options.unknownIsFree;  // transparent: unknown
      } else if (mode == "raw") {
        blocked = v > 100 ? !options.unknownIsFree : ratio(v, 100) > occ;
      } else {
        // map_server: p = (255 - v) / 255 (negate flips); exact comparison with the thresholds
        const Rational p = negate ? ratio(v, 255) : ratio(255 - v, 255);
        if (p > occ) blocked = true;
        else if (p < fre) blocked = false;
        else blocked = !options.unknownIsFree;
      }
      // pixel (row i, col j) is the square origin + res·[j, j+1] × res·[H-1-i, H-i]
      g.blocked[static_cast<std::size_t>(im.height - 1 - i) * g.width + j] = blocked;
    }
  Workspace w = gridToWorkspace(g, yamlPath);
  if (w.regions.empty()) throw InputError(yamlPath, "image", "empty free space: no free pixel");
  return w;
}

Workspace readMovingAi(const std::string& path) {
  std::istringstream in(readFile(path));
  std::string line, key;
  int height = -1, width = -1;
  int lineNo = 0;
  auto header = [&](const char* want) {
    ++lineNo;
    if (!std::getline(in, line)) throw InputError(path, "line " + std::to_string(lineNo), std::string("truncated header: expected '") + want + "'");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream ls(line);
    ls >> key;
    if (key != want) throw InputError(path, "line " + std::to_string(lineNo), std::string("bad Moving AI header: expected '") + want + "', found '" + line + "'");
    return std::string(std::istreambuf_iterator<char>(ls), {});
  };
  header("type");
  auto dim = [&](const char* what) {
    std::string v = header(what);
    try {
      std::size_t used = 0;
      int x = std::stoi(v, &used);
      if (x <= 0 || x > 100000) throw std::out_of_range("");
      return x;
    } catch (...) {
      throw InputError(path, "line " + std::to_string(lineNo), std::string("bad ") + what + " '" + v + "'");
    }
  };
  height = dim("height");
  width = dim("width");
  header("map");
  OccupancyGrid g;
  g.width = width;
  g.height = height;
  g.blocked.resize(static_cast<std::size_t>(width) * height);
  for (int i = 0; i < height; ++i) {
    ++lineNo;
    if (!std::getline(in, line)) throw InputError(path, "line " + std::to_string(lineNo), "missing map row " + std::to_string(i + 1) + " of " + std::to_string(height));
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (static_cast<int>(line.size()) < width)
      throw InputError(path, "line " + std::to_string(lineNo), "row has " + std::to_string(line.size()) + " cells, width is " + std::to_string(width));
    for (int j = 0; j < width; ++j) {
      const char c = line[static_cast<std::size_t>(j)];
      bool blocked;
      if (c == '.' || c == 'G' || c == 'S') blocked = false;
      else if (c == '@' || c == 'O' || c == 'T' || c == 'W') blocked = true;
      else throw InputError(path, "line " + std::to_string(lineNo) + " column " + std::to_string(j + 1), std::string("unknown terrain '") + c + "'");
      g.blocked[static_cast<std::size_t>(height - 1 - i) * width + j] = blocked;
    }
  }
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
Workspace parseGeoJson(const std::string& text, const std::string& name) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(name, "byte " + std::to_string(e.byte), std::string("GeoJSON does not parse: ") + e.what());
  } catch (const nlohmann::json::exception& e) {
    throw InputError(name, "", std::string("GeoJSON does not parse: ") + e.what());
  }
  std::vector<std::pair<std::string, const nlohmann::json*>> polys;  // place, coordinates of one polygon
  std::function<void(const nlohmann::json&, const std::string&)> geometry = [&](const nlohmann::json& g, const std::string& place) {
    if (!g.is_object() || !g.contains("type")) throw InputError(name, place, "geometry without a type");
    const std::string type = g["type"].is_string() ? g["type"].get<std::string>() : "";
    if (type == "Polygon") {
      if (!g.contains("coordinates") || !g["coordinates"].is_array()) throw InputError(name, place, "Polygon without coordinates");
      polys.emplace_back(place, &g["coordinates"]);
    } else if (type == "MultiPolygon") {
      if (!g.contains("coordinates") || !g["coordinates"].is_array()) throw InputError(name, place, "MultiPolygon without coordinates");
      for (std::size_t i = 0; i < g["coordinates"].size(); ++i) polys.emplace_back(place + ".coordinates[" + std::to_string(i) + "]", &g["coordinates"][i]);
    } else if (type == "GeometryCollection") {
      for (std::size_t i = 0; i < g["geometries"].size(); ++i) geometry(g["geometries"][i], place + ".geometries[" + std::to_string(i) + "]");
    } else {
      throw InputError(name, place, "unsupported geometry type '" + type + "' (Polygon or MultiPolygon)");
    }
  };
  const std::string type = j.is_object() && j.contains("type") && j["type"].is_string() ? j["type"].get<std::string>() : "";
  if (type == "FeatureCollection") {
    if (!j.contains("features") || !j["features"].is_array()) throw InputError(name, "features", "missing");
    for (std::size_t i = 0; i < j["features"].size(); ++i) {
      const auto& f = j["features"][i];
      if (!f.is_object() || !f.contains("geometry") || f["geometry"].is_null()) continue;
      geometry(f["geometry"], "features[" + std::to_string(i) + "].geometry");
    }
  } else if (type == "Feature") {
    geometry(j["geometry"], "geometry");
  } else {
    geometry(j, "geometry");
  }
  if (polys.empty()) throw InputError(name, "", "no Polygon in the GeoJSON: empty free space");
  // Collect raw doubles first to decide the frame.
  struct RawRing {
    std::vector<std::pair<double, double>> pts;
  };
  std::vector<std::vector<RawRing>> raw;
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for (auto& [place, coords] : polys) {
    std::vector<RawRing> rings;
    for (std::size_t r = 0; r < coords->size(); ++r) {
      const auto& ring = (*coords)[r];
      if (!ring.is_array()) throw InputError(name, place + "[" + std::to_string(r) + "]", "ring is not an array");
      RawRing rr;
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const auto& pt = ring[k];
        const std::string at = place + "[" + std::to_string(r) + "][" + std::to_string(k) + "]";
        if (!pt.is_array() || pt.size() < 2 || !pt[0].is_number() || !pt[1].is_number()) throw InputError(name, at, "position is not [x, y]");
        const double x = pt[0].get<double>(), y = pt[1].get<double>();
        if (!std::isfinite(x) || !std::isfinite(y)) throw InputError(name, at, "non-finite coordinate");
        rr.pts.emplace_back(x, y);
        xmin = std::min(xmin, x); xmax = std::max(xmax, x); ymin = std::min(ymin, y); ymax = std::max(ymax, y);
      }
      rings.push_back(std::move(rr));
    }
    raw.push_back(std::move(rings));
  }
  // Frame: longitude/latitude (RFC 7946) when every position is a valid WGS84 position and the extent
  // is below half a degree; otherwise the numbers are taken as metric coordinates as they are.
  // A "crs" member (GeoJSON 2008) decides when present: CRS84 / EPSG:4326 are longitude/latitude,
  // any other named CRS is taken as metric coordinates.
  int crsSaysLonLat = -1;
  if (j.is_object() && j.contains("crs") && j["crs"].is_object()) {
    const std::string crs = j["crs"].dump();
    crsSaysLonLat = (crs.find("CRS84") != std::string::npos || crs.find("4326") != std::string::npos) ? 1 : 0;
  }
  const bool inRange = xmin >= -180 && xmax <= 180 && ymin >= -90 && ymax <= 90;
  const bool lonlat = crsSaysLonLat == 1 ? inRange
                      : crsSaysLonLat == 0 ? false
                                           : inRange && (xmax - xmin) < 0.5 && (ymax - ymin) < 0.5;
  if (crsSaysLonLat == 1 && !inRange) throw InputError(name, "crs", "longitude/latitude CRS but positions out of range");
  const double lon0 = (xmin + xmax) / 2, lat0 = (ymin + ymax) / 2;
  constexpr double kEarth = 6371008.8;  // mean Earth radius (m)
  Workspace w;
  w.name = name;
  for (std::size_t pi = 0; pi < raw.size(); ++pi) {
    Region reg;
    for (std::size_t r = 0; r < raw[pi].size(); ++r) {
      Ring ring;
      for (auto [x, y] : raw[pi][r].pts) {
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
