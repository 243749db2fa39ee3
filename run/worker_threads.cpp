#include "run/worker_threads.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace morphogen {

namespace {
// Threads being started; libgomp's fatal error calls exit(), which runs this.
std::atomic<int> g_starting{0};

void explain_failed_start() {
    if (const int threads = g_starting.load(); threads > 0)
        std::fprintf(stderr,
                     "morphogen: could not start %d worker threads (the system refused to create more); "
                     "lower run.threads or pass --threads\n",
                     threads);
}
}  // namespace

int resolve_threads(int threads) {
    const int cores = std::max(1, omp_get_num_procs());
    return threads > 0 ? std::min(threads, cores) : omp_get_max_threads();
}

void start_worker_threads(int threads) {
    static const bool registered = std::atexit(explain_failed_start) == 0;
    (void)registered;
    g_starting = threads;
#pragma omp parallel num_threads(threads)
    {
    }
    g_starting = 0;
}

}  // namespace morphogen
