#pragma once
// One session of a run (`evolve`, or one `resume`): its directory, config,
// state so far, open record files and logs, as the run loop
// (evolution_run.hpp) and its recorder (run_recorder.hpp) share them.
#include "core/base/append_file.hpp"
#include "run/persistence/checkpoint.hpp"
#include "run/config/experiment_config.hpp"
#include "run/persistence/run_directory.hpp"
#include "run/loop/run_state.hpp"

#include <spdlog/logger.h>

#include <cstddef>
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

}  // namespace morphogen
