// `coverkit experiment ...`. See cmd_experiment.h.
#include "cmd_experiment.h"

#include "engine.h"
#include "experiment_registry.h"
#include "paper_experiments.h"
#include "report.h"

#include <coverkit/datasets/path_io.h>
#include <coverkit/geometry/error.h>

#include <iostream>
#include <map>

namespace coverkit::experiments {

namespace {

struct Options {
  CLI::App* command = nullptr;
  std::vector<std::string> args;   // NAME, then its arguments (run: CONFIG; report: DIR; merge: SHARD_DIR...)
  std::string config, out = "coverkit-experiment", shard;
  bool check = false, quiet = false;
  unsigned jobs = 0;
  ConfigOverrides settings;   ///< --seeds, --size, --density, --obstacles as given
};
Options& options() {
  static Options o;
  return o;
}

std::string namesList() {
  std::string s = "run, report, merge";
  for (const NamedExperiment& n : namedExperiments()) s += ", " + n.name;
  return s + ", sweep";
}

EngineOptions engineOptions(const std::string& commandLine) {
  const Options& o = options();
  EngineOptions e;
  e.jobs = o.jobs;
  e.quiet = o.quiet;
  e.command = commandLine;
  if (!o.shard.empty()) {
    const auto slash = o.shard.find('/');
    try {
      std::size_t a = 0, b = 0;
      if (slash == std::string::npos) throw std::invalid_argument("");
      const unsigned long i = std::stoul(o.shard.substr(0, slash), &a), n = std::stoul(o.shard.substr(slash + 1), &b);
      if (a != slash || b != o.shard.size() - slash - 1 || n == 0 || i >= n || n > 100000) throw std::invalid_argument("");
      e.shard = static_cast<unsigned>(i);
      e.shards = static_cast<unsigned>(n);
    } catch (const std::exception&) {
      throw InputError("--shard", o.shard, "expected i/n with 0 <= i < n (this process runs the cases k with k mod n = i)");
    }
  }
  return e;
}

/// The files an engine run wrote, for the closing line.
void printEngineResult(const EngineResult& r, const std::string& out, const EngineOptions& e) {
  if (r.cases == 0) return;   // an MPI rank other than 0
  if (!r.complete) {
    std::cout << "coverkit: " << r.ran << " cases run now, " << r.resumed << " found done, of " << r.cases << " in all";
    if (e.shards > 1) std::cout << " (shard " << e.shard << "/" << e.shards << "; combine the shards with `coverkit experiment merge`)";
    std::cout << ": " << out << "/results.db\n";
    return;
  }
  std::cout << r.summary << "written: " << out << "/results.csv, results.db, run.json, summary files (" << r.ran << " cases run now, "
            << r.resumed << " resumed)\n";
}

int runEngine(const Experiment& exp, const std::string& commandLine) {
  const Options& o = options();
  const EngineOptions e = engineOptions(commandLine);
  if (o.check) {
    std::cout << "config checked: " << exp.cases() << " cases\n";
    return 0;
  }
  const EngineResult r = runExperiment(exp, o.out, e);
  printEngineResult(r, o.out, e);
  return 0;
}

void refuse(bool given, const std::string& option, const std::string& name, const std::string& why) {
  if (given) throw InputError(option, name, why);
}

}  // namespace

CLI::App* addExperimentCommand(CLI::App& app) {
  Options& o = options();
  o.command = app.add_subcommand("experiment", "run an experiment with the engine (typed results, resumable, parallel), make its report, "
                                               "or reproduce a paper's experiment (docs/experiments.md)");
  o.command->add_option("name", o.args, namesList() + " (run CONFIG, report DIR, merge SHARD_DIR...)")->required();
  o.command->add_option("--config", o.config, "the YAML config (default for the named experiments: experiments/configs/)");
  o.command->add_option("--out", o.out, "output folder (default: coverkit-experiment); a folder with a stopped run of the same experiment is resumed");
  o.command->add_flag("--check", o.check, "read and check the config, run nothing, write nothing (experiments with a config)");
  o.command->add_option("--jobs", o.jobs, "cases run at once (threads); 0, the default: every core. Results do not depend on it")
      ->check(CLI::Range(0u, 1024u));
  o.command->add_flag("--quiet", o.quiet, "no progress on stderr");
  o.command->add_option("--shard", o.shard, "i/n: run only the cases k with k mod n = i (a job array); combine with `experiment merge`");
  // settings of some kinds' configs, given here instead (the kind's `options` in experiment_registry.cpp)
  const std::pair<const char*, const char*> settings[] = {
      {"seeds", "bsa-backtracking: usable seeded maps (default 100); decompositions: worlds per hole count (default 25); team-check: scenarios (default 500)"},
      {"size", "bsa-backtracking: map side in cells (default 30)"},
      {"density", "bsa-backtracking: fraction of blocked cells (default 0.05)"},
      {"obstacles", "bsa-backtracking: clustered (blobs, default) or scattered (single cells)"}};
  for (const auto& [key, help] : settings)
    o.command->add_option_function<std::string>("--" + std::string(key), [&o, k = std::string(key)](const std::string& v) { o.settings[k] = v; }, help);
  return o.command;
}

int runExperimentCommand(const std::string& commandLine) {
  Options& o = options();
  CLI::App* c = o.command;
  const std::string name = o.args.front();
  const std::vector<std::string> rest(o.args.begin() + 1, o.args.end());
  if (name != "run" && name != "report" && name != "merge" && !rest.empty())
    throw InputError("experiment", name, "takes no further argument: '" + rest.front() + "'");

  if (name == "run") {
    refuse(rest.size() != 1, "experiment run", "", "expected one config file: coverkit experiment run CONFIG.yaml --out DIR");
    refuse(c->count("--config"), "--config", "run", "the config is the argument of run");
    return runEngine(*experimentFromConfig(rest.front(), o.settings), commandLine);
  }
  if (name == "report") {
    refuse(rest.size() != 1, "experiment report", "", "expected one folder: coverkit experiment report DIR");
    for (const char* opt : {"--config", "--out", "--check", "--quiet", "--jobs", "--shard"})
      refuse(c->count(opt), opt, "report", "not an option of report (it writes into DIR)");
    refuse(!o.settings.empty(), "--" + (o.settings.empty() ? std::string() : o.settings.begin()->first), "report", "not an option of report");
    writeFilesInFolder(rest.front(), reportFiles(rest.front()));
    std::cout << "written: " << rest.front() << "/report.html\n";
    return 0;
  }
  if (name == "merge") {
    refuse(rest.empty(), "experiment merge", "", "expected the shard folders: coverkit experiment merge --config CONFIG --out DIR SHARD_DIR...");
    refuse(o.config.empty(), "--config", "merge", "give the config the shards ran");
    const EngineOptions e = engineOptions(commandLine);
    const EngineResult r = mergeShards(*experimentFromConfig(o.config, o.settings), rest, o.out, e);
    printEngineResult(r, o.out, e);
    return 0;
  }
  if (name == "sweep") {
    refuse(o.config.empty(), "--config", "", "the sweep needs a config file (or: coverkit experiment run CONFIG)");
    return runEngine(*experimentFromConfig(o.config, o.settings, "sweep"), commandLine);
  }
  const NamedExperiment* n = findNamedExperiment(name);
  if (!n) throw InputError("experiment", name, "unknown experiment (known: " + namesList() + ")");
  // a named experiment: its kind with its shipped config, or another config of that kind
  return runEngine(*experimentFromConfig(o.config.empty() ? defaultConfig(n->config) : o.config, o.settings, n->kind), commandLine);
}

int runDemo(const std::string& outDir, unsigned jobs, bool quiet, const std::string& commandLine) {
  const std::unique_ptr<Experiment> demo = experimentFromConfig(defaultConfig(findNamedExperiment("demo")->config));
  EngineOptions e;
  e.jobs = jobs;
  e.quiet = quiet;
  e.command = commandLine;
  const EngineResult r = runExperiment(*demo, outDir, e);
  if (r.cases == 0) return 0;   // an MPI rank other than 0
  writeFilesInFolder(outDir, reportFiles(outDir));
  const Table t = readTable(outDir);
  std::size_t invalid = 0;
  for (const Row& row : t.rows) invalid += t.real(row, "valid") == 0 ? 1 : 0;
  if (!quiet)
    std::cout << "coverkit demo: " << t.rows.size() << " plans, " << invalid << " invalid; report: " << outDir << "/report.html (summary.md, results.csv, "
              << "results.db, pictures/)\n";
  return invalid == 0 ? 0 : 1;
}

}  // namespace coverkit::experiments
