// The coverkit command line: plan, evaluate, render, cspace, decompose, list, demo, experiment, one
// file cmd_NAME.{h,cpp} each (cmd_common: what several share); here the app and the dispatch. Bad
// input: a message naming the file, the place and the problem on stderr, exit code 2, no output file.
#include "cmd_cspace.h"
#include "cmd_decompose.h"
#include "cmd_demo.h"
#include "cmd_evaluate.h"
#include "cmd_experiment.h"
#include "cmd_list.h"
#include "cmd_plan.h"
#include "cmd_render.h"
#include "engine.h"

#include <coverkit/geometry/error.h>

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <string>

#include "coverkit_git_revision.h"   // generated at every build (cmake/git_revision.cmake)
#ifndef COVERKIT_VERSION
#define COVERKIT_VERSION "0.0.0"
#endif

using namespace coverkit;

int main(int argc, char** argv) {
  CLI::App app{"coverkit: coverage path planning for disc robots on exact geometry"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(COVERKIT_VERSION) + " (" + COVERKIT_GIT_REVISION + ")" +
                                        (experiments::mpiBuiltIn() ? ", experiments with MPI" : ""));

  CLI::App* plan = experiments::addPlanCommand(app);
  CLI::App* eval = experiments::addEvaluateCommand(app);
  CLI::App* render = experiments::addRenderCommand(app);
  CLI::App* cspace = experiments::addCspaceCommand(app);
  CLI::App* decompose = experiments::addDecomposeCommand(app);
  CLI::App* list = experiments::addListCommand(app);
  CLI::App* demo = experiments::addDemoCommand(app);
  CLI::App* experiment = experiments::addExperimentCommand(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  std::string commandLine;  // the demo's and the experiments' record of how they were run
  for (int i = 0; i < argc; ++i) commandLine += (i ? " " : "") + std::string(argv[i]);
  try {
    if (*list) return experiments::runListCommand();
    if (*demo) return experiments::runDemoCommand(commandLine);
    if (*decompose) return experiments::runDecomposeCommand();
    if (*cspace) return experiments::runCspaceCommand();
    if (*plan) return experiments::runPlanCommand();
    if (*eval) return experiments::runEvaluateCommand();
    if (*experiment) return experiments::runExperimentCommand(commandLine);
    if (*render) return experiments::runRenderCommand();
  } catch (const InputError& e) {
    std::cerr << "coverkit: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "coverkit: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
