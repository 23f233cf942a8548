// The HTML report of an experiment's output folder. See report.h and docs/experiments.md.
#include "report.h"

#include "engine.h"

#include <coverkit/geometry/error.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <locale>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace coverkit::experiments {

namespace {

namespace fs = std::filesystem;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ---- text ------------------------------------------------------------------------------------------

/// Text for HTML and SVG (element content and quoted attribute values).
std::string esc(const std::string& s) {
  std::string o;
  o.reserve(s.size() + s.size() / 8);
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      case '\'': o += "&#39;"; break;
      case '\0': o += "\xEF\xBF\xBD"; break;   // U+FFFD
      default: o += c;
    }
  }
  return o;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

/// At most n characters (UTF-8 code points), with an ellipsis when cut.
std::string clip(const std::string& s, std::size_t n) {
  std::size_t chars = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if ((static_cast<unsigned char>(s[i]) & 0xC0) == 0x80) continue;
    if (chars == n) return s.substr(0, i) + "\xE2\x80\xA6";
    ++chars;
  }
  return s;
}

std::size_t codePoints(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return n;
}

/// A fixed-point number in the C locale, never "-0".
std::string fixed(double v, int decimals) {
  if (std::fabs(v) * std::pow(10.0, decimals) < 0.5) v = 0;
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os << std::fixed << std::setprecision(decimals) << v;
  return os.str();
}

/// A coordinate in an SVG.
std::string px(double v) { return fixed(v, 1); }

/// A number for a table: about four significant digits, no trailing zeros.
std::string shortNumber(double v) {
  if (!std::isfinite(v)) return "";
  if (v == 0) return "0";
  const int mag = static_cast<int>(std::floor(std::log10(std::fabs(v))));
  if (mag >= 15 || mag < -6) {
    std::ostringstream os;
    os.imbue(std::locale::classic());
    os << std::setprecision(4) << v;
    return os.str();
  }
  std::string s = fixed(v, std::clamp(3 - mag, 0, 6));
  if (s.find('.') != std::string::npos) {
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
  }
  return s;
}

/// A whole number written in decimal (C locale), e.g. "0.25", "3", "-1e3"; finite only.
bool parseNumber(const std::string& text, double& v) {
  const std::string s = trim(text);
  if (s.empty()) return false;
  std::istringstream is(s);
  is.imbue(std::locale::classic());
  is >> v;
  return !is.fail() && is.peek() == std::char_traits<char>::eof() && std::isfinite(v);
}

/// A name usable as a file name: letters, digits, '_', '-', '.'; other bytes become '_'.
std::string safeName(const std::string& s) {
  std::string o;
  for (char c : s) o += std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' ? c : '_';
  if (o.empty() || o[0] == '.') o = "_" + o;
  return o;
}

