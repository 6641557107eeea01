// A minimal fork-join loop over an index range: static chunks, one std::thread per chunk.
// Used for assembly and recovery, where the per-item work is uniform enough for static chunks.
#pragma once

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace kontakt {

/// Number of worker threads to use when the caller asked for `requested` (0 = all cores).
inline int resolve_threads(int requested) {
  if (requested > 0) return requested;
  return std::max(1u, std::thread::hardware_concurrency());
}

/// Calls fn(begin, end, thread_index) on disjoint chunks covering [0, n); rethrows the first
/// exception a chunk threw once every thread has joined.
template <class Fn>
void parallel_chunks(std::size_t n, int threads, Fn&& fn) {
  const std::size_t n_threads = std::min<std::size_t>(std::max(1, threads), std::max<std::size_t>(n, 1));
  if (n_threads <= 1 || n < 64) {
    fn(std::size_t{0}, n, 0);
    return;
  }
  std::vector<std::thread> pool;
  std::vector<std::exception_ptr> errors(n_threads);
  const std::size_t chunk = (n + n_threads - 1) / n_threads;
  for (std::size_t t = 0; t < n_threads; ++t) {
    const std::size_t begin = t * chunk, end = std::min(n, begin + chunk);
    pool.emplace_back([&, t, begin, end] {
      try {
        fn(begin, end, static_cast<int>(t));
      } catch (...) {
        errors[t] = std::current_exception();
      }
    });
  }
  for (auto& th : pool) th.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace kontakt
