#pragma once
// What a running `evolve`/`resume` shows. On a terminal (stderr is a tty):
// one line rewritten in place (at most 10 times a second) (generation, best, births/s,
// ETA). Otherwise (a pipe, a log collector): one plain log line per
// generation, with the time remaining at this session's rate (and coverage
// and QD-score for MAP-Elites). log.txt always gets the per-generation line.
#include "run/loop/run_records.hpp"

#include <spdlog/logger.h>

#include <chrono>
#include <cstdint>
#include <memory>

namespace morphogen {

class Progress {
public:
    // `console_and_file` logs to both; `file_only` to log.txt alone.
    Progress(std::shared_ptr<spdlog::logger> console_and_file, std::shared_ptr<spdlog::logger> file_only,
             std::uint64_t target_births, std::uint64_t target_generation);
    ~Progress();

    // After each birth: births done so far, the generation in progress and
    // the best score so far.
    void update(std::uint64_t births, std::uint64_t generation, const std::optional<double>& best);
    // After each generation.
    void generation(const HistoryRow& row);
    // Erases the live line before other output.
    void clear();
    bool on_terminal() const { return tty_; }

private:
    std::shared_ptr<spdlog::logger> log_, file_log_;
    std::uint64_t target_births_, target_generation_;
    bool tty_;
    bool line_shown_ = false;
    std::chrono::steady_clock::time_point start_, last_draw_;
    std::uint64_t start_births_ = 0;
    bool started_ = false;
};

}  // namespace morphogen