/// A file of the folder, or nothing when it does not exist.
std::optional<std::string> readOptional(const fs::path& p) {
  std::error_code ec;
  if (!fs::exists(p, ec)) return std::nullopt;
  if (!fs::is_regular_file(p, ec)) throw InputError(p.string(), "", "exists and is not a file");
  std::ifstream in(p, std::ios::binary);
  if (!in) throw InputError(p.string(), "", "cannot be read");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::string line;
  std::istringstream is(text);
  while (std::getline(is, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

/// The value of config.yaml's top-level `title:` line, unquoted ("" when there is none).
std::string configTitle(const std::string& yaml) {
  for (const std::string& line : splitLines(yaml)) {
    if (line.rfind("title:", 0) != 0) continue;
    std::string v = trim(line.substr(6));
    if (!v.empty() && (v[0] == '"' || v[0] == '\'')) {
      const char q = v[0];
      std::string out;
      for (std::size_t i = 1; i < v.size(); ++i) {
        if (q == '\'' && v[i] == '\'' && i + 1 < v.size() && v[i + 1] == '\'') out += '\'', ++i;
        else if (q == '"' && v[i] == '\\' && i + 1 < v.size()) out += v[++i];
        else if (v[i] == q) break;
        else out += v[i];
      }
      return out;
    }
    const auto hash = v.find(" #");
    if (hash != std::string::npos) v = trim(v.substr(0, hash));
    return v.rfind('#', 0) == 0 ? "" : v;
  }
  return "";
}

// ---- the table -------------------------------------------------------------------------------------

bool isNumeric(const Column& c) { return c.type != ColumnType::kText; }

/// A cell as a double: NaN for text.
double number(const Value& v) {
  if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  if (const auto* d = std::get_if<double>(&v)) return *d;
  return kNaN;
}

/// A cell as it is written in results.csv.
std::string cellText(const Table& t, const Row& r, std::size_t c) {
  const Value& v = r[c];
  if (const auto* s = std::get_if<std::string>(&v)) return *s;
  if (const auto* i = std::get_if<std::int64_t>(&v)) return std::to_string(*i);
  return t.text(r, t.columns[c].name);   // the engine's shortest exact form
}

/// A time column: the engine's timing columns and the experiments' *_seconds.
bool isTime(const std::string& name) {
  return isTimingColumn(name) || (name.size() > 8 && name.compare(name.size() - 8, 8, "_seconds") == 0);
}

/// Rows grouped into series (planner) and x positions (value).
struct Grouping {
  std::vector<std::string> series;   ///< first-appearance order
  std::vector<std::string> xs;       ///< numeric order when numeric, else first-appearance order
  std::vector<double> xValues;       ///< when numeric
  bool numeric = false;              ///< a line chart (two or more x values, all numbers)
  std::string xLabel;
  std::vector<std::size_t> rowSeries, rowX;
};

Grouping groupRows(const Table& t) {
  Grouping g;
  const int pc = t.column("planner"), vc = t.column("value"), yc = t.column("vary");
  std::map<std::string, std::size_t> seriesIndex;
  std::vector<std::string> xsFirst;
  std::set<std::string> xsSeen, varies;
  std::vector<std::string> rowSeriesName, rowXName;
  for (const Row& r : t.rows) {
    const std::string s = pc >= 0 ? cellText(t, r, static_cast<std::size_t>(pc)) : "all rows";
    const std::string x = vc >= 0 ? cellText(t, r, static_cast<std::size_t>(vc)) : "all rows";
    if (seriesIndex.emplace(s, g.series.size()).second) g.series.push_back(s);
    if (xsSeen.insert(x).second) xsFirst.push_back(x);
    g.rowSeries.push_back(seriesIndex[s]);
    rowXName.push_back(x);
    if (yc >= 0) varies.insert(cellText(t, r, static_cast<std::size_t>(yc)));
  }
  std::vector<double> values(xsFirst.size());
  bool allNumbers = vc >= 0 && xsFirst.size() >= 2;
  for (std::size_t i = 0; i < xsFirst.size() && allNumbers; ++i) allNumbers = parseNumber(xsFirst[i], values[i]);
  g.numeric = allNumbers;
  std::vector<std::size_t> order(xsFirst.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  if (g.numeric) std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  std::map<std::string, std::size_t> xIndex;
  for (std::size_t k = 0; k < order.size(); ++k) {
    g.xs.push_back(xsFirst[order[k]]);
    if (g.numeric) g.xValues.push_back(values[order[k]]);
    xIndex[xsFirst[order[k]]] = k;
  }
  for (const std::string& x : rowXName) g.rowX.push_back(xIndex[x]);
  if (vc < 0) {
    g.xLabel = "";   // one group of all rows
  } else if (!varies.empty()) {
    for (const std::string& v : varies) g.xLabel += (g.xLabel.empty() ? "" : ", ") + v;
  } else {
    g.xLabel = "value";
  }
  return g;
}

/// The mean of column c per series and x position (NaN where there is no finite value).
std::vector<std::vector<double>> means(const Table& t, const Grouping& g, std::size_t c) {
  std::vector<std::vector<double>> sum(g.series.size(), std::vector<double>(g.xs.size(), 0.0)), n = sum;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const double v = number(t.rows[i][c]);
    if (!std::isfinite(v)) continue;
    sum[g.rowSeries[i]][g.rowX[i]] += v;
    n[g.rowSeries[i]][g.rowX[i]] += 1;
  }
  for (std::size_t s = 0; s < sum.size(); ++s)
    for (std::size_t x = 0; x < sum[s].size(); ++x) sum[s][x] = n[s][x] > 0 ? sum[s][x] / n[s][x] : kNaN;
  return sum;
}

// ---- charts ----------------------------------------------------------------------------------------

const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
const char* const kDashes[] = {"", "6 3", "2 3", "8 3 2 3"};

struct Ticks {
  double lo = 0, hi = 1;
  std::vector<double> values;
  int decimals = 0;
};

/// About five round tick values covering [lo, hi].
Ticks niceTicks(double lo, double hi) {
  if (!(hi > lo)) {
    const double d = lo == 0 ? 1 : std::fabs(lo) * 0.1;
    lo -= d;
    hi += d;
  }
  const double raw = (hi - lo) / 5, mag = std::pow(10.0, std::floor(std::log10(raw))), f = raw / mag;
  const double step = (f <= 1 ? 1 : f <= 2 ? 2 : f <= 2.5 ? 2.5 : f <= 5 ? 5 : 10) * mag;
  const long long a = static_cast<long long>(std::floor(lo / step + 1e-9)), b = static_cast<long long>(std::ceil(hi / step - 1e-9));
  Ticks t;
  for (long long k = a; k <= b && k - a <= 50; ++k) t.values.push_back(static_cast<double>(k) * step);
  t.lo = t.values.front();
  t.hi = std::max(t.values.back(), t.lo + step);
  while (t.decimals < 12) {
    const double scaled = step * std::pow(10.0, t.decimals);
    if (std::fabs(scaled - std::round(scaled)) < 1e-6 * std::max(1.0, scaled)) break;
    ++t.decimals;
  }
  return t;
}

/// One chart: the mean per series against x, a line chart (numeric x) or bar groups.
std::string chartSvg(const Grouping& g, const std::string& title, const std::string& yLabel, const std::vector<std::vector<double>>& mean) {
  const std::size_t ns = g.series.size(), nx = g.xs.size();
  std::size_t longest = 0;
  for (const std::string& s : g.series) longest = std::max(longest, std::min<std::size_t>(28, codePoints(s)));
  const int legendW = std::clamp(static_cast<int>(34 + 7 * longest), 90, 240);
  const int ml = 78, mt = 48, mb = 62, plotW = g.numeric ? 480 : std::max(480, static_cast<int>(nx * std::max<std::size_t>(56, ns * 14 + 24)));
  const int plotH = std::max(260, static_cast<int>(18 * ns) + 10), W = ml + plotW + legendW + 24, H = mt + plotH + mb;
  double lo = g.numeric ? 1e300 : 0, hi = g.numeric ? -1e300 : 0;
  for (const auto& row : mean)
    for (double v : row)
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  const Ticks yt = niceTicks(lo, hi);
  auto sy = [&](double v) { return mt + plotH - (v - yt.lo) / (yt.hi - yt.lo) * plotH; };
  const int bottom = mt + plotH;
  std::ostringstream o;
  o << "<svg class=\"chart\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 " << W << ' ' << H
    << "\" role=\"img\" aria-label=\"" << esc(title) << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
    << "<title>" << esc(title) << "</title>\n<rect width=\"" << W << "\" height=\"" << H << "\" fill=\"#ffffff\"/>\n"
    << "<text x=\"" << ml + plotW / 2 << "\" y=\"26\" text-anchor=\"middle\" font-size=\"15\" font-weight=\"bold\">" << esc(title) << "</text>\n";
  for (double v : yt.values) {
    const std::string y = px(sy(v));
    o << "<line x1=\"" << ml << "\" x2=\"" << ml + plotW << "\" y1=\"" << y << "\" y2=\"" << y << "\" stroke=\"#e4e4e4\"/>"
      << "<line x1=\"" << ml - 5 << "\" x2=\"" << ml << "\" y1=\"" << y << "\" y2=\"" << y << "\" stroke=\"#333333\"/>"
      << "<text x=\"" << ml - 8 << "\" y=\"" << px(sy(v) + 4) << "\" text-anchor=\"end\">" << fixed(v, yt.decimals) << "</text>\n";
  }
  o << "<text transform=\"translate(18 " << mt + plotH / 2 << ") rotate(-90)\" text-anchor=\"middle\">" << esc(yLabel) << "</text>\n";
  if (!g.xLabel.empty()) o << "<text x=\"" << ml + plotW / 2 << "\" y=\"" << H - 14 << "\" text-anchor=\"middle\">" << esc(g.xLabel) << "</text>\n";
  // a point's or bar's tooltip
  auto tip = [&](std::size_t s, std::size_t x) {
    return "<title>" + esc(g.series[s]) + ", " + (g.xLabel.empty() ? std::string() : esc(g.xLabel) + " ") + esc(g.xs[x]) + ": " + shortNumber(mean[s][x]) + "</title>";
  };
  if (g.numeric) {
    const Ticks xt = niceTicks(g.xValues.front(), g.xValues.back());
    auto sx = [&](double v) { return ml + (v - xt.lo) / (xt.hi - xt.lo) * plotW; };
    for (double v : xt.values)
      o << "<line x1=\"" << px(sx(v)) << "\" x2=\"" << px(sx(v)) << "\" y1=\"" << bottom << "\" y2=\"" << bottom + 5 << "\" stroke=\"#333333\"/>"
        << "<text x=\"" << px(sx(v)) << "\" y=\"" << bottom + 19 << "\" text-anchor=\"middle\">" << fixed(v, xt.decimals) << "</text>\n";
    for (std::size_t s = 0; s < ns; ++s) {
      const char* colour = kColours[s % 10];
      const char* dash = kDashes[s / 10 % 4];
      std::string points;
      std::size_t count = 0;
      for (std::size_t x = 0; x < nx; ++x)
        if (std::isfinite(mean[s][x])) points += (count++ ? " " : "") + px(sx(g.xValues[x])) + "," + px(sy(mean[s][x]));
      if (count > 1)
        o << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\"" << (*dash ? std::string(" stroke-dasharray=\"") + dash + "\"" : "")
          << " points=\"" << points << "\"/>\n";
      for (std::size_t x = 0; x < nx; ++x)
        if (std::isfinite(mean[s][x]))
          o << "<circle cx=\"" << px(sx(g.xValues[x])) << "\" cy=\"" << px(sy(mean[s][x])) << "\" r=\"3.5\" fill=\"" << colour << "\">" << tip(s, x)
            << "</circle>\n";
    }
  } else {
    const double gw = static_cast<double>(plotW) / static_cast<double>(std::max<std::size_t>(1, nx));
    const double bw = std::min(60.0, gw * 0.75 / static_cast<double>(std::max<std::size_t>(1, ns)));
    const double inset = (gw - bw * static_cast<double>(ns)) / 2;
    const std::size_t maxChars = static_cast<std::size_t>(std::max(4.0, gw / 7.5));
    const double zero = sy(std::clamp(0.0, yt.lo, yt.hi));
    for (std::size_t x = 0; x < nx; ++x) {
      const double left = ml + gw * static_cast<double>(x);
      o << "<text x=\"" << px(left + gw / 2) << "\" y=\"" << bottom + 19 << "\" text-anchor=\"middle\"><title>" << esc(g.xs[x]) << "</title>"
        << esc(clip(g.xs[x], maxChars)) << "</text>\n";
      for (std::size_t s = 0; s < ns; ++s) {
        if (!std::isfinite(mean[s][x])) continue;
        const double y = sy(mean[s][x]);
        o << "<rect x=\"" << px(left + inset + bw * static_cast<double>(s)) << "\" y=\"" << px(std::min(y, zero)) << "\" width=\"" << px(bw)
          << "\" height=\"" << px(std::fabs(zero - y)) << "\" fill=\"" << kColours[s % 10] << "\">" << tip(s, x)
          << "</rect>\n";
      }
    }
    o << "<line x1=\"" << ml << "\" x2=\"" << ml + plotW << "\" y1=\"" << px(zero) << "\" y2=\"" << px(zero) << "\" stroke=\"#333333\"/>\n";
  }
  o << "<line x1=\"" << ml << "\" y1=\"" << mt << "\" x2=\"" << ml << "\" y2=\"" << bottom << "\" stroke=\"#333333\"/>"
    << "<line x1=\"" << ml << "\" y1=\"" << bottom << "\" x2=\"" << ml + plotW << "\" y2=\"" << bottom << "\" stroke=\"#333333\"/>\n";
  const int lx = ml + plotW + 20;
  for (std::size_t s = 0; s < ns; ++s) {
    const int y = mt + 4 + 18 * static_cast<int>(s);
    const char* colour = kColours[s % 10];
    const char* dash = kDashes[s / 10 % 4];
    if (g.numeric)
      o << "<line x1=\"" << lx << "\" x2=\"" << lx + 22 << "\" y1=\"" << y + 6 << "\" y2=\"" << y + 6 << "\" stroke=\"" << colour << "\" stroke-width=\"2\""
        << (*dash ? std::string(" stroke-dasharray=\"") + dash + "\"" : "") << "/><circle cx=\"" << lx + 11 << "\" cy=\"" << y + 6 << "\" r=\"3.5\" fill=\""
        << colour << "\"/>";
    else
      o << "<rect x=\"" << lx + 5 << "\" y=\"" << y << "\" width=\"12\" height=\"12\" fill=\"" << colour << "\"/>";
    o << "<text x=\"" << lx + 28 << "\" y=\"" << y + 10 << "\"><title>" << esc(g.series[s]) << "</title>" << esc(clip(g.series[s], 28)) << "</text>\n";
  }
  o << "</svg>\n";
  return o.str();
}

// ---- HTML pieces -----------------------------------------------------------------------------------

/// A sortable table: header cells, then rows; cells whose column is numeric are right-aligned.
std::string htmlTable(const std::vector<std::string>& head, const std::vector<std::vector<std::string>>& rows, const std::vector<bool>& numeric = {}) {
  std::ostringstream o;
  o << "<table class=\"sortable\">\n<thead><tr>";
  for (const std::string& h : head) o << "<th>" << esc(h) << "</th>";
  o << "</tr></thead>\n<tbody>\n";
  for (const auto& r : rows) {
    o << "<tr>";
    for (std::size_t i = 0; i < std::max(r.size(), head.size()); ++i) {
      const std::string cell = i < r.size() ? r[i] : "";
      o << (i < numeric.size() && numeric[i] ? "<td class=\"num\">" : "<td>") << esc(cell) << "</td>";
    }
    o << "</tr>\n";
  }
  o << "</tbody>\n</table>\n";
  return o.str();
}

/// The cells of a Markdown table row `| a | b |` (`\|` is a bar inside a cell).
std::vector<std::string> markdownCells(const std::string& line) {
  std::string s = trim(line);
  if (!s.empty() && s[0] == '|') s.erase(0, 1);
  if (!s.empty() && s.back() == '|' && (s.size() < 2 || s[s.size() - 2] != '\\')) s.pop_back();
  std::vector<std::string> cells;
  std::string cur;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\' && i + 1 < s.size() && s[i + 1] == '|') cur += '|', ++i;
    else if (s[i] == '|') cells.push_back(trim(cur)), cur.clear();
    else cur += s[i];
  }
  cells.push_back(trim(cur));
  return cells;
}

bool isSeparatorRow(const std::string& line) {
  const std::string s = trim(line);
  return s.find('-') != std::string::npos && s.find_first_not_of("|-: \t") == std::string::npos;
}

/// summary.md as HTML: its tables as tables, headings as headings, other lines as paragraphs.
std::string markdownHtml(const std::string& md) {
  const std::vector<std::string> lines = splitLines(md);
  std::ostringstream o;
  std::string para;
  auto flush = [&] {
    if (!para.empty()) o << "<p>" << esc(para) << "</p>\n";
    para.clear();
  };
  for (std::size_t i = 0; i < lines.size();) {
    const std::string line = trim(lines[i]);
    if (line.rfind('|', 0) == 0) {
      flush();
      std::vector<std::string> block;
      while (i < lines.size() && trim(lines[i]).rfind('|', 0) == 0) block.push_back(lines[i++]);
      std::vector<std::vector<std::string>> rows;
      for (std::size_t k = 1; k < block.size(); ++k)
        if (!(k == 1 && isSeparatorRow(block[k]))) rows.push_back(markdownCells(block[k]));
      std::vector<bool> numeric;
      const std::vector<std::string> head = markdownCells(block[0]);
      for (std::size_t c = 0; c < head.size(); ++c) {
        bool all = !rows.empty();
        double v = 0;
        for (const auto& r : rows) all = all && (c >= r.size() || r[c].empty() || parseNumber(r[c], v));
        numeric.push_back(all);
      }
      o << "<div class=\"scroll\">" << htmlTable(head, rows, numeric) << "</div>\n";
      continue;
    }
    if (line.empty()) {
      flush();
    } else if (line[0] == '#') {
      flush();
      o << "<h3>" << esc(trim(line.substr(line.find_first_not_of('#')))) << "</h3>\n";
    } else {
      para += (para.empty() ? "" : "\n") + line;
    }
    ++i;
  }
  flush();
  return o.str();
}

/// The attributes of a start tag's text (after the name): name → raw value (with its quote).
struct Attribute {
  std::string name, value;
  char quote = 0;   ///< 0: no value
};

std::vector<Attribute> parseAttributes(const std::string& s) {
  std::vector<Attribute> attrs;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (std::isspace(static_cast<unsigned char>(s[i])) || s[i] == '/')) ++i;
    if (i >= s.size()) break;
    Attribute a;
    while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i])) && s[i] != '=' && s[i] != '/') a.name += s[i++];
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i < s.size() && s[i] == '=') {
      ++i;
      while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
      if (i < s.size() && (s[i] == '"' || s[i] == '\'')) {
        a.quote = s[i];
        const auto end = s.find(a.quote, i + 1);
        a.value = s.substr(i + 1, end == std::string::npos ? std::string::npos : end - i - 1);
        i = end == std::string::npos ? s.size() : end + 1;
      } else {
        a.quote = '"';
        while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) a.value += s[i++];
      }
    }
    if (!a.name.empty()) attrs.push_back(a);
    else ++i;
  }
  return attrs;
}

