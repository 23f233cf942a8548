#pragma once
// `coverkit decompose`: the subcommand's options and what it does (docs/decompositions.md).
#include <CLI/CLI.hpp>

namespace coverkit::experiments {

/// Adds the subcommand `decompose` to `app`; returns it.
CLI::App* addDecomposeCommand(CLI::App& app);

/// Runs the parsed subcommand: 0 once the cells file is written; InputError for bad input (the
/// caller prints it, exit 2).
int runDecomposeCommand();

}  // namespace coverkit::experiments
