#pragma once
// `coverkit demo`: the subcommand's options and what it does (the experiment `demo`, see
// cmd_experiment.h).
#include <CLI/CLI.hpp>

#include <string>

namespace coverkit::experiments {

/// Adds the subcommand `demo` to `app`; returns it.
CLI::App* addDemoCommand(CLI::App& app);

/// Runs the parsed subcommand (runDemo): 0 when every plan is valid, 1 otherwise; InputError for bad
/// input (the caller prints it, exit 2).
int runDemoCommand(const std::string& commandLine);

}  // namespace coverkit::experiments
