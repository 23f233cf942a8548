// The experiment engine. See engine.h and docs/experiments.md ("The engine").
#include "engine.h"

#include "runner.h"

#include <coverkit/datasets/path_io.h>
#include <coverkit/geometry/error.h>
#include <coverkit/geometry/rational.h>

#include <nlohmann/json.hpp>
#include <sqlite3.h>
#include <sys/resource.h>
#include <unistd.h>

#ifdef COVERKIT_HAVE_MPI
#include <mpi.h>
#endif

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "coverkit_git_revision.h"   // generated at every build (cmake/git_revision.cmake)
#ifndef COVERKIT_VERSION
#define COVERKIT_VERSION "unknown"
#endif

namespace coverkit::experiments {

namespace fs = std::filesystem;

int Table::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i].name == name) return static_cast<int>(i);
  return -1;
}

double Table::real(const Row& r, const std::string& name) const {
  const int c = column(name);
  if (c < 0) throw std::logic_error("no column " + name);
  const Value& v = r[static_cast<std::size_t>(c)];
  if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  if (const auto* d = std::get_if<double>(&v)) return *d;
  throw std::logic_error("column " + name + " is text");
}

namespace {

std::string valueText(const Value& v) {
  if (const auto* i = std::get_if<std::int64_t>(&v)) return std::to_string(*i);
  if (const auto* d = std::get_if<double>(&v)) return formatDouble(*d);
  return std::get<std::string>(v);
}

/// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string hashHex(const std::string& text) {   // FNV-1a, 64 bits
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ULL;
  std::ostringstream os;
  os << std::hex << std::setw(16) << std::setfill('0') << h;
  return os.str();
}

double peakRssMiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

const char* sqlType(ColumnType t) { return t == ColumnType::kInteger ? "INTEGER" : t == ColumnType::kReal ? "REAL" : "TEXT"; }

std::vector<Column> allColumns(const Experiment& e) {
  std::vector<Column> c{{"case", ColumnType::kInteger}, {"row", ColumnType::kInteger}, {"key", ColumnType::kText}};
  for (const Column& k : e.columns()) c.push_back(k);
  c.push_back({"wall_seconds", ColumnType::kReal});
  c.push_back({"peak_rss_mib", ColumnType::kReal});
  return c;
}

/// The rows of one case, as the engine stores them: case, row, key, the experiment's values, times.
struct CaseRows {
  std::size_t index = 0;
  std::vector<Row> rows;
  std::vector<std::pair<std::string, std::string>> files;
};

CaseRows runCase(const Experiment& e, std::size_t i) {
  const auto t0 = std::chrono::steady_clock::now();
  Experiment::Output output = e.run(i);
  const std::vector<Row>& rows = output.rows;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::size_t expected = e.columns().size();
  const std::string key = e.caseKey(i);
  CaseRows out{i, {}, std::move(output.files)};
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (rows[k].size() != expected) throw std::logic_error("experiment " + e.kind() + ": case " + key + " gave a row of the wrong width");
    Row r{static_cast<std::int64_t>(i), static_cast<std::int64_t>(k), key};
    r.insert(r.end(), rows[k].begin(), rows[k].end());
    r.push_back(wall);
    r.push_back(peakRssMiB());
    out.rows.push_back(std::move(r));
  }
  return out;
}

// ---- the SQLite store ------------------------------------------------------------------------------

