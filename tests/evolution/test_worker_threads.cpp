// resolve_threads: the one meaning of a thread count (run.threads, --threads).
#include "evolution/execution/worker_threads.hpp"

#include <catch2/catch.hpp>

#include <omp.h>

#include <algorithm>

using namespace morphogen;

TEST_CASE("0 threads are OpenMP's default, a request is capped at the cores", "[evolution][threads]") {
    const int cores = std::max(1, omp_get_num_procs());
    CHECK(resolve_threads(0) == omp_get_max_threads());
    CHECK(resolve_threads(-3) == omp_get_max_threads());
    CHECK(resolve_threads(1) == 1);
    CHECK(resolve_threads(cores) == cores);
    CHECK(resolve_threads(cores + 1) == cores);
    CHECK(resolve_threads(1 << 20) == cores);
}
