#include "evolution_run.hpp"

#include "archive_csv.hpp"
#include "archive_stats.hpp"
#include "atomic_file.hpp"
#include "cvt.hpp"
#include "errors.hpp"
#include "map_elites.hpp"
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
RemoteEvaluatorFactory g_remote_factory;

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

// What the run loop needs of a search, for the GA and MAP-Elites alike: one
// batch (children in birth order with their errors, whether it ended a
// generation and that generation's invalid births), the best ever, the
// statistics of a history row, the individual exported to best/, and saving
// the state into the checkpoint's RunState.
struct StepResult {
    std::vector<Individual> children;
    std::vector<std::string> errors;
    bool ends_generation = false;
    std::uint64_t generation_invalid = 0;
    std::uint64_t generation_new_cells = 0;
};

class GaDriver {
public:
    GaDriver(const ExperimentConfig& c, Problem& problem, RunState& state)
        : ga_(c.evolution, c.run.seed, problem, std::move(state.ga)) {}
    std::uint64_t births() const { return ga_.state().births; }
    std::uint64_t completed_generations() const { return ga_.completed_generations(); }
    const std::optional<Individual>& best() const { return ga_.state().best; }
    StepResult step(int threads, BatchEvaluator* remote) {
        BatchOutcome out = ga_.step(threads, remote);
        return {std::move(out.children), std::move(out.errors), out.ends_generation, out.generation_invalid, 0};
    }
    void fill(HistoryRow& row, const StepResult&) const {
        const PopulationStats stats = summarize(ga_.state().population);
        row.best = stats.best;
        row.mean = stats.mean;
        row.median = stats.median;
        row.worst = stats.worst;
        row.mean_vertices = stats.mean_size;
    }
    const Individual* exported() const { return best_member(ga_.state().population); }
    void save(RunState& state) const { state.ga = ga_.state(); }
    std::string archive_text() const { return {}; }

private:
    SteadyStateGA ga_;
};

MapElitesParams map_elites_params(const GaParams& p) {
    return {p.population, p.crossover, p.mutation_rate, p.mutation_sigma, p.batch, p.init_range};
}

}  // namespace

MapElitesState initial_elites_state(const ExperimentConfig& c, int threads) {
    if (c.qd.archive == ArchiveKind::grid) return MapElitesState{0, Archive::grid(c.qd.descriptors), {}, 0, 0};
    return MapElitesState{
        0, Archive::cvt(c.qd.descriptors, cvt_centroids(c.run.seed, c.qd.cvt_cells, c.qd.descriptors.size(), threads)),
        {}, 0, 0};
}