/// Every row of table `runs`, ordered by case and row, read as `columns` say.
std::vector<Row> selectRuns(sqlite3* db, const std::vector<Column>& columns) {
  std::vector<Row> rows;
  sqlite3_stmt* st = nullptr;
  if (sqlite3_prepare_v2(db, "SELECT * FROM runs ORDER BY \"case\", \"row\"", -1, &st, nullptr) != SQLITE_OK) {
    sqlite3_finalize(st);
    return rows;
  }
  while (sqlite3_step(st) == SQLITE_ROW) {
    Row r;
    for (std::size_t i = 0; i < columns.size(); ++i) {
      const int k = static_cast<int>(i);
      if (columns[i].type == ColumnType::kInteger) r.emplace_back(static_cast<std::int64_t>(sqlite3_column_int64(st, k)));
      else if (columns[i].type == ColumnType::kReal) r.emplace_back(sqlite3_column_double(st, k));
      else {
        const unsigned char* s = sqlite3_column_text(st, k);
        r.emplace_back(std::string(s ? reinterpret_cast<const char*>(s) : ""));
      }
    }
    rows.push_back(std::move(r));
  }
  sqlite3_finalize(st);
  return rows;
}

/// OUT/results.db: table `runs` (the typed rows), table `cases` (every finished case, also those
/// with no row), table `meta` (kind, identity and its hash, the column list). One transaction per
/// finished case, so a killed run leaves whole cases only.
class Store {
public:
  Store(const std::string& file, const Experiment& e, const std::vector<Column>& columns) : file_(file), columns_(columns) {
    try {
      open(e);
    } catch (...) {   // a constructor that throws has no destructor run: close the handle here
      if (db_) sqlite3_close(db_);
      db_ = nullptr;
      throw;
    }
  }
  void open(const Experiment& e) {
    if (sqlite3_open_v2(file_.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) != SQLITE_OK)
      fail("cannot be opened");
    exec("PRAGMA busy_timeout = 5000");
    // a folder of another experiment is refused before anything in it changes
    const std::string hash = hashHex(e.identity()), colList = columnList();
    const std::string oldHash = hasTable("meta") ? meta("identity_hash") : "";
    if (!oldHash.empty() && (oldHash != hash || meta("columns") != colList))
      throw InputError(file_, "", "holds the results of another experiment (" + meta("kind") + ", identity " + oldHash + "; this one: " + e.kind() +
                                     ", " + hash + "): give another --out, or remove the folder");
    exec("PRAGMA journal_mode = WAL");
    exec("PRAGMA synchronous = NORMAL");
    exec("CREATE TABLE IF NOT EXISTS meta (key TEXT PRIMARY KEY, value TEXT NOT NULL)");
    exec("CREATE TABLE IF NOT EXISTS cases (\"case\" INTEGER PRIMARY KEY, key TEXT NOT NULL, rows INTEGER NOT NULL)");
    std::string create = "CREATE TABLE IF NOT EXISTS runs (";
    for (std::size_t i = 0; i < columns_.size(); ++i) create += (i ? ", \"" : "\"") + columns_[i].name + "\" " + sqlType(columns_[i].type);
    create += ", PRIMARY KEY (\"case\", \"row\"))";
    exec(create);
    if (oldHash.empty()) {
      exec("BEGIN");
      setMeta("kind", e.kind());
      setMeta("identity", e.identity());
      setMeta("identity_hash", hash);
      setMeta("columns", colList);
      exec("COMMIT");
    }
  }
  ~Store() {
    if (db_) sqlite3_close(db_);
  }
  Store(const Store&) = delete;
  Store& operator=(const Store&) = delete;

  bool hasTable(const std::string& name) {
    sqlite3_stmt* st = prepare("SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = ?");
    sqlite3_bind_text(st, 1, name.c_str(), -1, SQLITE_TRANSIENT);
    const bool has = sqlite3_step(st) == SQLITE_ROW;
    sqlite3_finalize(st);
    return has;
  }
  std::set<std::size_t> doneCases() {
    std::set<std::size_t> done;
    sqlite3_stmt* st = prepare("SELECT \"case\" FROM cases");
    while (sqlite3_step(st) == SQLITE_ROW) done.insert(static_cast<std::size_t>(sqlite3_column_int64(st, 0)));
    sqlite3_finalize(st);
    return done;
  }

