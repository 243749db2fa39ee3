#include "run/loop/session_files.hpp"

#include "core/base/errors.hpp"

#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>

namespace morphogen {

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

}  // namespace morphogen
