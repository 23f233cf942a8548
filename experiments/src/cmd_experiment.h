#pragma once
// `coverkit experiment ...`: the subcommand's options and what it does (docs/experiments.md).
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace coverkit::experiments {

/// Adds the subcommand `experiment` to `app`; returns it.
CLI::App* addExperimentCommand(CLI::App& app);

/// Runs the parsed subcommand: 0 on success; InputError for bad input (the caller prints it, exit 2).
int runExperimentCommand(const std::string& commandLine);

/// `coverkit demo`: the named experiment `demo` (experiments/configs/demo.yaml) run by the engine
/// into `outDir`, then its report. 0 when every plan is valid, 1 otherwise.
int runDemo(const std::string& outDir, unsigned jobs, bool quiet, const std::string& commandLine);

}  // namespace coverkit::experiments
