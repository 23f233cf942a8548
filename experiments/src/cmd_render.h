#pragma once
// `coverkit render`: the subcommand's options and what it does.
#include <CLI/CLI.hpp>

namespace coverkit::experiments {

/// Adds the subcommand `render` to `app`; returns it.
CLI::App* addRenderCommand(CLI::App& app);

/// Runs the parsed subcommand: 0 once the picture is written; InputError for bad input (the caller
/// prints it, exit 2).
int runRenderCommand();

}  // namespace coverkit::experiments
