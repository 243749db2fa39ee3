#include "run/evolution_run.hpp"

#include "base/atomic_file.hpp"
#include "base/errors.hpp"
#include "evolution/thread_evaluator.hpp"
#include "run/exit_codes.hpp"
#include "run/growth_problem.hpp"
#include "run/io_thread.hpp"
#include "run/progress.hpp"
#include "run/search_drivers.hpp"
#include "run/stop_signals.hpp"
#include "run/worker_threads.hpp"

#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>

#include <omp.h>

#include <algorithm>
#include <chrono>

namespace morphogen {

namespace {
RemoteEvaluatorFactory g_remote_factory;

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
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

void set_remote_evaluator_factory(RemoteEvaluatorFactory factory) { g_remote_factory = std::move(factory); }

namespace {
// The threads this process scores with: run.threads capped at the cores and
// at the births that can be in flight at once (more would have nothing to do).
int scoring_threads(const ExperimentConfig& config, const BirthSchedule& schedule, spdlog::logger& log) {
    const int threads = std::min<long long>(resolve_threads(config.run.threads), static_cast<long long>(schedule.width));
    if (config.run.threads > threads)
        log.warn("run.threads {} is more than can run at once here ({} cores, {} births in flight: {}): using {} "
                 "threads",
                 config.run.threads, omp_get_num_procs(), schedule.width, schedule.describe(), threads);
    return threads;
}

template <class Driver>
int run_loop(RunSession& s, GrowthProblem& problem, Driver& ga) {
    const ExperimentConfig& config = s.config;
    const auto P = static_cast<std::uint64_t>(config.evolution.population);
    const std::uint64_t target_births = (config.run.generations + 1) * P;
    const BirthSchedule schedule = birth_schedule(config.evolution);
    auto& log = s.log.both;

    std::unique_ptr<GenomeEvaluator> evaluator = g_remote_factory ? g_remote_factory(config, s.paths.dir) : nullptr;
    const bool remote = evaluator != nullptr;
    if (!remote) evaluator = std::make_unique<ThreadEvaluator>(problem, scoring_threads(config, schedule, *log));

    Progress progress(s.log.both, s.log.file_only, target_births, config.run.generations);
    log->info("run directory {}: population {}, generation {}/{} ({} births done), {}, {}, seed {}",
              s.paths.dir.string(), P, ga.completed_generations(), config.run.generations, ga.births(),
              remote ? "scored over MPI" : evaluator->description(), schedule.describe(), config.run.seed);
    if (remote) log->info("genomes are grown and scored by {}", evaluator->description());
    if (schedule.kind == ScheduleKind::pipeline && schedule.width < 2 * static_cast<std::uint64_t>(evaluator->capacity()))
        log->warn("evolution.lag {} keeps fewer than 2 genomes in flight per thread ({} threads): some will wait; "
                  "a larger lag keeps them busy (docs/performance.md)",
                  schedule.width, evaluator->capacity());

    const auto session_start = Clock::now();
    const double elapsed_before = s.state.elapsed_s;
    auto generation_start = session_start;
    std::uint64_t generation_first_birth = ga.births();
    BirthPipeline pipeline(schedule, ga.breeder(), *evaluator, std::move(s.state.pending));
    std::string rows;  // lineage.csv rows not yet written
    // The exported individual's files as its evaluation kept them (none after a resume, until it changes).
    std::optional<std::uint64_t> kept_id;
    std::string kept_files;
    // Declared last, so it finishes its writes before anything it uses goes.
    IoThread io;
    // The last checkpoint posted. A generation's end waits for it before it
    // writes or reports anything, so what a kill -9 finds on disk is at most
    // one finished generation past the last due checkpoint (§11.1).
    std::uint64_t checkpoint_ticket = 0;

    // spdlog reports a failed log write to the handler, not to us: check it.
    auto check_log = [&] {
        if (!s.log.failure->empty()) throw IoError(*s.log.failure);
    };
    auto write_rows = [&] {
        s.lineage.write(rows);
        rows.clear();
        check_log();
    };
    // The state is taken here; the I/O thread syncs the rows written so far
    // and writes archive.csv, then the checkpoint (each atomically, in order).
    auto checkpoint = [&] {
        write_rows();
        s.state.config = config.resolved;
        s.state.seed = config.run.seed;
        ga.save(s.state);
        s.state.pending = pipeline.kept();
        s.state.lineage_bytes = s.lineage.size();
        s.state.lineage_hash = s.lineage.hash_hex();
        s.state.elapsed_s = elapsed_before + seconds_since(session_start);
        std::string archive = config.algorithm == Algorithm::map_elites ? ga.archive_text() : std::string();
        checkpoint_ticket = io.post([&s, bytes = checkpoint_bytes(s.state), archive = std::move(archive)] {
            s.history.sync();
            s.lineage.sync();
            // archive.csv first: a checkpoint never refers to an older archive.csv.
            if (!archive.empty()) write_file_atomically(s.paths.archive, archive);
            write_file_atomically(s.paths.checkpoint, bytes);
        });
    };
    auto best_fitness = [&] { return ga.best() ? std::optional<double>(ga.best()->fitness) : std::nullopt; };

    const auto on_insert = [&](const Individual& child, const std::string& error, const Inserted& what,
                               const std::string& kept) {
        if (!kept.empty()) {
            if (const Individual* exported = ga.exported(); exported != nullptr && exported->id == child.id) {
                kept_id = child.id;
                kept_files = kept;
            }
        }
        rows += format_lineage_row(child, s.lineage_descriptor_columns.value_or(config.qd.descriptors.size()));
        if (!error.empty()) {
            progress.clear();
            log->warn("birth {} is invalid: {}", child.id, error);
        }
        const std::uint64_t births = ga.births();
        progress.update(births, births / P, best_fitness());
        if (!what.ends_generation) return;
        io.wait_for(checkpoint_ticket);
        write_rows();

        const std::uint64_t generation = births / P - 1;
        HistoryRow row;
        row.generation = generation;
        row.births = births;
        ga.fill(row, what);
        row.invalid = what.generation_invalid;
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
            if (const Individual* best = ga.exported()) {
                const std::filesystem::path stem = s.paths.best_stem(generation);
                if (kept_id == best->id)
                    io.post([&problem, files = kept_files, params = best->params, stem] {
                        problem.export_kept(files, params, stem);
                    });
                else  // grown again, on the I/O thread
                    io.post([&problem, params = best->params, stem] { problem.export_genome(params, stem); });
            }
        }
        if (last || every(config.run.checkpoint_every)) checkpoint();
        generation_start = Clock::now();
        generation_first_birth = births;
    };

