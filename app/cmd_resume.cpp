// `morphogen resume DIR`: continues a run from its checkpoint, exactly as if
// it had never stopped.
#include "app/commands.hpp"
#include "app/resource_options.hpp"
#include "core/base/atomic_file.hpp"
#include "core/base/config_reader.hpp"
#include "core/base/errors.hpp"
#include "report/end_of_run.hpp"
#include "run/persistence/checkpoint_checks.hpp"
#include "run/config/config_migration.hpp"
#include "run/loop/run_session.hpp"
#include "run/exit_codes.hpp"
#include "run/loop/run_records.hpp"
#include "run/persistence/seed_genomes.hpp"
#include "run/searches/run_search.hpp"
#include "run/loop/stop_signals.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>

namespace morphogen {

namespace {
struct ResumeOptions {
    std::string dir;
    std::uint64_t generations = 0;
    int threads = 0;
    bool no_report = false;
    CLI::Option *generations_option = nullptr, *threads_option = nullptr;
    ResourceOptions resources;
    EvaluatorFactory evaluators;
};

// The keys that decide a run's result must be the same in config.json and the
// checkpoint, both resolved in the current format (a run directory of an
// earlier release is migrated); run.generations, threads, checkpoint_every,
// export_every and name may be edited between sessions.
void check_same_experiment(const nlohmann::json& checkpoint_config, const nlohmann::json& file_config,
                           const std::string& file) {
    auto deciding = [](const nlohmann::json& c) {
        nlohmann::json out = nlohmann::json::object();
        for (const char* section : {"network", "growth", "fitness", "evolution", "descriptors", "archive", "emitters"})
            out[section] = c.is_object() && c.contains(section) ? c[section] : nlohmann::json();
        out["run"]["seed"] = c.is_object() && c.contains("run") && c["run"].is_object() && c["run"].contains("seed")
                                 ? c["run"]["seed"]
                                 : nlohmann::json();
        return out;
    };
    const nlohmann::json a = deciding(checkpoint_config), b = deciding(file_config);
    if (a == b) return;
    std::string path = nlohmann::json::diff(a, b).at(0).at("path").get<std::string>();
    for (char& c : path) c = c == '/' ? '.' : c;
    if (!path.empty() && path[0] == '.') path.erase(0, 1);
    throw CheckpointError("checkpoint does not match " + file + ": " + path +
                          " differs (only run.generations, threads, checkpoint_every, export_every and name may "
                          "change between sessions)");
}

int run_resume(const ResumeOptions& o) {
    StopSignals signals;  // first: a signal during start-up is a stop request too
    const RunPaths paths = run_paths(o.dir);
    if (!std::filesystem::is_directory(paths.dir)) throw IoError("run directory " + o.dir + " does not exist");
    if (!std::filesystem::exists(paths.checkpoint)) {
        // Nothing is refused: there is no checkpoint to read (exit 3, not 5).
        if (is_stopped_start(paths))
            throw IoError("no checkpoint in " + o.dir + ": the run stopped before its first checkpoint, " +
                                  "so nothing was lost; start it again with: morphogen evolve CONFIG --out " + o.dir);
        throw IoError("no checkpoint in " + o.dir + " (" + paths.checkpoint.string() + " is missing)");
    }
    RunLock lock(paths.dir);
    // Check everything before changing anything.
    RunState state = load_checkpoint(paths.checkpoint);
    const nlohmann::json on_disk = load_json_file(paths.config.string());
    ConfigOverrides overrides;
    if (*o.generations_option) overrides.generations = o.generations;
    if (*o.threads_option) overrides.threads = o.threads;
    ExperimentConfig config = read_experiment_config(migrate_config(on_disk), paths.config.string(), overrides);
    check_same_experiment(state.config, config.resolved, paths.config.string());
    const auto P = static_cast<std::uint64_t>(config.evolution.population);
    std::size_t lineage_descriptor_columns = config.qd.descriptors.size();
    try {
        const std::string lineage_prefix =
            AppendFile::check_prefix(paths.lineage, state.lineage_bytes, state.lineage_hash);
        std::string header = lineage_header_for(config.qd.measure_names());
        // A MAP-Elites run begun before lineage.csv had descriptor columns
        // keeps its five columns, so that its lineage.csv stays one table.
        if (config.algorithm == Algorithm::map_elites && lineage_prefix.starts_with(lineage_header)) {
            header = lineage_header;
            lineage_descriptor_columns = 0;
        }
        const BirthReplay replay = birth_replay(config);
        check_checkpoint_against_lineage(state, lineage_prefix, P, header, &replay);
    } catch (const std::invalid_argument& e) {
        throw CheckpointError("checkpoint " + paths.checkpoint.string() + " refused: it contradicts " +
                              paths.lineage.string() + ": " + e.what());
    }

    if (state.births() >= (config.run.generations + 1) * P) {
        std::cout << o.dir << ": generation " << config.run.generations
                  << " already reached; nothing to do (pass --generations to go further)\n";
        // A report that failed (a full disk) or was never written is written now.
        if (!o.no_report && report_is_stale(paths.dir)) report_at_end_of_run(paths.dir);
        return exit_code::ok;
    }
    // Check everything before changing anything.
    check_resource_limits(config, evolution_workload(config), o.resources.limits(), paths.config.string());
    GrowthProblem problem(config);
    problem.set_seed_genomes(load_recorded_genomes(paths.dir, config.network.layers()));  // evolve --from's copies
    RunLoggers log = make_run_loggers(paths);
    if (StopSignals::requested()) {
        log.both->warn("stopped by signal {} before resuming; nothing changed. Continue with: morphogen resume {}",
                       StopSignals::signal_number(), o.dir);
        return exit_code::interrupted;
    }

    // Cut everything written after the checkpoint: rows, exports, temporary files.
    prepare_resumed_run_files(paths, state.history.size());
    if (config.resolved != on_disk) write_file_atomically(paths.config, config.resolved.dump(2) + "\n");
    // archive.csv is written just before each checkpoint: a stop between the two leaves a newer one.
    if (const std::string archive = state.search->archive_text(); !archive.empty())
        write_file_atomically(paths.archive, archive);
    std::string history_text = history_header_for(search_kind(config.algorithm).qd_history);
    for (const HistoryRow& row : state.history) history_text += format_history_row(row);
    AppendFile history = AppendFile::create(paths.history, history_text);
    AppendFile lineage = AppendFile::resume(paths.lineage, state.lineage_bytes, state.lineage_hash);
    RunSession session{paths,           config, std::move(state), std::move(history), std::move(lineage),
                       std::move(log), lineage_descriptor_columns};
    session.log.both->info("resuming {} after {} births", o.dir, session.state.births());
    return run_session_then_report(session, problem, o.evaluators, !o.no_report);
}
}  // namespace

void add_resume_command(CLI::App& root, CommandRunner& selected, EvaluatorFactory evaluators) {
    auto options = std::make_shared<ResumeOptions>();
    options->evaluators = std::move(evaluators);
    CLI::App* cmd = root.add_subcommand("resume", "Continue a run from its checkpoint");
    cmd->add_option("dir", options->dir, "run directory")->required();
    options->generations_option =
        cmd->add_option("--generations", options->generations, "total generations to reach (replaces run.generations)");
    options->threads_option = cmd->add_option("--threads", options->threads, "worker threads (0 = all cores)");
    cmd->add_flag("--no-report", options->no_report, "do not write RUN_DIR/report/ at the end (morphogen report)");
    add_resource_options(cmd, options->resources);
    select_on_pick(cmd, selected, options, run_resume);
}

}  // namespace morphogen
