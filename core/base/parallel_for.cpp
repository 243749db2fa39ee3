#include "core/base/parallel_for.hpp"

#include <omp.h>

#include <algorithm>
#include <exception>
#include <limits>

namespace morphogen {

int machine_cores() { return std::max(1, omp_get_num_procs()); }

int resolve_threads(int threads) {
    return threads > 0 ? std::min(threads, machine_cores()) : std::max(1, omp_get_max_threads());
}

void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t index, int worker)>& body,
                  std::size_t grain) {
    if (count == 0) return;
    const auto n = static_cast<long long>(count);
    const int chunk = static_cast<int>(std::clamp<std::size_t>(grain, 1, std::numeric_limits<int>::max()));
    std::size_t failed = count;  // the lowest index that threw; count: none
    std::exception_ptr error;
#pragma omp parallel for schedule(dynamic, chunk) num_threads(std::max(1, threads))
    for (long long i = 0; i < n; ++i) {
        const auto index = static_cast<std::size_t>(i);
        try {
            body(index, omp_get_thread_num());
        } catch (...) {
#pragma omp critical(morphogen_parallel_for_error)
            if (index < failed) {
                failed = index;
                error = std::current_exception();
            }
        }
    }
    if (error) std::rethrow_exception(error);
}

}  // namespace morphogen
