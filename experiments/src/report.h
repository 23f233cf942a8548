#pragma once
// The HTML report of an experiment's output folder (`coverkit experiment report DIR`): one
// self-contained page (inline CSS, inline SVG charts, a few lines of inline JS for sortable tables;
// nothing fetched from the network) and the charts again as separate SVG files.
//
// Made from the folder's files only: results.db (the typed table, engine.h's readTable), run.json,
// config.yaml, summary.md and pictures/*.svg when present. The table needs only a `case` column:
// `planner` (series) and `value` (x axis, named by `vary`) are used when present. The same folder
// gives the same bytes (no clock, no host name other than run.json's).
#include <string>
#include <utility>
#include <vector>

namespace coverkit::experiments {

/// The files to write into `dir` (name relative to `dir` → content): "report.html" first, then
/// "charts/<metric>.svg" for every chart. Bad input (no results.db, not a coverkit database, a
/// table without a `case` column, an unreadable run.json): InputError naming the file.
std::vector<std::pair<std::string, std::string>> reportFiles(const std::string& dir);

}  // namespace coverkit::experiments
