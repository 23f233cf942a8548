#pragma once
// `coverkit evaluate`: the subcommand's options and what it does.
#include <CLI/CLI.hpp>

namespace coverkit::experiments {

/// Adds the subcommand `evaluate` to `app`; returns it.
CLI::App* addEvaluateCommand(CLI::App& app);

/// Runs the parsed subcommand: 0 when the path is valid, 1 otherwise; InputError for bad input (the
/// caller prints it, exit 2).
int runEvaluateCommand();

}  // namespace coverkit::experiments
