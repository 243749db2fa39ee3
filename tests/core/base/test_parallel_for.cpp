// The one meaning of a thread count (resolve_threads) and the one parallel
// loop (core/base/parallel_for.hpp).
#include "core/base/parallel_for.hpp"

#include <catch2/catch.hpp>

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

using namespace morphogen;

TEST_CASE("0 threads are OpenMP's default, a request is capped at the cores", "[base][threads]") {
    const int cores = std::max(1, omp_get_num_procs());
    CHECK(machine_cores() == cores);
    CHECK(resolve_threads(0) == omp_get_max_threads());
    CHECK(resolve_threads(-3) == omp_get_max_threads());
    CHECK(resolve_threads(1) == 1);
    CHECK(resolve_threads(cores) == cores);
    CHECK(resolve_threads(cores + 1) == cores);
    CHECK(resolve_threads(1 << 20) == cores);
}

TEST_CASE("parallel_for calls the body once per index, from workers below the thread count", "[base][threads]") {
    for (const int threads : {1, 3, 8})
        for (const std::size_t grain : {std::size_t{1}, std::size_t{7}}) {
            INFO(threads << " threads, grain " << grain);
            std::vector<std::atomic<int>> calls(1000);
            std::atomic<int> bad_worker{0};
            parallel_for(
                calls.size(), threads,
                [&](std::size_t i, int worker) {
                    calls[i].fetch_add(1);
                    if (worker < 0 || worker >= threads) bad_worker.fetch_add(1);
                },
                grain);
            CHECK(std::all_of(calls.begin(), calls.end(), [](const std::atomic<int>& c) { return c.load() == 1; }));
            CHECK(bad_worker.load() == 0);
        }
    bool called = false;
    parallel_for(0, 4, [&](std::size_t, int) { called = true; });
    CHECK_FALSE(called);
    // A count of 0 threads or less still runs, on one.
    int sum = 0;
    parallel_for(10, 0, [&](std::size_t i, int worker) { sum += static_cast<int>(i) + worker; });
    CHECK(sum == 45);
}

TEST_CASE("parallel_for runs every index and rethrows the lowest index's exception", "[base][threads]") {
    for (const int threads : {1, 4}) {
        std::vector<std::atomic<int>> calls(200);
        try {
            parallel_for(calls.size(), threads, [&](std::size_t i, int) {
                calls[i].fetch_add(1);
                if (i % 50 == 17) throw std::runtime_error("item " + std::to_string(i));
            });
            FAIL("no exception");
        } catch (const std::runtime_error& e) {
            CHECK(std::string(e.what()) == "item 17");
        }
        CHECK(std::all_of(calls.begin(), calls.end(), [](const std::atomic<int>& c) { return c.load() == 1; }));
    }
}