  void insert(const CaseRows& c, const std::string& key) {
    // the case's files first: a case is done only when its files are there
    if (!c.files.empty()) writeFilesInFolder(fs::path(file_).parent_path().string(), c.files);
    exec("BEGIN IMMEDIATE");
    std::string sql = "INSERT INTO runs VALUES (";
    for (std::size_t i = 0; i < columns_.size(); ++i) sql += i ? ", ?" : "?";
    sql += ")";
    sqlite3_stmt* st = prepare(sql);
    for (const Row& r : c.rows) {
      sqlite3_reset(st);
      for (std::size_t i = 0; i < r.size(); ++i) {
        const int k = static_cast<int>(i + 1);
        if (const auto* v = std::get_if<std::int64_t>(&r[i])) sqlite3_bind_int64(st, k, *v);
        else if (const auto* d = std::get_if<double>(&r[i])) sqlite3_bind_double(st, k, *d);
        else sqlite3_bind_text(st, k, std::get<std::string>(r[i]).c_str(), -1, SQLITE_TRANSIENT);
      }
      if (sqlite3_step(st) != SQLITE_DONE) {
        sqlite3_finalize(st);
        exec("ROLLBACK");
        fail("a row could not be stored");
      }
    }
    sqlite3_finalize(st);
    sqlite3_stmt* cs = prepare("INSERT INTO cases VALUES (?, ?, ?)");
    sqlite3_bind_int64(cs, 1, static_cast<sqlite3_int64>(c.index));
    sqlite3_bind_text(cs, 2, key.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_int64(cs, 3, static_cast<sqlite3_int64>(c.rows.size()));
    const int rc = sqlite3_step(cs);
    sqlite3_finalize(cs);
    if (rc != SQLITE_DONE) {
      exec("ROLLBACK");
      fail("a case could not be stored");
    }
    exec("COMMIT");
  }

  Table table() {
    Table t;
    t.columns = columns_;
    t.rows = selectRuns(db_, columns_);
    return t;
  }

  std::string meta(const std::string& key) {
    sqlite3_stmt* st = prepare("SELECT value FROM meta WHERE key = ?");
    sqlite3_bind_text(st, 1, key.c_str(), -1, SQLITE_TRANSIENT);
    std::string v;
    if (sqlite3_step(st) == SQLITE_ROW) v = reinterpret_cast<const char*>(sqlite3_column_text(st, 0));
    sqlite3_finalize(st);
    return v;
  }
  void setMeta(const std::string& key, const std::string& value) {
    sqlite3_stmt* st = prepare("INSERT OR REPLACE INTO meta VALUES (?, ?)");
    sqlite3_bind_text(st, 1, key.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(st, 2, value.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_step(st);
    sqlite3_finalize(st);
  }
  /// Copies into this store the cases of another store of the same experiment.
  void absorb(const std::string& other) {
    exec("ATTACH DATABASE '" + escape(other) + "' AS shard");
    exec("BEGIN");
    exec("INSERT OR IGNORE INTO runs SELECT * FROM shard.runs WHERE \"case\" NOT IN (SELECT \"case\" FROM cases)");
    exec("INSERT OR IGNORE INTO cases SELECT * FROM shard.cases");
    exec("COMMIT");
    exec("DETACH DATABASE shard");
  }
  /// Back to a single file (no -wal, -shm beside it): what a finished run leaves for others to read.
  void checkpoint() { exec("PRAGMA journal_mode = DELETE"); }

private:
  static std::string escape(const std::string& s) {
    std::string o;
    for (char c : s) o += c == '\'' ? std::string("''") : std::string(1, c);
    return o;
  }
  std::string columnList() const {
    std::string s;
    for (const Column& c : columns_) s += c.name + ":" + sqlType(c.type) + ",";
    return s;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(file_, "", what + (db_ ? std::string(": ") + sqlite3_errmsg(db_) : std::string()));
  }
  void exec(const std::string& sql) {
    char* err = nullptr;
    if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &err) != SQLITE_OK) {
      const std::string msg = err ? err : "error";
      sqlite3_free(err);
      if (sql.rfind("ROLLBACK", 0) == 0) return;
      throw InputError(file_, "", "SQLite: " + msg + " (" + sql.substr(0, 60) + ")");
    }
  }
  sqlite3_stmt* prepare(const std::string& sql) {
    sqlite3_stmt* st = nullptr;
    if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &st, nullptr) != SQLITE_OK) fail("SQLite cannot prepare " + sql.substr(0, 60));
    return st;
  }

  std::string file_;
  std::vector<Column> columns_;
  sqlite3* db_ = nullptr;
};

