#pragma once
// `coverkit list`: the subcommand and what it prints.
#include <CLI/CLI.hpp>

namespace coverkit::experiments {

/// Adds the subcommand `list` to `app`; returns it.
CLI::App* addListCommand(CLI::App& app);

/// Runs the parsed subcommand: prints the planners and decompositions with their parameters; 0.
int runListCommand();

}  // namespace coverkit::experiments
