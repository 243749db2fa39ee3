#pragma once
// Work spread over the threads of this process: the one meaning of a thread
// count (run.threads, every --threads) and the one parallel loop, for every
// room (growing genomes, the CVT, contact sheets, the breed grid).
#include <cstddef>
#include <functional>

namespace morphogen {

// The worker threads for a requested count: 0 (or less) = all cores
// (OpenMP's default, which OMP_NUM_THREADS may lower); a request beyond the
// machine's cores is capped to them, since more threads than cores only wait
// for one another. Never below 1.
int resolve_threads(int threads);

// The processors of this machine (at least 1), whatever OMP_NUM_THREADS says.
int machine_cores();

// Calls body(index, worker) once for every index in [0, count), on at most
// `threads` threads (at least 1; not resolved here), indices handed out
// `grain` at a time in any order. `worker` in [0, threads) names the thread
// making the call, for per-thread scratch (a GrowthWorkspace each). Every
// index runs even when some throw; then the exception of the lowest index
// is rethrown, so the error is the same for any thread count.
void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t index, int worker)>& body,
                  std::size_t grain = 1);

}  // namespace morphogen
