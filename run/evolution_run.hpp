#pragma once
// The loop shared by `evolve` and `resume`: the birth pipeline
// (evolution/pipeline.hpp) until run.generations is complete or a stop is
// requested, writing at generation ends the generation's lineage rows, a
// history row, the best mesh (every run.export_every) and a checkpoint (every
// run.checkpoint_every and at the end). Rows written after the last
// checkpoint are cut off by a resume, so the files always equal those of an
// uninterrupted run.
#include "evolution/genome_evaluator.hpp"
#include "run/append_file.hpp"
#include "run/checkpoint.hpp"
#include "run/experiment_config.hpp"
#include "run/growth_problem.hpp"
#include "run/run_directory.hpp"

#include <spdlog/logger.h>

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace morphogen {

struct RunLoggers {
    std::shared_ptr<spdlog::logger> both;       // stderr + log.txt
    std::shared_ptr<spdlog::logger> file_only;  // log.txt
    // The first failure to write log.txt (spdlog's message names the file and
    // the reason), empty while there was none; run_session stops on it.
    std::shared_ptr<std::string> failure;
};

// Console (stderr) and file sinks; log.txt is appended to. Throws IoError
// naming log.txt and the reason if it cannot be opened (e.g. a directory).
RunLoggers make_run_loggers(const RunPaths& paths);

struct RunSession {
    RunPaths paths;
    ExperimentConfig config;  // its run.generations is the target, run.threads the workers
    RunState state;           // where to continue from (births 0 for a new run)
    AppendFile history;       // positioned at the end of state.history's rows
    AppendFile lineage;       // positioned at state.lineage_bytes
    RunLoggers log;
    // Descriptor columns of lineage.csv's rows: the config's descriptors,
    // except for a run begun before lineage.csv had them (resume sets 0).
    std::optional<std::size_t> lineage_descriptor_columns;
};

// Returns exit_code::ok when run.generations is complete, exit_code::interrupted
// after a Ctrl-C/SIGTERM (the checkpoint is saved first; the caller holds the
// StopSignals). A file that cannot be written (a row, the log, an export, a
// checkpoint) throws IoError naming it and the reason; the last checkpoint is
// then intact and the run can be resumed.
int run_session(RunSession& session, GrowthProblem& problem);

// Where run_session has its genomes scored when the process is one of several
// (cluster/: other MPI processes): called once per session with the config
// and the run directory; nullptr, or no factory (the default), scores them
// here with a ThreadEvaluator of run.threads threads.
using RemoteEvaluatorFactory =
    std::function<std::unique_ptr<GenomeEvaluator>(const ExperimentConfig&, const std::filesystem::path& run_dir)>;
void set_remote_evaluator_factory(RemoteEvaluatorFactory factory);

}  // namespace morphogen
