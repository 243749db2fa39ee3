// Timings for docs/performance.md ("Checkpoint size and speed"): saving and
// loading large checkpoints. Not part of the suite (ctest label "bench"):
// build/tests/bench_timings '[checkpoint]' --durations no
#include "core/base/atomic_file.hpp"
#include "run/persistence/checkpoint.hpp"
#include "tests/run/checkpoint_states.hpp"
#include "tests/support/temp_dir.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

using namespace morphogen;
using namespace morphogen::test;
using morphogen::testing::TempDir;
namespace fs = std::filesystem;

TEST_CASE("benchmark: saving and loading large checkpoints, format 1 against format 2", "[bench][checkpoint]") {
    TempDir tmp("ckpt-bench");
    using clock = std::chrono::steady_clock;
    // Median of 5 of the wall-clock time and, in brackets, of the process's CPU time.
    auto median_s = [](const std::function<void()>& work) {
        std::vector<double> wall, cpu;
        for (int i = 0; i < 5; ++i) {
            const auto t0 = clock::now();
            const std::clock_t c0 = std::clock();
            work();
            cpu.push_back(static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
            wall.push_back(std::chrono::duration<double>(clock::now() - t0).count());
        }
        std::sort(wall.begin(), wall.end());
        std::sort(cpu.begin(), cpu.end());
        char text[64];
        std::snprintf(text, sizeof text, "%.3f s (cpu %.3f s)", wall[2], cpu[2]);
        return std::string(text);
    };
    for (const auto& [name, state] : std::vector<std::pair<std::string, RunState>>{
             {"MAP-Elites, 10,000 elites", generation0_state(archive_config(20000), 10000)},
             {"GA, population 1,000", generation0_state(ga_config(1001), 1000)}}) {
        const fs::path v1 = tmp.path / "v1.json", v2 = tmp.path / "v2.json";
        const std::string save1 = median_s([&] { write_file_atomically(v1, format1_text(state)); });
        const std::string save2 = median_s([&] { save_checkpoint(v2, state); });
        const std::string load1 = median_s([&] { (void)load_checkpoint(v1); });
        const std::string load2 = median_s([&] { (void)load_checkpoint(v2); });
        const std::string bytes2 = median_s([&] { (void)checkpoint_bytes(state); });
        const std::string text = checkpoint_bytes(state);
        const std::string write2 = median_s([&] { write_file_atomically(v2, text); });
        std::cout << name << ": format 1 " << fs::file_size(v1) << " bytes, save " << save1 << ", load " << load1
                  << "; format 2 " << fs::file_size(v2) << " bytes, save " << save2 << ", load " << load2
                  << " (in memory " << bytes2 << ", writing " << write2 << ")\n";
    }
}
