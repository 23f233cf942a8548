#pragma once
// `coverkit cspace`: the subcommand's options and what it does.
#include <CLI/CLI.hpp>

namespace coverkit::experiments {

/// Adds the subcommand `cspace` to `app`; returns it.
CLI::App* addCspaceCommand(CLI::App& app);

/// Runs the parsed subcommand: 0 once the C-space file is written; InputError for bad input (the
/// caller prints it, exit 2).
int runCspaceCommand();

}  // namespace coverkit::experiments
