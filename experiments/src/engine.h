#pragma once
// The experiment engine (docs/experiments.md, "The engine"): an experiment is a list of cases; the
// engine runs them on every core (`--jobs`) or over MPI ranks, stores each finished case at once as
// typed rows in OUT/results.db (SQLite, one transaction per case), skips the cases a stopped run
// already stored, and at the end writes results.csv, run.json and the experiment's own summary from
// the whole table. Rows are ordered by case, so the files do not depend on the number of jobs or
// ranks (the timing columns aside).
//
// Modelled on OMPL's benchmark database (one row per run, typed columns, run metadata beside it),
// with what OMPL's tooling leaves out: parallel runs, resuming, and sharding over machines.
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace coverkit::experiments {

enum class ColumnType { kInteger, kReal, kText };
struct Column {
  std::string name;
  ColumnType type;
};
using Value = std::variant<std::int64_t, double, std::string>;
using Row = std::vector<Value>;

/// The whole results table of a run: the engine's columns (case, row) first, then the experiment's,
/// then the engine's timing columns (wall_seconds, peak_rss_mib).
struct Table {
  std::vector<Column> columns;
  std::vector<Row> rows;
  /// The index of a column, or -1.
  int column(const std::string& name) const;
  double real(const Row& r, const std::string& name) const;          ///< integer or real column as a double
  std::string text(const Row& r, const std::string& name) const;     ///< any column as it is written in the CSV
};

/// A column that holds a time or a memory size: the one thing allowed to differ between two runs of
/// the same experiment (names ending in `_seconds`, and peak_rss_mib).
bool isTimingColumn(const std::string& name);

struct RunResult;
/// The columns of one planner run, shared by the experiments that plan: status, valid, violations,
/// every metric of docs/metrics.md (datasets::metricFields, coverable region included), and the
/// wall seconds of planning, validation and metrics.
std::vector<Column> runColumns();
/// The values of runColumns() for `r`, appended to `row`.
void appendRun(Row& row, const RunResult& r);

/// What an experiment gives the engine. `run` is called from several threads at once (and in other
/// processes under MPI): it must touch no shared mutable state.
class Experiment {
public:
  virtual ~Experiment() = default;
  /// The experiment's kind (its registry name), e.g. "sweep".
  virtual std::string kind() const = 0;
  /// Everything that decides the results (the config's text, the options): a folder that holds the
  /// rows of a different identity is not resumed into.
  virtual std::string identity() const = 0;
  /// The experiment's columns (case keys and results).
  virtual std::vector<Column> columns() const = 0;
  virtual std::size_t cases() const = 0;
  /// A short text that names case i (shown in errors and in the table's `key` column).
  virtual std::string caseKey(std::size_t i) const = 0;
  /// The rows of case i (one per run, e.g. one per planner on the case's world), and the files the
  /// case makes (name relative to OUT → content, e.g. pictures/NAME.png), written before its rows
  /// are stored.
  struct Output {
    std::vector<Row> rows;
    std::vector<std::pair<std::string, std::string>> files;
  };
  virtual Output run(std::size_t i) const = 0;
  /// The files made from the whole table (name → content), e.g. summary.md and chart.svg. The first
  /// one's text is what the command prints.
  virtual std::vector<std::pair<std::string, std::string>> summarise(const Table& table) const = 0;
  /// Files written once, before any case runs (e.g. a copy of the config, maps the cases use).
  virtual std::vector<std::pair<std::string, std::string>> inputs() const { return {}; }
};

struct EngineOptions {
  unsigned jobs = 0;        ///< threads running cases; 0: every core
  bool quiet = false;       ///< no progress
  unsigned shard = 0;       ///< this process runs the cases i with i % shards == shard
  unsigned shards = 1;
  std::string command;      ///< the command line, for run.json
};

struct EngineResult {
  std::size_t cases = 0;      ///< of the experiment (all shards)
  std::size_t ran = 0;        ///< run now
  std::size_t resumed = 0;    ///< found done in OUT/results.db
  bool complete = false;      ///< every case is in the table: the summary files were written
  std::string summary;        ///< the first summary file's text (complete runs)
};

/// Runs the experiment into `outDir` (created if missing). Under mpirun with more than one rank
/// (COVERKIT_MPI builds), rank 0 hands out cases one at a time and stores the rows the others send.
/// Bad options or a folder that holds another experiment: InputError before anything runs.
EngineResult runExperiment(const Experiment& experiment, const std::string& outDir, const EngineOptions& options);

/// Merges the tables of shard folders (`--shard i/n` runs of one experiment) into `outDir`, then
/// writes the files of a complete run. The shards must hold the same experiment.
EngineResult mergeShards(const Experiment& experiment, const std::vector<std::string>& shardDirs, const std::string& outDir,
                         const EngineOptions& options);

/// Reads OUT/results.db: the table (rows ordered by case and row) and run.json's fields as text.
Table readTable(const std::string& outDir);

/// The table as CSV (header of column names; reals in their shortest exact form).
std::string tableCsv(const Table& table);

/// Writes `files` (names relative to `dir`, in sub-folders too) together, as datasets::OutputBatch
/// does: all of them or none.
void writeFilesInFolder(const std::string& dir, const std::vector<std::pair<std::string, std::string>>& files);

/// True when the engine was built with MPI (COVERKIT_MPI).
bool mpiBuiltIn();

/// True when this process was started by mpirun with more than one rank (and MPI is built in).
bool underMpi();

}  // namespace coverkit::experiments
