#include "run/loop/run_session.hpp"

#include "core/base/errors.hpp"
#include "evolution/execution/thread_evaluator.hpp"
#include "run/exit_codes.hpp"
#include "run/growth_problem.hpp"
#include "run/loop/progress.hpp"
#include "run/loop/run_recorder.hpp"
#include "run/searches/run_search.hpp"
#include "run/loop/stop_signals.hpp"
#include "core/base/parallel_for.hpp"

#include <algorithm>
#include <optional>

namespace morphogen {

SessionEvaluator local_evaluator(const RunSession& session, GrowthProblem& problem) {
    const ExperimentConfig& config = session.config;
    const BirthSchedule schedule = birth_schedule(config.evolution);
    // More threads than births in flight would have nothing to do.
    const int threads = std::min<long long>(resolve_threads(config.run.threads), static_cast<long long>(schedule.width));
    if (config.run.threads > threads)
        session.log.both->warn("run.threads {} is more than can run at once here ({} cores, {} births in flight: {}): "
                               "using {} threads",
                               config.run.threads, machine_cores(), schedule.width, schedule.describe(), threads);
    return {std::make_unique<ThreadEvaluator>(problem, threads), false};
}

namespace {
void log_start(const RunSession& session, const RunSearch& search, const SessionEvaluator& scoring,
               const BirthSchedule& schedule) {
    const ExperimentConfig& config = session.config;
    const GenomeEvaluator& evaluator = *scoring.evaluator;
    auto& log = session.log.both;
    log->info("run directory {}: population {}, generation {}/{} ({} births done), {}, {}, seed {}",
              session.paths.dir.string(), config.evolution.population, search.completed_generations(),
              config.run.generations, search.births(),
              scoring.remote ? "scored over MPI" : evaluator.description(), schedule.describe(), config.run.seed);
    if (scoring.remote) log->info("genomes are grown and scored by {}", evaluator.description());
    if (schedule.kind == ScheduleKind::pipeline && schedule.width < 2 * static_cast<std::uint64_t>(evaluator.capacity()))
        log->warn("evolution.lag {} keeps fewer than 2 genomes in flight per thread ({} threads): some will wait; "
                  "a larger lag keeps them busy (docs/performance.md)",
                  schedule.width, evaluator.capacity());
}

void log_end(const RunSession& session, const RunSearch& search, const SessionEvaluator& scoring) {
    if (scoring.remote && !scoring.evaluator->summary().empty())
        session.log.file_only->info("{}", scoring.evaluator->summary());
    if (const std::optional<Individual>& best = search.best())
        session.log.both->info("done: generation {} reached; best fitness {} (individual {})",
                               session.config.run.generations, format_number(best->fitness), best->id);
    else
        session.log.both->info("done: generation {} reached; no valid individual", session.config.run.generations);
}

std::optional<double> best_fitness(const RunSearch& search) {
    const std::optional<Individual>& best = search.best();
    return best ? std::optional<double>(best->fitness) : std::nullopt;
}

int run_loop(RunSession& session, GrowthProblem& problem, RunSearch& search, SessionEvaluator& scoring) {
    const ExperimentConfig& config = session.config;
    const std::uint64_t target_births = (config.run.generations + 1) * static_cast<std::uint64_t>(config.evolution.population);
    const BirthSchedule schedule = birth_schedule(config.evolution);
    log_start(session, search, scoring, schedule);

    Progress progress(session.log.both, session.log.file_only, target_births, config.run.generations);
    BirthPipeline pipeline(schedule, search.breeder(), *scoring.evaluator, std::move(session.state.pending));
    // After the pipeline, so its writes finish before the pipeline abandons what is in flight.
    RunRecorder recorder(session, problem, search, pipeline, progress);
    const auto on_insert = [&recorder](const Individual& child, const std::string& error, const Inserted& what,
                                       const std::string& kept) { recorder.inserted(child, error, what, kept); };

    progress.update(search.births(), search.completed_generations(), best_fitness(search));
    if (!pipeline.run(target_births, on_insert, [] { return StopSignals::requested(); })) {
        recorder.checkpoint();
        recorder.drain();
        progress.clear();
        session.log.both->warn(
            "stopped by signal {} after {} births; checkpoint saved. Continue with: morphogen resume {}",
            StopSignals::signal_number(), search.births(), session.paths.dir.string());
        return exit_code::interrupted;
    }
    recorder.drain();
    progress.clear();
    log_end(session, search, scoring);
    return exit_code::ok;
}

}  // namespace

int run_session(RunSession& session, GrowthProblem& problem, SessionEvaluator& evaluator) {
    try {
        const std::unique_ptr<RunSearch> search = session.state.search->start(session.config, problem);
        return run_loop(session, problem, *search, evaluator);
    } catch (const IoError& e) {
        throw IoError(std::string(e.what()) + " (the last checkpoint is intact: free space or fix the file, then " +
                      "continue with morphogen resume " + session.paths.dir.string() + ")");
    }
}

}  // namespace morphogen
