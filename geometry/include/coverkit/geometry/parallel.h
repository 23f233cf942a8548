#pragma once
// The phases that split over threads (`--threads`): the validator's ranges of a long path, the
// metrics' rasters, a C-space's offsets, the coverable region's two C-spaces, Smooth-STC's sweeps
// and their exact checks. Each job writes its own slot, and the caller combines the slots in job
// order, so that results do not depend on the number of threads. An internal helper of the
// libraries (namespace detail), public so that the planners share it.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace coverkit::detail {

/// `threads`, or every core for 0.
inline unsigned threadCount(unsigned threads) {
  return threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : threads;
}

/// Calls job(k) once for every k in [0, n), on at most `threads` threads (0: every core), the
/// calling one included. Jobs are taken in index order; after a job throws no new one starts, and
/// once all threads have stopped the exception of the lowest failed job is rethrown.
template <class Job>
void parallelFor(std::size_t n, unsigned threads, Job&& job) {
  const std::size_t workers = std::min<std::size_t>(threadCount(threads), n);
  if (workers <= 1) {
    for (std::size_t k = 0; k < n; ++k) job(k);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::vector<std::exception_ptr> failed(n);
  auto work = [&] {
    for (std::size_t k = next++; k < n && !stop; k = next++) {
      try {
        job(k);
      } catch (...) {
        failed[k] = std::current_exception();
        stop = true;
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace coverkit::detail
