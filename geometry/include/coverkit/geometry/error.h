#pragma once
// coverkit's one exception type for bad input: it names the file, the place and the problem.
// Expected planning outcomes are PlanStatus values, never exceptions (see docs/architecture.md).
#include <stdexcept>
#include <string>

namespace coverkit {

class InputError : public std::runtime_error {
public:
  InputError(std::string file, std::string place, std::string problem)
      : std::runtime_error(compose(file, place, problem)), file_(std::move(file)),
        place_(std::move(place)), problem_(std::move(problem)) {}
  const std::string& file() const { return file_; }
  const std::string& place() const { return place_; }
  const std::string& problem() const { return problem_; }

private:
  static std::string compose(const std::string& f, const std::string& p, const std::string& what) {
    std::string s = f.empty() ? std::string("<input>") : f;
    if (!p.empty()) s += ": " + p;
    return s + ": " + what;
  }
  std::string file_, place_, problem_;
};

}  // namespace coverkit