// ---- progress --------------------------------------------------------------------------------------

/// done/total, rate and ETA on stderr: one line redrawn on a terminal, plain lines (every 10 % or
/// 30 s) otherwise.
class Progress {
public:
  Progress(std::size_t total, std::size_t already, bool quiet)
      : total_(total), done_(already), start_(already), quiet_(quiet), tty_(isatty(2) != 0), t0_(std::chrono::steady_clock::now()) {}
  void tick() {
    ++done_;
    if (quiet_) return;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    const std::size_t percent = total_ ? done_ * 100 / total_ : 100;
    if (!tty_ && done_ != total_ && percent / 10 == lastTenth_ && s - lastLine_ < 30) return;
    lastTenth_ = percent / 10;
    lastLine_ = s;
    const double rate = s > 0 ? static_cast<double>(done_ - start_) / s : 0;
    const double eta = rate > 0 ? static_cast<double>(total_ - done_) / rate : 0;
    std::ostringstream os;
    if (tty_) {
      const std::size_t width = 30, full = total_ ? done_ * width / total_ : width;
      os << "\r[" << std::string(full, '#') << std::string(width - full, '.') << "] ";
    } else {
      os << "coverkit: ";
    }
    os << done_ << "/" << total_ << " cases, " << std::fixed << std::setprecision(2) << rate << "/s, ETA " << clock(eta);
    if (tty_) os << "   " << (done_ == total_ ? "\n" : "");
    else os << "\n";
    std::cerr << os.str() << std::flush;
  }

private:
  static std::string clock(double s) {
    const long t = static_cast<long>(s + 0.5);
    std::ostringstream os;
    os << t / 3600 << ":" << std::setw(2) << std::setfill('0') << t / 60 % 60 << ":" << std::setw(2) << t % 60;
    return os.str();
  }
  std::size_t total_, done_, start_;
  bool quiet_, tty_;
  std::chrono::steady_clock::time_point t0_;
  std::size_t lastTenth_ = 0;
  double lastLine_ = 0;
};

// ---- run metadata ---------------------------------------------------------------------------------

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(colon + 2);
    }
  return "unknown";
}

std::string runJson(const Experiment& e, const EngineOptions& o, unsigned jobs, int ranks, const EngineResult& r) {
  char host[256] = {0};
  gethostname(host, sizeof host - 1);
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  nlohmann::ordered_json j;
  j["format"] = "coverkit.run/1";
  j["kind"] = e.kind();
  j["version"] = COVERKIT_VERSION;
  j["git_revision"] = COVERKIT_GIT_REVISION;
  j["identity_hash"] = hashHex(e.identity());
  j["host"] = host;
  j["cpu"] = cpuModel();
  j["cores"] = std::thread::hardware_concurrency();
  j["compiler"] = __VERSION__;
  j["date_utc"] = date;
  j["command"] = o.command;
  j["jobs"] = jobs;
  j["mpi_ranks"] = ranks;
  j["cases"] = r.cases;
  j["cases_run_now"] = r.ran;
  j["cases_resumed"] = r.resumed;
  return j.dump(2) + "\n";
}

