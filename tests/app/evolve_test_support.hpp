#pragma once
// Helpers for the evolve/resume tests: running the morphogen executable and
// comparing run files while ignoring timings (files and temporary directories
// come from support/temp_dir.hpp).
#include "tests/run/tiny_configs.hpp"
#include "tests/support/temp_dir.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace morphogen::test {

namespace fs = std::filesystem;

using morphogen::testing::read_text;
using morphogen::testing::TempDir;
using morphogen::testing::write_text;

struct CliResult {
    int code = -1;       // exit status (128 + signal if killed)
    std::string output;  // stdout and stderr together
};

// Runs `morphogen <args>` (args are passed through the shell).
CliResult run_morphogen(const std::string& args);

// Starts `morphogen <args...>` without waiting; output goes to `log`. With
// `block_stop_signals` it starts with SIGINT and SIGTERM blocked (a signal
// sent at once then waits until morphogen's handlers are in place).
int spawn_morphogen(const std::vector<std::string>& args, const fs::path& log, bool block_stop_signals = false);
// Waits for a spawned process; returns its exit status (128 + signal if
// killed; `killed`, if given, tells the two apart).
int wait_for(int pid, bool* killed = nullptr);

// Waits until history.csv has at least `rows` data rows (or ~10 s passed).
void wait_for_rows(const fs::path& dir, std::size_t rows);

// A path quoted for the shell.
std::string q(const fs::path& p);

// history.csv without its two timing columns.
std::string history_without_times(const fs::path& run_dir);
// The checkpoint's content minus timings (history timing columns, elapsed_s).
nlohmann::json checkpoint_without_times(const fs::path& run_dir);
// Asserts (Catch CHECKs) that two run directories hold the same results.
void check_same_results(const fs::path& a, const fs::path& b);

}  // namespace morphogen::test
