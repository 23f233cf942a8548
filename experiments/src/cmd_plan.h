#pragma once
// `coverkit plan`: the subcommand's options and what it does.
#include <CLI/CLI.hpp>

namespace coverkit::experiments {

/// Adds the subcommand `plan` to `app`; returns it.
CLI::App* addPlanCommand(CLI::App& app);

/// Runs the parsed subcommand: 0 when the plan succeeded and is valid, 1 otherwise; InputError for
/// bad input (the caller prints it, exit 2).
int runPlanCommand();

}  // namespace coverkit::experiments