/// results.csv, the experiment's summary files and run.json, written together.
EngineResult finish(const Experiment& e, Store& store, const std::string& outDir, const EngineOptions& o, unsigned jobs, int ranks, EngineResult r) {
  store.checkpoint();
  const std::set<std::size_t> done = store.doneCases();
  r.complete = done.size() == e.cases();
  if (!r.complete) return r;
  const Table t = store.table();
  const auto files = e.summarise(t);
  std::vector<std::pair<std::string, std::string>> all{{"results.csv", tableCsv(t)}};
  all.insert(all.end(), files.begin(), files.end());
  all.emplace_back("run.json", runJson(e, o, jobs, ranks, r));
  writeFilesInFolder(outDir, all);
  if (!files.empty()) r.summary = files.front().second;
  return r;
}

std::vector<std::size_t> todoList(const Experiment& e, const std::set<std::size_t>& done, const EngineOptions& o) {
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < e.cases(); ++i)
    if (!done.count(i) && i % o.shards == o.shard) todo.push_back(i);
  return todo;
}

void checkOptions(const EngineOptions& o) {
  if (o.shards == 0 || o.shard >= o.shards)
    throw InputError("--shard", std::to_string(o.shard) + "/" + std::to_string(o.shards), "must be i/n with 0 <= i < n");
  if (o.jobs > 1024) throw InputError("--jobs", std::to_string(o.jobs), "must be in 0..1024 (0: every core)");
}

/// Prepares OUT: checks it, creates it, opens the store, writes the experiment's input files once.
std::unique_ptr<Store> openStore(const Experiment& e, const std::string& outDir) {
  datasets::checkOutputFolder(outDir, "--out", {"results.db", "results.csv", "run.json"});
  std::error_code ec;
  fs::create_directories(outDir, ec);
  if (ec) throw InputError(outDir, "--out", "cannot be created: " + ec.message());
  auto store = std::make_unique<Store>((fs::path(outDir) / "results.db").string(), e, allColumns(e));
  if (store->doneCases().empty()) {
    datasets::OutputBatch in(outDir);
    for (const auto& [name, content] : e.inputs()) in.addInFolder(name, content);
    if (in.size()) in.commit();
  }
  return store;
}

// ---- MPI -------------------------------------------------------------------------------------------

