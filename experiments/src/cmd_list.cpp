// `coverkit list`. See cmd_list.h.
#include "cmd_list.h"

#include <coverkit/optimise/processor.h>
#include <coverkit/planners/registry.h>

#include <iostream>

namespace coverkit::experiments {

namespace {

void printParams(const std::vector<planners::ParamSpec>& params, const char* prefix = "  --param ") {
  for (const auto& s : params)
    std::cout << prefix << s.name << "=<" << planners::toString(s.type) << "> default " << s.defaultValue << ", range " << s.range
              << "\n      " << s.help << "\n";
}

}  // namespace

CLI::App* addListCommand(CLI::App& app) {
  return app.add_subcommand("list", "list planners, decompositions and path processors, and their parameters");
}

int runListCommand() {
  for (const std::string& n : planners::Registry::instance().names()) {
    auto p = planners::Registry::instance().create(n);
    const auto caps = p->capabilities();
    std::cout << n << ": " << p->description() << "\n  capabilities: " << (caps.online ? "online" : "offline")
              << (caps.multiRobot ? ", multi-robot" : ", single robot") << ", output " << caps.output << ", covers " << caps.coverage << "\n";
    printParams(p->params());
  }
  for (const std::string& n : planners::DecompositionRegistry::instance().names()) {
    auto d = planners::DecompositionRegistry::instance().create(n);
    const auto caps = d->capabilities();
    std::cout << "decomposition " << n << ": " << d->description() << "\n  capabilities: " << (caps.monotone ? "monotone cells" : "cells not monotone")
              << (caps.rotatable ? ", any sweep direction" : "") << "\n";
    printParams(d->params());
  }
  for (const std::string& n : optimise::ProcessorRegistry::instance().names()) {
    auto p = optimise::ProcessorRegistry::instance().create(n);
    std::cout << "path processor " << n << " (--post " << n << ":KEY=VALUE;...): " << p->description() << "\n";
    printParams(p->params(), "  ");
  }
  return 0;
}

}  // namespace coverkit::experiments
