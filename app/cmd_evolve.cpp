// `morphogen evolve CONFIG`: checks the config, makes a new run directory and
// runs its search (evolution_run.hpp).
#include "app/commands.hpp"
#include "app/resource_options.hpp"
#include "core/base/atomic_file.hpp"
#include "core/base/errors.hpp"
#include "report/end_of_run.hpp"
#include "run/loop/run_session.hpp"
#include "run/exit_codes.hpp"
#include "run/loop/run_records.hpp"
#include "run/persistence/seed_genomes.hpp"
#include "run/searches/run_search.hpp"
#include "run/loop/stop_signals.hpp"
#include "core/base/parallel_for.hpp"

#include <chrono>
#include <iostream>
#include <memory>

namespace morphogen {

namespace {
struct EvolveOptions {
    std::string config, out;
    std::vector<std::string> from;
    std::uint64_t seed = 0, generations = 0;
    int threads = 0;
    bool force = false, no_report = false;
    CLI::Option *seed_option = nullptr, *generations_option = nullptr, *threads_option = nullptr;
    ResourceOptions resources;
    EvaluatorFactory evaluators;
};

int run_evolve(const EvolveOptions& o) {
    StopSignals signals;  // first: a signal during start-up is a stop request too
    ConfigOverrides overrides;
    if (*o.seed_option) overrides.seed = o.seed;
    if (*o.generations_option) overrides.generations = o.generations;
    if (*o.threads_option) overrides.threads = o.threads;
    ExperimentConfig config = load_experiment_config(o.config, overrides);  // every problem, before anything else
    check_resource_limits(config, evolution_workload(config), o.resources.limits(), o.config);
    GrowthProblem problem(config);  // a bad seed mesh file fails here, before the directory exists
    // --from adds to run.from; the genomes are read (and their shapes checked) before the directory exists.
    if (!o.from.empty()) {
        config.run.from.insert(config.run.from.end(), o.from.begin(), o.from.end());
        config.resolved["run"]["from"] = config.run.from;
    }
    const std::vector<GivenGenome> given = read_given_genomes(config.run.from, config.network.layers());
    if (given.size() > static_cast<std::size_t>(config.evolution.population))
        throw ConfigError("run.from and --from name " + std::to_string(given.size()) +
                          " genomes, more than generation 0 holds (evolution.population " +
                          std::to_string(config.evolution.population) + ")");

    const RunPaths paths =
        run_paths(o.out.empty() ? default_run_dir(config.run.name, std::chrono::system_clock::now())
                                : std::filesystem::path(o.out));
    if (StopSignals::requested()) {
        std::cerr << "morphogen: stopped by signal " << StopSignals::signal_number() << " before "
                  << paths.dir.string() << " was touched\n";
        return exit_code::interrupted;
    }
    // Until the first checkpoint is saved the directory is a "stopped start"
    // (run_directory.hpp), which a new evolve may reuse without --force.
    const bool restart = is_stopped_start(paths);
    create_run_dir(paths, o.force);
    RunLock lock(paths.dir);
    clear_run_files(paths);
    if (!given.empty()) {
        // The copies in RUN_DIR/seeds/ are what this run and every resume start from.
        record_given_genomes(paths.dir, given, config.network.layers());
        problem.set_seed_genomes(load_recorded_genomes(paths.dir, config.network.layers()));
    }
    RunLoggers log = make_run_loggers(paths);
    if (restart)
        log.both->info("{} held a run stopped before its first checkpoint; starting it again", paths.dir.string());
    write_file_atomically(paths.config, config.resolved.dump(2) + "\n");

    const SearchKind& search = search_kind(config.algorithm);
    RunSession session{paths,
                       config,
                       RunState{},
                       AppendFile::create(paths.history, history_header_for(search.qd_history)),
                       AppendFile::create(paths.lineage, lineage_header_for(config.qd.measure_names())),
                       std::move(log),
                       std::nullopt};
    // The first checkpoint (no births yet) makes the directory resumable.
    session.state.config = config.resolved;
    session.state.seed = config.run.seed;
    session.state.lineage_bytes = session.lineage.size();
    session.state.lineage_hash = session.lineage.hash_hex();
    session.state.search = search.initial(config, resolve_threads(config.run.threads), session.log.both.get());
    if (!session.state.search) {
        session.log.both->warn("stopped by signal {} while the search's first state was made (the CVT centroids "
                               "placed), before the first checkpoint: nothing was lost; start it again with the same "
                               "command",
                               StopSignals::signal_number());
        return exit_code::interrupted;
    }
    // archive.csv (a search that keeps one) before the checkpoint that refers to it.
    if (const std::string archive = session.state.search->archive_text(); !archive.empty())
        write_file_atomically(paths.archive, archive);
    save_checkpoint(paths.checkpoint, session.state);
    return run_session_then_report(session, problem, o.evaluators, !o.no_report);
}
}  // namespace

void add_evolve_command(CLI::App& root, CommandRunner& selected, EvaluatorFactory evaluators) {
    auto options = std::make_shared<EvolveOptions>();
    options->evaluators = std::move(evaluators);
    CLI::App* cmd = root.add_subcommand("evolve", "Run the search of a config (the GA, MAP-Elites or novelty search) into a new run directory");
    cmd->add_option("config", options->config, "experiment config (JSON)")->required()->check(CLI::ExistingFile);
    cmd->add_option("--out", options->out, "run directory (default runs/<name>-<YYYYmmdd-HHMMSS>)");
    options->seed_option = cmd->add_option("--seed", options->seed, "replaces run.seed");
    options->generations_option = cmd->add_option("--generations", options->generations, "replaces run.generations");
    options->threads_option = cmd->add_option("--threads", options->threads, "replaces run.threads (0 = all cores)");
    cmd->add_option("--from", options->from,
                    "start generation 0 from a genome file, a run directory (best, or MAP-Elites elites) or a breed "
                    "session's exports; repeatable, adds to run.from");
    cmd->add_flag("--force", options->force, "reuse a non-empty run directory (removes its morphogen files)");
    cmd->add_flag("--no-report", options->no_report, "do not write RUN_DIR/report/ at the end (morphogen report)");
    add_resource_options(cmd, options->resources);
    select_on_pick(cmd, selected, options, run_evolve);
}

}  // namespace morphogen