#ifdef COVERKIT_HAVE_MPI
/// A finished case as a message from a worker rank: CBOR of its index, rows and files.
std::string encodeRows(const CaseRows& c) {
  nlohmann::json rows = nlohmann::json::array(), files = nlohmann::json::array();
  for (const Row& r : c.rows) {
    nlohmann::json jr = nlohmann::json::array();
    for (const Value& v : r) {
      if (const auto* i = std::get_if<std::int64_t>(&v)) jr.push_back(*i);
      else if (const auto* d = std::get_if<double>(&v)) jr.push_back(*d);
      else jr.push_back(std::get<std::string>(v));
    }
    rows.push_back(jr);
  }
  for (const auto& [name, content] : c.files)
    files.push_back({name, nlohmann::json::binary(std::vector<std::uint8_t>(content.begin(), content.end()))});
  const std::vector<std::uint8_t> bytes = nlohmann::json::to_cbor(nlohmann::json{{"index", c.index}, {"rows", rows}, {"files", files}});
  return "R" + std::string(bytes.begin(), bytes.end());
}
CaseRows decodeRows(const std::string& s, const std::vector<Column>& columns) {
  const nlohmann::json j = nlohmann::json::from_cbor(s.begin() + 1, s.end());
  CaseRows c;
  c.index = j.at("index").get<std::size_t>();
  for (const auto& jr : j.at("rows")) {
    Row r;
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (columns[i].type == ColumnType::kInteger) r.emplace_back(jr[i].get<std::int64_t>());
      else if (columns[i].type == ColumnType::kReal) r.emplace_back(jr[i].get<double>());
      else r.emplace_back(jr[i].get<std::string>());
    }
    c.rows.push_back(std::move(r));
  }
  for (const auto& f : j.at("files")) {
    const auto& bin = f[1].get_binary();
    c.files.emplace_back(f[0].get<std::string>(), std::string(bin.begin(), bin.end()));
  }
  return c;
}
void sendText(const std::string& s, int to, int tag) {
  MPI_Send(s.data(), static_cast<int>(s.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}
std::string receiveText(int from, int tag, MPI_Status& status) {
  MPI_Status probe;
  // rank 0 waits without spinning a core: probe, and sleep briefly when nothing is there
  for (int flag = 0;;) {
    MPI_Iprobe(from, tag, MPI_COMM_WORLD, &flag, &probe);
    if (flag) break;
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  int n = 0;
  MPI_Get_count(&probe, MPI_CHAR, &n);
  std::string s(static_cast<std::size_t>(n), '\0');
  MPI_Recv(s.data(), n, MPI_CHAR, probe.MPI_SOURCE, probe.MPI_TAG, MPI_COMM_WORLD, &status);
  return s;
}
constexpr int kTagWork = 1, kTagResult = 2;

struct MpiSession {
  MpiSession() {
    int init = 0;
    MPI_Initialized(&init);
    if (!init) MPI_Init(nullptr, nullptr);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
  }
  ~MpiSession() {
    int fin = 0;
    MPI_Finalized(&fin);
    if (!fin) MPI_Finalize();
  }
  int rank = 0, size = 1;
};

/// Rank 0: hands out the cases one at a time (a worker's result asks for its next case) and stores
/// the rows. Other ranks: run what they are given. A worker's failure stops the handing out; its
/// message is thrown on rank 0 once every worker has stopped.
EngineResult runMpi(const Experiment& e, const std::string& outDir, const EngineOptions& o, MpiSession& mpi) {
  EngineResult result;
  result.cases = e.cases();
  std::unique_ptr<Store> store;
  std::vector<std::size_t> todo;
  std::string openError;
  if (mpi.rank == 0) {
    try {
      store = openStore(e, outDir);
      const std::set<std::size_t> done = store->doneCases();
      result.resumed = done.size();
      todo = todoList(e, done, o);
    } catch (const std::exception& ex) {
      openError = ex.what();
    }
  }
  if (mpi.rank != 0) {
    std::string reply = "-";   // the first request carries no result
    for (;;) {
      sendText(reply, 0, kTagResult);
      MPI_Status st;
      const std::string next = receiveText(0, kTagWork, st);
      if (next == "stop") break;
      try {
        reply = encodeRows(runCase(e, static_cast<std::size_t>(std::stoull(next))));
      } catch (const std::exception& ex) {
        reply = std::string("!") + ex.what();
      }
    }
    return result;
  }
  Progress progress(e.cases(), result.resumed, o.quiet || !openError.empty());
  const std::vector<Column> columns = allColumns(e);
  std::size_t next = 0;
  int active = mpi.size - 1;
  std::string failure = openError;
  while (active > 0) {
    MPI_Status st;
    const std::string msg = receiveText(MPI_ANY_SOURCE, kTagResult, st);
    if (!msg.empty() && msg[0] == '!') {
      if (failure.empty()) failure = msg.substr(1);
    } else if (!msg.empty() && msg[0] == 'R') {
      const CaseRows c = decodeRows(msg, columns);
      try {
        store->insert(c, e.caseKey(c.index));
        ++result.ran;
        progress.tick();
      } catch (const std::exception& ex) {
        if (failure.empty()) failure = ex.what();
      }
    }
    if (failure.empty() && next < todo.size()) {
      sendText(std::to_string(todo[next++]), st.MPI_SOURCE, kTagWork);
    } else {
      sendText("stop", st.MPI_SOURCE, kTagWork);
      --active;
    }
  }
  if (!openError.empty()) throw InputError(outDir, "--out", openError);
  if (!failure.empty()) throw std::runtime_error(failure);
  return finish(e, *store, outDir, o, 1, mpi.size, result);
}
#endif

}  // namespace

std::string Table::text(const Row& r, const std::string& name) const {
  const int c = column(name);
  if (c < 0) throw std::logic_error("no column " + name);
  return valueText(r[static_cast<std::size_t>(c)]);
}

std::vector<Column> runColumns() {
  std::vector<Column> c{{"status", ColumnType::kText}, {"valid", ColumnType::kInteger}, {"violations", ColumnType::kInteger}};
  Metrics none;
  none.hasArea = none.hasCoverable = true;
  for (const auto& [name, value] : datasets::metricFields(none)) {
    const bool count = name == "free_subcells" || name == "covered_subcells" || name == "entered_subcells" || name == "revisited_subcells" ||
                       name == "area_exact" || name == "turns" || name == "segments";
    c.push_back({name, count ? ColumnType::kInteger : ColumnType::kReal});
  }
  for (const char* t : {"plan_seconds", "validate_seconds", "metrics_seconds"}) c.push_back({t, ColumnType::kReal});
  return c;
}

void appendRun(Row& row, const RunResult& r) {
  row.emplace_back(std::string(toString(r.plan.status)));
  row.emplace_back(static_cast<std::int64_t>(r.validation.valid ? 1 : 0));
  row.emplace_back(static_cast<std::int64_t>(r.validation.violations.size()));
  Metrics m = r.metrics;
  m.hasArea = m.hasCoverable = true;   // the same columns for every row (zeros when not computed)
  m.hasTeam = false;                   // a team planner's own figures are not columns here (runColumns)
  static const std::vector<Column> cols = runColumns();   // the same for every row
  const auto fields = datasets::metricFields(m);
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (cols[i + 3].type == ColumnType::kInteger) row.emplace_back(static_cast<std::int64_t>(fields[i].second));
    else row.emplace_back(fields[i].second);
  }
  row.emplace_back(r.planSeconds);
  row.emplace_back(r.validateSeconds);
  row.emplace_back(r.metricsSeconds);
}

bool isTimingColumn(const std::string& name) {
  return name == "peak_rss_mib" || (name.size() > 8 && name.compare(name.size() - 8, 8, "_seconds") == 0);
}

std::string tableCsv(const Table& t) {
  std::ostringstream os;
  for (std::size_t i = 0; i < t.columns.size(); ++i) os << (i ? "," : "") << csvField(t.columns[i].name);
  os << "\n";
  for (const Row& r : t.rows) {
    for (std::size_t i = 0; i < r.size(); ++i) os << (i ? "," : "") << csvField(valueText(r[i]));
    os << "\n";
  }
  return os.str();
}

void writeFilesInFolder(const std::string& dir, const std::vector<std::pair<std::string, std::string>>& files) {
  datasets::OutputBatch out(dir);
  for (const auto& [name, content] : files) {
    const fs::path sub = fs::path(name).parent_path();
    if (!sub.empty()) {
      std::error_code ec;
      fs::create_directories(fs::path(dir) / sub, ec);
      if (ec) throw InputError((fs::path(dir) / sub).string(), "", "cannot be created: " + ec.message());
    }
    out.addInFolder(name, content);
  }
  out.commit();
}

bool mpiBuiltIn() {
#ifdef COVERKIT_HAVE_MPI
  return true;
#else
  return false;
#endif
}

bool underMpi() {
#ifdef COVERKIT_HAVE_MPI
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) {
    const char* v = std::getenv(var);
    if (v && std::atoi(v) > 1) return true;
  }
#endif
  return false;
}

