#include "evolution/execution/worker_threads.hpp"

#include <omp.h>

#include <algorithm>

namespace morphogen {

int resolve_threads(int threads) {
    const int cores = std::max(1, omp_get_num_procs());
    return threads > 0 ? std::min(threads, cores) : std::max(1, omp_get_max_threads());
}

}  // namespace morphogen
