#pragma once
// Shared by every libFuzzer target in fuzz/ (docs/fuzzing.md).
//
// The contract is the command line's: a reader either returns or throws InputError (the CLI's exit
// 2, a clean refusal). Any other exception would be the CLI's exit 3 (an internal error), so it
// aborts here and libFuzzer records the input as a crash; so does every sanitizer report, a leak, a
// run past -timeout and memory past -rss_limit_mb / -malloc_limit_mb.
#include <coverkit/geometry/error.h>

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace coverkit::fuzz {

/// Runs `read` under the contract: InputError is fine, anything else aborts.
template <class F>
void expectReadOrInputError(F&& read) {
  try {
    read();
  } catch (const InputError&) {
    // a clean refusal (exit 2)
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coverkit fuzz: internal error (the CLI's exit 3): %s\n", e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "coverkit fuzz: unknown exception (the CLI's exit 3)\n");
    std::abort();
  }
}

/// A private folder for the files a path-taking reader needs, one per process (so -jobs/-fork
/// work), removed at exit.
inline const std::filesystem::path& scratchDir() {
  static const std::filesystem::path dir = [] {
    const char* base = std::getenv("TMPDIR");
    std::string templ = std::string(base && *base ? base : "/tmp") + "/coverkit-fuzz-XXXXXX";
    if (!mkdtemp(templ.data())) {
      std::perror("coverkit fuzz: mkdtemp");
      std::abort();
    }
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(scratchDir(), ec);
    });
    return std::filesystem::path(templ);
  }();
  return dir;
}

/// Writes bytes to scratchDir()/name and returns the full path.
inline std::string writeScratch(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path p = scratchDir() / name;
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) {
    std::fprintf(stderr, "coverkit fuzz: cannot write %s\n", p.c_str());
    std::abort();
  }
  return p.string();
}
inline std::string writeScratch(const std::string& name, const std::string& text) {
  return writeScratch(name, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
}

}  // namespace coverkit::fuzz