EngineResult runExperiment(const Experiment& e, const std::string& outDir, const EngineOptions& o) {
  checkOptions(o);
#ifdef COVERKIT_HAVE_MPI
  if (underMpi()) {
    MpiSession mpi;
    if (mpi.size > 1) {
      EngineResult r = runMpi(e, outDir, o, mpi);
      if (mpi.rank != 0) r.complete = false, r.cases = 0;   // only rank 0 reports
      return r;
    }
  }
#endif
  EngineResult result;
  result.cases = e.cases();
  std::unique_ptr<Store> store = openStore(e, outDir);
  const std::set<std::size_t> done = store->doneCases();
  result.resumed = done.size();
  const std::vector<std::size_t> todo = todoList(e, done, o);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const unsigned jobs = std::max(1u, std::min<unsigned>(o.jobs ? o.jobs : cores, static_cast<unsigned>(std::max<std::size_t>(1, todo.size()))));
  // --jobs N is the number of cores the run uses: N cases at once, each on one thread; when fewer
  // cases than cores are left to run, each case's metric rasters get a share of the rest (the
  // results do not depend on it)
  const unsigned threadsBefore = threads();
  setThreads(std::max(1u, (o.jobs ? o.jobs : cores) / jobs));
  // a shard counts only its own cases
  const bool whole = o.shards == 1;
  Progress progress(whole ? e.cases() : todo.size(), whole ? done.size() : 0, o.quiet);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex storeMutex;
  std::exception_ptr failure;
  auto worker = [&] {
    while (!stop) {
      const std::size_t k = next++;
      if (k >= todo.size()) return;
      try {
        const CaseRows c = runCase(e, todo[k]);
        std::lock_guard<std::mutex> lock(storeMutex);
        store->insert(c, e.caseKey(c.index));
        ++result.ran;
        progress.tick();
      } catch (...) {
        std::lock_guard<std::mutex> lock(storeMutex);
        if (!failure) failure = std::current_exception();
        stop = true;
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned j = 1; j < jobs; ++j) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  setThreads(threadsBefore);
  if (failure) std::rethrow_exception(failure);
  return finish(e, *store, outDir, o, jobs, 1, result);
}

EngineResult mergeShards(const Experiment& e, const std::vector<std::string>& shardDirs, const std::string& outDir, const EngineOptions& o) {
  std::unique_ptr<Store> store = openStore(e, outDir);
  EngineResult result;
  result.cases = e.cases();
  for (const std::string& dir : shardDirs) {
    const std::string file = (fs::path(dir) / "results.db").string();
    if (!fs::is_regular_file(file)) throw InputError(file, "merge", "no results.db here (not the --out of a run)");
    Store shard(file, e, allColumns(e));   // refuses a shard of another experiment
    store->absorb(file);
  }
  result.resumed = store->doneCases().size();
  EngineResult r = finish(e, *store, outDir, o, 0, 1, result);
  if (!r.complete)
    throw InputError(outDir, "merge", std::to_string(result.resumed) + " of " + std::to_string(e.cases()) +
                                          " cases are in the shards: run the missing shards (or rerun one with --shard i/n to complete it)");
  return r;
}

Table readTable(const std::string& outDir) {
  const std::string file = (fs::path(outDir) / "results.db").string();
  if (!fs::is_regular_file(file)) throw InputError(file, "", "not found: the folder holds no experiment results");
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(file.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
    if (db) sqlite3_close(db);
    throw InputError(file, "", "cannot be opened");
  }
  Table t;
  sqlite3_stmt* st = nullptr;
  std::string columns;
  if (sqlite3_prepare_v2(db, "SELECT value FROM meta WHERE key = 'columns'", -1, &st, nullptr) == SQLITE_OK && sqlite3_step(st) == SQLITE_ROW)
    columns = reinterpret_cast<const char*>(sqlite3_column_text(st, 0));
  sqlite3_finalize(st);
  if (columns.empty()) {
    sqlite3_close(db);
    throw InputError(file, "meta", "not a coverkit results database");
  }
  std::stringstream cs(columns);
  std::string item;
  while (std::getline(cs, item, ',')) {
    const auto colon = item.rfind(':');
    const std::string type = item.substr(colon + 1);
    t.columns.push_back({item.substr(0, colon), type == "INTEGER" ? ColumnType::kInteger : type == "REAL" ? ColumnType::kReal : ColumnType::kText});
  }
  t.rows = selectRuns(db, t.columns);
  sqlite3_close(db);
  return t;
}

}  // namespace coverkit::experiments
