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
/// work), removed at exit. In $COVERKIT_FUZZ_TMP, else /dev/shm (a file rewritten a million times
/// on a disk file system waits for the disk: ext4 flushes a truncated-and-rewritten file on close),
/// else $TMPDIR or /tmp.
inline const std::filesystem::path& scratchDir() {
  static const std::filesystem::path* dir = [] {
    std::string base = "/tmp";
    std::error_code ec;
    if (const char* t = std::getenv("COVERKIT_FUZZ_TMP"); t && *t) base = t;
    else if (std::filesystem::is_directory("/dev/shm", ec) && access("/dev/shm", W_OK) == 0) base = "/dev/shm";
    else if (const char* t2 = std::getenv("TMPDIR"); t2 && *t2) base = t2;
    std::string templ = base + "/coverkit-fuzz-XXXXXX";
    if (!mkdtemp(templ.data())) {
      std::perror("coverkit fuzz: mkdtemp");
      std::abort();
    }
    auto* p = new std::filesystem::path(templ);  // never destroyed: the exit handler below uses it
    std::atexit([] {
      std::error_code e;
      std::filesystem::remove_all(scratchDir(), e);
    });
    return p;
  }();
  return *dir;
}

/// Writes bytes to scratchDir()/name and returns the full path.
inline std::string writeScratch(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path p = scratchDir() / name;
  std::error_code ec;
  std::filesystem::remove(p, ec);  // a new file each time, never truncated (see scratchDir)
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