    progress.update(ga.births(), ga.completed_generations(), best_fitness());
    if (!pipeline.run(target_births, on_insert, [] { return StopSignals::requested(); })) {
        checkpoint();
        io.drain();
        progress.clear();
        log->warn("stopped by signal {} after {} births; checkpoint saved. Continue with: morphogen resume {}",
                  StopSignals::signal_number(), ga.births(), s.paths.dir.string());
        return exit_code::interrupted;
    }
    io.drain();
    progress.clear();
    if (remote && !evaluator->summary().empty()) s.log.file_only->info("{}", evaluator->summary());
    if (ga.best())
        log->info("done: generation {} reached; best fitness {} (individual {})", config.run.generations,
                  format_number(ga.best()->fitness), ga.best()->id);
    else
        log->info("done: generation {} reached; no valid individual", config.run.generations);
    return exit_code::ok;
}

}  // namespace

int run_session(RunSession& s, GrowthProblem& problem) {
    try {
        if (s.config.algorithm == Algorithm::map_elites) {
            EliteDriver driver(s.config, problem, s.state);
            return run_loop(s, problem, driver);
        }
        GaDriver driver(s.config, problem, s.state);
        return run_loop(s, problem, driver);
    } catch (const IoError& e) {
        throw IoError(std::string(e.what()) + " (the last checkpoint is intact: free space or fix the file, then " +
                      "continue with morphogen resume " + s.paths.dir.string() + ")");
    }
}

}  // namespace morphogen