namespace {
class EliteDriver {
public:
    EliteDriver(const ExperimentConfig& c, Problem& problem, RunState& state, int threads)
        : offset_(c.qd.qd_offset),
          me_(map_elites_params(c.evolution), c.run.seed, problem,
              state.elites ? std::move(*state.elites) : initial_elites_state(c, threads)) {}
    std::uint64_t births() const { return me_.state().births; }
    std::uint64_t completed_generations() const { return me_.completed_generations(); }
    const std::optional<Individual>& best() const { return me_.state().best; }
    StepResult step(int threads, BatchEvaluator* remote) {
        EliteBatchOutcome out = me_.step(threads, remote);
        return {std::move(out.children), std::move(out.errors), out.ends_generation, out.generation_invalid,
                out.generation_new_cells};
    }
    void fill(HistoryRow& row, const StepResult& step) const {
        const ArchiveStats stats = archive_stats(me_.state().archive, offset_);
        row.best = stats.fitness.best;
        row.mean = stats.fitness.mean;
        row.median = stats.fitness.median;
        row.worst = stats.fitness.worst;
        row.mean_vertices = stats.fitness.mean_size;
        row.qd = true;
        row.coverage = stats.coverage;
        row.qd_score = stats.qd_score;
        row.new_cells = step.generation_new_cells;
    }
    // The fittest elite (ties: the lower cell).
    const Individual* exported() const {
        const Individual* best = nullptr;
        for (const auto& [cell, elite] : me_.state().archive.elites())
            if (best == nullptr || elite.fitness > best->fitness) best = &elite;
        return best;
    }
    void save(RunState& state) const { state.elites = me_.state(); }
    std::string archive_text() const { return archive_csv(me_.state().archive); }

private:
    double offset_;
    MapElites me_;
};
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

int resolve_threads(int threads) { return threads > 0 ? threads : omp_get_max_threads(); }

namespace {
template <class Driver>
int run_loop(RunSession& s, GrowthProblem& problem, Driver& ga) {
    const ExperimentConfig& config = s.config;
    const auto P = static_cast<std::uint64_t>(config.evolution.population);
    const std::uint64_t target_births = (config.run.generations + 1) * P;
    const int threads = resolve_threads(config.run.threads);
    auto& log = s.log.both;
    const std::unique_ptr<BatchEvaluator> remote = g_remote_factory ? g_remote_factory(config, s.paths.dir) : nullptr;

    Progress progress(s.log.both, s.log.file_only, target_births, config.run.generations);
    log->info("run directory {}: population {}, generation {}/{} ({} births done), {} threads, seed {}",
              s.paths.dir.string(), P, ga.completed_generations(), config.run.generations, ga.births(),
              threads, config.run.seed);
    if (remote) log->info("genomes are grown and scored by {}", remote->description());

    const auto session_start = Clock::now();
    const double elapsed_before = s.state.elapsed_s;
    auto generation_start = session_start;
    std::uint64_t generation_first_birth = ga.births();

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
        ga.save(s.state);
        s.state.lineage_bytes = s.lineage.size();
        s.state.lineage_hash = s.lineage.hash_hex();
        s.state.elapsed_s = elapsed_before + seconds_since(session_start);
        // archive.csv first: a checkpoint never refers to an older archive.csv.
        if (config.algorithm == Algorithm::map_elites) write_file_atomically(s.paths.archive, ga.archive_text());
        save_checkpoint(s.paths.checkpoint, s.state);
    };

    progress.batch(ga.births(), ga.completed_generations(),
                   ga.best() ? std::optional<double>(ga.best()->fitness) : std::nullopt);
    while (ga.births() < target_births) {
        if (StopSignals::requested()) {
            checkpoint();
            progress.clear();
            log->warn("stopped by signal {} after {} births; checkpoint saved. Continue with: morphogen resume {}",
                      StopSignals::signal_number(), ga.births(), s.paths.dir.string());
            return exit_code::interrupted;
        }
        const StepResult out = ga.step(threads, remote.get());
        std::string rows;
        for (std::size_t i = 0; i < out.children.size(); ++i) {
            rows += format_lineage_row(out.children[i], s.lineage_descriptor_columns.value_or(config.qd.descriptors.size()));
            if (!out.errors[i].empty()) {
                progress.clear();
                log->warn("birth {} is invalid: {}", out.children[i].id, out.errors[i]);
            }
        }
        s.lineage.write(rows);
        check_log();
        const std::uint64_t births = ga.births();
        progress.batch(births, births / P, ga.best() ? std::optional<double>(ga.best()->fitness) : std::nullopt);
        if (!out.ends_generation) continue;

        const std::uint64_t generation = births / P - 1;
        HistoryRow row;
        row.generation = generation;
        row.births = births;
        ga.fill(row, out);
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
            if (const Individual* best = ga.exported())
                problem.export_genome(best->params, s.paths.best_stem(generation));
        }
        if (last || every(config.run.checkpoint_every)) checkpoint();
        generation_start = Clock::now();
        generation_first_birth = births;
    }
    progress.clear();
    if (remote && !remote->summary().empty()) s.log.file_only->info("{}", remote->summary());
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
            EliteDriver driver(s.config, problem, s.state, resolve_threads(s.config.run.threads));
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
