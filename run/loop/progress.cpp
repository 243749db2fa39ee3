#include "run/loop/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace morphogen {

namespace {
std::string duration_text(double seconds) {
    if (!(seconds >= 0) || seconds > 1e8) return "?";
    const auto s = static_cast<long long>(seconds + 0.5);
    char text[32];
    std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", s / 3600, (s / 60) % 60, s % 60);
    return text;
}
std::string score_text(const std::optional<double>& v) {
    if (!v) return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", *v);
    return text;
}
}  // namespace

Progress::Progress(std::shared_ptr<spdlog::logger> console_and_file, std::shared_ptr<spdlog::logger> file_only,
                   std::uint64_t target_births, std::uint64_t target_generation)
    : log_(std::move(console_and_file)),
      file_log_(std::move(file_only)),
      target_births_(target_births),
      target_generation_(target_generation),
      tty_(::isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() {
    if (line_shown_) std::fputc('\n', stderr);
}

void Progress::clear() {
    if (!line_shown_) return;
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
    line_shown_ = false;
}

void Progress::update(std::uint64_t births, std::uint64_t generation, const std::optional<double>& best) {
    const auto now = std::chrono::steady_clock::now();
    if (!started_) {
        started_ = true;
        start_ = now;
        start_births_ = births;
        return;
    }
    if (!tty_) return;
    // Redraw at most ~10 times a second: a terminal flooded with updates slows the run.
    if (line_shown_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    generation = std::min(generation, target_generation_);
    const double seconds = std::chrono::duration<double>(now - start_).count();
    const double rate = seconds > 0 ? static_cast<double>(births - start_births_) / seconds : 0.0;
    const double eta = rate > 0 ? static_cast<double>(target_births_ - births) / rate : -1.0;
    std::fprintf(stderr, "\r\033[Kgeneration %llu/%llu  best %s  %.1f births/s  ETA %s",
                 static_cast<unsigned long long>(generation), static_cast<unsigned long long>(target_generation_),
                 score_text(best).c_str(), rate, duration_text(eta).c_str());
    std::fflush(stderr);
    line_shown_ = true;
}

void Progress::generation(const HistoryRow& row) {
    // The time left at this session's average rate so far (a resumed run's
    // earlier sessions ran on other terms: threads, machine).
    double remaining = -1.0;
    if (started_) {
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        const double done = static_cast<double>(row.births - start_births_);
        if (seconds > 0 && done > 0) remaining = static_cast<double>(target_births_ - row.births) * seconds / done;
    }
    std::string quality;
    if (row.qd) {
        char qd[96];
        std::snprintf(qd, sizeof qd, "coverage %.4g, QD-score %s, ", row.coverage,
                      score_text(row.qd_score).c_str());
        quality = qd;
    }
    char text[384];
    std::snprintf(text, sizeof text,
                  "generation %llu/%llu: best %s mean %s median %s worst %s, mean vertices %s, invalid %llu, "
                  "%s%.1f births/s, elapsed %s, remaining %s",
                  static_cast<unsigned long long>(row.generation), static_cast<unsigned long long>(target_generation_),
                  score_text(row.best).c_str(), score_text(row.mean).c_str(), score_text(row.median).c_str(),
                  score_text(row.worst).c_str(), score_text(row.mean_vertices).c_str(),
                  static_cast<unsigned long long>(row.invalid), quality.c_str(), row.births_per_s,
                  duration_text(row.elapsed_s).c_str(), duration_text(remaining).c_str());
    if (tty_) {
        file_log_->info(text);
    } else {
        log_->info(text);
    }
}

}  // namespace morphogen