std::string prefixUrls(const std::string& s, const std::string& prefix) {
  std::string o;
  std::size_t i = 0;
  for (std::size_t k; (k = s.find("url(#", i)) != std::string::npos; i = k + 5) o += s.substr(i, k + 5 - i) + prefix;
  return o + s.substr(i);
}

/// An SVG file made fit to be inlined: from its <svg> to its </svg>, without scripts, foreign
/// objects or event attributes, its ids (and the references to them) prefixed so that several
/// pictures on one page do not share ids. Empty when the file holds no <svg> element.
std::string inlineSvg(const std::string& text, const std::string& prefix) {
  const std::string low = lower(text);
  const auto start = low.find("<svg"), end = low.rfind("</svg>");
  if (start == std::string::npos || end == std::string::npos || end < start) return "";
  std::string o;
  std::size_t i = start;
  while (i < end + 6) {
    const auto lt = text.find('<', i);
    if (lt == std::string::npos || lt >= end + 6) break;
    o += prefixUrls(text.substr(i, lt - i), prefix);
    if (low.compare(lt, 4, "<!--") == 0 || low.compare(lt, 9, "<![cdata[") == 0) {
      const bool comment = low[lt + 2] == '-';
      const auto close = text.find(comment ? "-->" : "]]>", lt);
      const std::size_t next = close == std::string::npos ? end + 6 : close + 3;
      if (!comment) o += prefixUrls(text.substr(lt, next - lt), prefix);   // e.g. a <style>'s text
      i = next;
      continue;
    }
    // the tag's end: the first '>' outside quotes
    std::size_t gt = lt + 1;
    for (char q = 0; gt < text.size() && (q || text[gt] != '>'); ++gt)
      if (q && text[gt] == q) q = 0;
      else if (!q && (text[gt] == '"' || text[gt] == '\'')) q = text[gt];
    if (gt >= text.size()) break;
    const bool closing = text[lt + 1] == '/';
    std::size_t n = lt + (closing ? 2 : 1);
    while (n < gt && !std::isspace(static_cast<unsigned char>(text[n])) && text[n] != '/') ++n;
    const std::string name = text.substr(lt + (closing ? 2 : 1), n - lt - (closing ? 2 : 1)), lname = lower(name);
    const bool selfClosing = text[gt - 1] == '/';
    if (lname == "script" || lname == "foreignobject") {
      if (closing || selfClosing) {
        i = gt + 1;
      } else {
        const auto close = low.find("</" + lname, gt);
        const auto closeEnd = close == std::string::npos ? std::string::npos : text.find('>', close);
        i = closeEnd == std::string::npos ? end + 6 : closeEnd + 1;
      }
      continue;
    }
    if (closing || name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) {
      o += text.substr(lt, gt + 1 - lt);
      i = gt + 1;
      continue;
    }
    o += "<" + name;
    for (Attribute& a : parseAttributes(text.substr(n, gt - n - (selfClosing ? 1 : 0)))) {
      const std::string an = lower(a.name), av = lower(trim(a.value));
      if (an.rfind("on", 0) == 0 || av.rfind("javascript:", 0) == 0 || av.rfind("data:text/html", 0) == 0) continue;
      if (an == "id") a.value = prefix + a.value;
      else if ((an == "href" || an == "xlink:href") && a.value.rfind('#', 0) == 0) a.value = "#" + prefix + a.value.substr(1);
      else a.value = prefixUrls(a.value, prefix);
      o += " " + a.name;
      if (a.quote) o += "=" + std::string(1, a.quote) + a.value + std::string(1, a.quote);
    }
    o += selfClosing ? "/>" : ">";
    i = gt + 1;
  }
  return o + "\n";
}

