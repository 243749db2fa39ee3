#include "evolution_run.hpp"

#include "errors.hpp"
#include "exit_codes.hpp"
#include "growth_problem.hpp"
#include "operators.hpp"
#include "population_stats.hpp"
#include "progress.hpp"
#include "steady_state.hpp"
#include "stop_signals.hpp"

#include <omp.h>
#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>

#include <chrono>

namespace morphogen {

namespace {
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// The population member that ranks highest, if it is valid.
const Individual* best_member(const std::vector<Individual>& population) {
    const Individual* best = nullptr;
    for (const Individual& member : population)
        if (best == nullptr || ranks_above(member, *best)) best = &member;
    return best != nullptr && best->valid() ? best : nullptr;
}
}  // namespace

RunLoggers make_run_loggers(const RunPaths& paths) {
    auto console = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
    std::shared_ptr<spdlog::sinks::basic_file_sink_mt> file;
    try {
        file = std::make_shared<spdlog::sinks::basic_file_sink_mt>(paths.log.string(), /*truncate=*/false);
    } catch (const spdlog::spdlog_ex& e) {
        throw IoError(paths.log.string() + ": cannot open the log (" + e.what() + ")");
    }
    RunLoggers loggers;
    loggers.failure = std::make_shared<std::string>();
    loggers.both = std::make_shared<spdlog::logger>("morphogen", spdlog::sinks_init_list{console, file});
    loggers.file_only = std::make_shared<spdlog::logger>("morphogen", file);
    for (auto* logger : {&loggers.both, &loggers.file_only}) {
        (*logger)->set_pattern("[%Y-%m-%d %H:%M:%S.%e] [%l] %v");
        (*logger)->flush_on(spdlog::level::info);
        // Only log.txt's failures stop a run: a closed stderr is no reason to.
        (*logger)->set_error_handler(
            [failure = loggers.failure, name = paths.log.string()](const std::string& message) {
                if (failure->empty() && message.find(name) != std::string::npos) *failure = message;
            });
    }
    console->set_pattern("%v");
    return loggers;
}

int resolve_threads(int threads) { return threads > 0 ? threads : omp_get_max_threads(); }

namespace {
int run_loop(RunSession& s, GrowthProblem& problem) {
    const ExperimentConfig& config = s.config;
    const auto P = static_cast<std::uint64_t>(config.evolution.population);
    const std::uint64_t target_births = (config.run.generations + 1) * P;
    const int threads = resolve_threads(config.run.threads);
    auto& log = s.log.both;

    SteadyStateGA ga(config.evolution, config.run.seed, problem, std::move(s.state.ga));
    Progress progress(s.log.both, s.log.file_only, target_births, config.run.generations);
    log->info("run directory {}: population {}, generation {}/{} ({} births done), {} threads, seed {}",
              s.paths.dir.string(), P, ga.completed_generations(), config.run.generations, ga.state().births,
              threads, config.run.seed);

    const auto session_start = Clock::now();
    const double elapsed_before = s.state.elapsed_s;
    auto generation_start = session_start;
    std::uint64_t generation_first_birth = ga.state().births;

    // spdlog reports a failed log write to the handler, not to us: check it.
    auto check_log = [&] {
        if (!s.log.failure->empty()) throw IoError(*s.log.failure);
    };
    auto checkpoint = [&] {
        check_log();
        s.history.sync();
        s.lineage.sync();
        s.state.config = config.resolved;
        s.state.seed = config.run.seed;
        s.state.ga = ga.state();
        s.state.lineage_bytes = s.lineage.size();
        s.state.lineage_hash = s.lineage.hash_hex();
        s.state.elapsed_s = elapsed_before + seconds_since(session_start);
        save_checkpoint(s.paths.checkpoint, s.state);
    };

    progress.batch(ga.state().births, ga.completed_generations(),
                   ga.state().best ? std::optional<double>(ga.state().best->fitness) : std::nullopt);
    while (ga.state().births < target_births) {
        if (StopSignals::requested()) {
            checkpoint();
            progress.clear();
            log->warn("stopped by signal {} after {} births; checkpoint saved. Continue with: morphogen resume {}",
                      StopSignals::signal_number(), ga.state().births, s.paths.dir.string());
            return exit_code::interrupted;
        }
        const BatchOutcome out = ga.step(threads);
        std::string rows;
        for (std::size_t i = 0; i < out.children.size(); ++i) {
            rows += format_lineage_row(out.children[i]);
            if (!out.errors[i].empty()) {
                progress.clear();
                log->warn("birth {} is invalid: {}", out.children[i].id, out.errors[i]);
            }
        }
        s.lineage.write(rows);
        check_log();
        const std::uint64_t births = ga.state().births;
        progress.batch(births, births / P,
                       ga.state().best ? std::optional<double>(ga.state().best->fitness) : std::nullopt);
        if (!out.ends_generation) continue;

        const std::uint64_t generation = births / P - 1;
        const PopulationStats stats = summarize(ga.state().population);
        HistoryRow row;
        row.generation = generation;
        row.births = births;
        row.best = stats.best;
        row.mean = stats.mean;
        row.median = stats.median;
        row.worst = stats.worst;
        row.mean_vertices = stats.mean_size;
        row.invalid = out.generation_invalid;
        const double generation_seconds = seconds_since(generation_start);
        row.births_per_s =
            generation_seconds > 0 ? static_cast<double>(births - generation_first_birth) / generation_seconds : 0.0;
        row.elapsed_s = elapsed_before + seconds_since(session_start);
        s.history.write(format_history_row(row));
        s.state.history.push_back(row);
        progress.clear();
        progress.generation(row);

        const bool last = births == target_births;
        const auto every = [&](std::uint64_t n) { return n > 0 && (generation % n == 0 || last); };
        if (config.run.export_every > 0 && every(config.run.export_every)) {
            if (const Individual* best = best_member(ga.state().population))
                problem.export_genome(best->params, s.paths.best_stem(generation));
        }
        if (last || every(config.run.checkpoint_every)) checkpoint();
        generation_start = Clock::now();
        generation_first_birth = births;
    }
    progress.clear();
    if (ga.state().best)
        log->info("done: generation {} reached; best fitness {} (individual {})", config.run.generations,
                  format_number(ga.state().best->fitness), ga.state().best->id);
    else
        log->info("done: generation {} reached; no valid individual", config.run.generations);
    return exit_code::ok;
}

}  // namespace

int run_session(RunSession& s, GrowthProblem& problem) {
    try {
        return run_loop(s, problem);
    } catch (const IoError& e) {
        throw IoError(std::string(e.what()) + " (the last checkpoint is intact: free space or fix the file, then " +
                      "continue with morphogen resume " + s.paths.dir.string() + ")");
    }
}

}  // namespace morphogen