const char* const kStyle = R"(
body { font-family: system-ui, -apple-system, "Segoe UI", sans-serif; margin: 0 auto; max-width: 1280px; padding: 0 1.5em 3em; color: #222; line-height: 1.45; }
header { border-bottom: 2px solid #1f77b4; margin-bottom: 1em; }
header h1 { margin: 0.6em 0 0.1em; }
header p { margin: 0 0 0.8em; color: #555; }
nav a { margin-right: 1em; }
h2 { margin-top: 1.8em; border-bottom: 1px solid #ddd; padding-bottom: 0.2em; }
table { border-collapse: collapse; font-size: 13px; margin: 0.5em 0 1em; }
th, td { border: 1px solid #d4d4d4; padding: 3px 8px; text-align: left; vertical-align: top; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
thead th { background: #f0f4f8; cursor: pointer; user-select: none; white-space: nowrap; position: sticky; top: 0; }
th[aria-sort="ascending"]::after { content: " \25B2"; }
th[aria-sort="descending"]::after { content: " \25BC"; }
tbody tr:nth-child(even) { background: #fafafa; }
.scroll { overflow: auto; max-width: 100%; }
.scroll.tall { max-height: 80vh; }
#results td { white-space: nowrap; }
.scroll.lazy { content-visibility: auto; contain-intrinsic-size: auto 80vh; }
pre { background: #f6f8fa; padding: 0.8em; overflow: auto; font-size: 13px; }
figure { display: inline-block; width: calc(50% - 1.2em); min-width: 420px; margin: 0.5em 1em 1em 0; vertical-align: top; }
figure.wide { width: calc(100% - 1.2em); }
figcaption { font-size: 12px; color: #555; }
svg.chart { width: 100%; height: auto; border: 1px solid #e4e4e4; }
.picture { display: inline-block; width: calc(50% - 1.2em); min-width: 420px; margin: 0 1em 1em 0; vertical-align: top; }
.picture h3 { font-size: 14px; margin: 0.4em 0; }
.picture svg { width: 100%; height: auto; border: 1px solid #e4e4e4; }
.note { color: #666; font-size: 13px; }
)";

// The page's script: sortable tables, then data-ready and data-charts on <body>.
const char* const kScript = R"(
(function () {
  "use strict";
  function cellText(row, i) {
    var c = row.cells[i];
    return c ? c.textContent.trim() : "";
  }
  function isNumber(s) {
    return s !== "" && isFinite(Number(s));
  }
  function sortBy(table, th) {
    var body = table.tBodies[0];
    if (!body) return;
    var col = th.cellIndex;
    var rows = Array.prototype.slice.call(body.rows);
    var numeric = rows.every(function (r) {
      var s = cellText(r, col);
      return s === "" || isNumber(s);
    });
    var dir = th.getAttribute("aria-sort") === "ascending" ? -1 : 1;
    Array.prototype.forEach.call(th.parentNode.cells, function (h) {
      h.removeAttribute("aria-sort");
    });
    th.setAttribute("aria-sort", dir === 1 ? "ascending" : "descending");
    var keyed = rows.map(function (r, k) {
      var s = cellText(r, col);
      return { row: r, k: k, key: numeric ? (s === "" ? -Infinity : Number(s)) : s };
    });
    keyed.sort(function (a, b) {
      var c = numeric ? (a.key < b.key ? -1 : a.key > b.key ? 1 : 0) : a.key.localeCompare(b.key, undefined, { numeric: true });
      return c !== 0 ? dir * c : a.k - b.k;
    });
    var frag = document.createDocumentFragment();
    keyed.forEach(function (e) {
      frag.appendChild(e.row);
    });
    body.appendChild(frag);
  }
  Array.prototype.forEach.call(document.querySelectorAll("table.sortable"), function (table) {
    var head = table.tHead;
    if (!head || !head.rows.length) return;
    Array.prototype.forEach.call(head.rows[head.rows.length - 1].cells, function (th) {
      th.tabIndex = 0;
      th.title = "sort by this column";
      th.addEventListener("click", function () {
        sortBy(table, th);
      });
      th.addEventListener("keydown", function (e) {
        if (e.key === "Enter" || e.key === " ") {
          e.preventDefault();
          sortBy(table, th);
        }
      });
    });
  });
  document.body.dataset.charts = String(document.querySelectorAll("svg.chart").length);
  document.body.dataset.ready = "1";
})();
)";

}  // namespace

std::vector<std::pair<std::string, std::string>> reportFiles(const std::string& dir) {
  const fs::path folder(dir);
  const Table t = readTable(dir);
  const std::string dbFile = (folder / "results.db").string();
  const int caseCol = t.column("case");
  if (caseCol < 0) throw InputError(dbFile, "columns", "the table has no 'case' column: not the results of a coverkit experiment");

  // the folder's other files, each optional
  const fs::path runFile = folder / "run.json";
  const std::optional<std::string> runText = readOptional(runFile), config = readOptional(folder / "config.yaml"),
                                   summary = readOptional(folder / "summary.md");
  nlohmann::ordered_json run = nlohmann::ordered_json::object();
  if (runText) {
    try {
      run = nlohmann::ordered_json::parse(*runText);
    } catch (const nlohmann::json::exception& e) {
      throw InputError(runFile.string(), "", std::string("not valid JSON: ") + e.what());
    }
    if (!run.is_object()) throw InputError(runFile.string(), "", "not a JSON object (the metadata of a run)");
  }
  std::vector<std::pair<std::string, std::string>> pictures;   // file name → inlined SVG
  const fs::path pictureDir = folder / "pictures";
  std::error_code ec;
  if (fs::is_directory(pictureDir, ec)) {
    std::vector<std::string> names;
    for (fs::directory_iterator it(pictureDir, ec), endIt; !ec && it != endIt; it.increment(ec))
      if (it->is_regular_file(ec) && lower(it->path().extension().string()) == ".svg") names.push_back(it->path().filename().string());
    if (ec) throw InputError(pictureDir.string(), "", "cannot be listed: " + ec.message());
    std::sort(names.begin(), names.end());
    for (std::size_t k = 0; k < names.size(); ++k)
      pictures.emplace_back(names[k], inlineSvg(*readOptional(pictureDir / names[k]), "pic" + std::to_string(k + 1) + "-"));
  }

  const std::string kind = run.contains("kind") && run["kind"].is_string() ? run["kind"].get<std::string>() : "";
  std::string title = config ? configTitle(*config) : "";
  if (title.empty() && summary)
    for (const std::string& line : splitLines(*summary))
      if (line.rfind("# ", 0) == 0) {
        title = trim(line.substr(2));
        break;
      }

  // charts
  const Grouping g = groupRows(t);
  auto numericColumn = [&](const std::string& name) {
    const int c = t.column(name);
    return c >= 0 && isNumeric(t.columns[static_cast<std::size_t>(c)]) ? c : -1;
  };
  // a planner's own time when the rows have it (a case's wall time is shared by its rows)
  int wallCol = numericColumn("plan_seconds");
  if (wallCol < 0) wallCol = numericColumn("wall_seconds");
  for (std::size_t c = 0; c < t.columns.size() && wallCol < 0; ++c)
    if (isNumeric(t.columns[c]) && isTime(t.columns[c].name) && t.columns[c].name != "peak_rss_mib") wallCol = static_cast<int>(c);
  // a metric column that is 0 in every row was not measured by this kind (e.g. the coverable region
  // of the grid experiments): no chart of it
  auto measured = [&](int c) {
    for (const Row& r : t.rows)
      if (t.real(r, t.columns[static_cast<std::size_t>(c)].name) != 0) return true;
    return false;
  };
  std::vector<std::size_t> metricCols;
  for (const char* name : {"coverable_coverage", "area_coverage", "subcell_coverage", "swept_area_overlap", "length", "turns", "turning_angle_deg"})
    if (numericColumn(name) >= 0 && measured(numericColumn(name))) metricCols.push_back(static_cast<std::size_t>(numericColumn(name)));
  if (metricCols.empty()) {
    const std::set<std::string> skip{"case", "row", "world", "repetition", "value"};
    for (std::size_t c = 0; c < t.columns.size(); ++c)
      if (isNumeric(t.columns[c]) && !skip.count(t.columns[c].name) && !isTime(t.columns[c].name) && static_cast<int>(c) != wallCol) metricCols.push_back(c);
  }
  struct Chart {
    std::string file, svg;
    bool wide = false;   ///< many bar groups: the page's whole width
  };
  std::vector<Chart> charts;
  std::set<std::string> chartFiles;
  auto addChart = [&](std::size_t c, const std::string& chartTitle, const std::string& yLabel) {
    const auto m = means(t, g, c);
    bool any = false;
    for (const auto& row : m)
      for (double v : row) any = any || std::isfinite(v);
    if (!any) return;
    std::string file = "charts/" + safeName(t.columns[c].name) + ".svg";
    for (int k = 2; chartFiles.count(file); ++k) file = "charts/" + safeName(t.columns[c].name) + "-" + std::to_string(k) + ".svg";
    chartFiles.insert(file);
    charts.push_back({file, chartSvg(g, chartTitle, yLabel, m), !g.numeric && g.xs.size() * std::max<std::size_t>(56, g.series.size() * 14 + 24) > 480});
  };
  for (std::size_t c : metricCols) addChart(c, "mean " + t.columns[c].name, t.columns[c].name);
  if (wallCol >= 0)
    addChart(static_cast<std::size_t>(wallCol), "mean wall time (" + t.columns[static_cast<std::size_t>(wallCol)].name + ")",
             t.columns[static_cast<std::size_t>(wallCol)].name + " (s)");

  // per planner
  std::vector<std::string> aggHead{t.column("planner") >= 0 ? "planner" : "group", "rows"};
  const int validCol = numericColumn("valid"), coverageCol = numericColumn("coverable_coverage"), lengthCol = numericColumn("length"),
            turnsCol = numericColumn("turns");
  if (validCol >= 0) aggHead.push_back("valid share");
  if (coverageCol >= 0) aggHead.insert(aggHead.end(), {"mean coverable_coverage", "min coverable_coverage"});
  if (lengthCol >= 0) aggHead.push_back("mean length");
  if (turnsCol >= 0) aggHead.push_back("mean turns");
  if (wallCol >= 0) aggHead.push_back("mean " + t.columns[static_cast<std::size_t>(wallCol)].name);
  std::vector<std::vector<std::string>> aggRows;
  for (std::size_t s = 0; s < g.series.size(); ++s) {
    std::size_t n = 0;
    auto stat = [&](int c, bool minimum) {
      double sum = 0, lowest = kNaN;
      std::size_t k = 0;
      for (std::size_t i = 0; i < t.rows.size(); ++i) {
        if (g.rowSeries[i] != s) continue;
        const double v = number(t.rows[i][static_cast<std::size_t>(c)]);
        if (!std::isfinite(v)) continue;
        sum += v, ++k;
        lowest = std::isnan(lowest) ? v : std::min(lowest, v);
      }
      return shortNumber(minimum ? lowest : k ? sum / static_cast<double>(k) : kNaN);
    };
    for (std::size_t i = 0; i < t.rows.size(); ++i) n += g.rowSeries[i] == s;
    std::vector<std::string> r{g.series[s], std::to_string(n)};
    if (validCol >= 0) {
      std::size_t valid = 0;
      for (std::size_t i = 0; i < t.rows.size(); ++i) valid += g.rowSeries[i] == s && number(t.rows[i][static_cast<std::size_t>(validCol)]) != 0;
      r.push_back(shortNumber(n ? static_cast<double>(valid) / static_cast<double>(n) : kNaN));
    }
    if (coverageCol >= 0) r.insert(r.end(), {stat(coverageCol, false), stat(coverageCol, true)});
    if (lengthCol >= 0) r.push_back(stat(lengthCol, false));
    if (turnsCol >= 0) r.push_back(stat(turnsCol, false));
    if (wallCol >= 0) r.push_back(stat(wallCol, false));
    aggRows.push_back(r);
  }
  std::vector<bool> aggNumeric(aggHead.size(), true);
  aggNumeric[0] = false;

  std::set<std::int64_t> caseIds;
  for (const Row& r : t.rows) caseIds.insert(static_cast<std::int64_t>(number(r[static_cast<std::size_t>(caseCol)])));

  // the page
  std::ostringstream h;
  const std::string pageTitle = "coverkit report" + (kind.empty() ? std::string() : ": " + kind) + (title.empty() ? std::string() : " \xE2\x80\x94 " + title);
  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    << "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'; script-src 'unsafe-inline'; img-src data:\">\n"
    << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<meta name=\"generator\" content=\"coverkit experiment report\">\n"
    << "<title>" << esc(pageTitle) << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n<header>\n<h1>"
    << esc(title.empty() ? "Experiment report" : title) << "</h1>\n<p>experiment kind <strong>" << esc(kind.empty() ? "unknown" : kind) << "</strong> \xC2\xB7 "
    << caseIds.size() << " cases \xC2\xB7 " << t.rows.size() << " rows \xC2\xB7 " << charts.size() << " charts" << (pictures.empty() ? "" : " \xC2\xB7 ")
    << (pictures.empty() ? std::string() : std::to_string(pictures.size()) + " pictures") << "</p>\n</header>\n<nav>";
  std::vector<std::pair<std::string, std::string>> sections{{"run", "Run"}};
  if (config) sections.emplace_back("config", "Config");
  if (summary) sections.emplace_back("summary", "Summary");
  sections.insert(sections.end(), {{"planners", "Per planner"}, {"charts", "Charts"}});
  if (!pictures.empty()) sections.emplace_back("pictures", "Pictures");
  sections.emplace_back("results", "Results");
  for (const auto& [id, name] : sections) h << "<a href=\"#" << id << "\">" << name << "</a>";
  h << "</nav>\n";

  h << "<section id=\"run\">\n<h2>Run</h2>\n";
  if (runText) {
    std::vector<std::vector<std::string>> rows;
    for (auto it = run.begin(); it != run.end(); ++it) rows.push_back({it.key(), it.value().is_string() ? it.value().get<std::string>() : it.value().dump()});
    h << htmlTable({"field", "value"}, rows);
  } else {
    h << "<p class=\"note\">No run.json in the folder (the run did not complete).</p>\n";
  }
  h << "</section>\n";
  if (config) h << "<section id=\"config\">\n<h2>Config</h2>\n<pre>" << esc(*config) << "</pre>\n</section>\n";
  if (summary) h << "<section id=\"summary\">\n<h2>Summary</h2>\n" << markdownHtml(*summary) << "</section>\n";

  const std::string groupName = t.column("planner") >= 0 ? "planner" : "group";
  h << "<section id=\"planners\">\n<h2>Per planner</h2>\n<p class=\"note\">Means and minima over all rows of each " << groupName
    << (g.xLabel.empty() ? std::string() : " (every " + esc(g.xLabel) + ")") << ".</p>\n<div class=\"scroll\">"
    << htmlTable(aggHead, aggRows, aggNumeric) << "</div>\n</section>\n";

  h << "<section id=\"charts\">\n<h2>Charts</h2>\n";
  if (charts.empty()) h << "<p class=\"note\">No numeric results to chart.</p>\n";
  else h << "<p class=\"note\">The mean per " << groupName << (g.xLabel.empty() ? std::string() : " against " + esc(g.xLabel))
         << " over all rows (hover a point or bar for its value).</p>\n";
  for (const Chart& c : charts)
    h << (c.wide ? "<figure class=\"wide\">\n" : "<figure>\n") << c.svg << "<figcaption><a href=\"" << esc(c.file) << "\">" << esc(c.file) << "</a></figcaption>\n</figure>\n";
  h << "</section>\n";

  if (!pictures.empty()) {
    h << "<section id=\"pictures\">\n<h2>Pictures</h2>\n";
    for (const auto& [name, svg] : pictures) {
      h << "<section class=\"picture\">\n<h3>" << esc(name) << "</h3>\n";
      if (svg.empty()) h << "<p class=\"note\">pictures/" << esc(name) << " holds no SVG drawing.</p>\n";
      else h << "<div>" << svg << "</div>\n";
      h << "</section>\n";
    }
    h << "</section>\n";
  }

  h << "<section id=\"results\">\n<h2>Results</h2>\n<p class=\"note\">" << t.rows.size() << " rows, " << t.columns.size()
    << " columns (results.csv holds the same table).</p>\n<div class=\"scroll tall" << (t.rows.size() > 2000 ? " lazy" : "")
    << "\">\n<table class=\"sortable\">\n<thead><tr>";
  for (const Column& c : t.columns) h << "<th>" << esc(c.name) << "</th>";
  h << "</tr></thead>\n<tbody>\n";
  for (const Row& r : t.rows) {
    h << "<tr>";
    for (std::size_t c = 0; c < t.columns.size() && c < r.size(); ++c)
      h << (isNumeric(t.columns[c]) ? "<td class=\"num\">" : "<td>") << esc(cellText(t, r, c)) << "</td>";
    h << "</tr>\n";
  }
  h << "</tbody>\n</table>\n</div>\n</section>\n<script>" << kScript << "</script>\n</body>\n</html>\n";

  std::vector<std::pair<std::string, std::string>> files{{"report.html", h.str()}};
  for (Chart& c : charts) files.emplace_back(c.file, std::move(c.svg));
  return files;
}

}  // namespace coverkit::experiments
