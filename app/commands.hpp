#pragma once
// One function per CLI verb registers its subcommand. When the user picks a
// subcommand, its callback stores the work to do in `selected`; main() runs it
// and maps exceptions to exit codes (exit_codes.hpp).
#include "run/loop/run_session.hpp"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>

namespace morphogen {

using CommandRunner = std::function<int()>;

void add_grow_command(CLI::App& root, CommandRunner& selected);
void add_gallery_command(CLI::App& root, CommandRunner& selected);
void add_render_command(CLI::App& root, CommandRunner& selected);
void add_bench_command(CLI::App& root, CommandRunner& selected);
// `evaluators` scores the genomes of their sessions (local_evaluator, or the MPI workers).
void add_evolve_command(CLI::App& root, CommandRunner& selected, EvaluatorFactory evaluators);
void add_resume_command(CLI::App& root, CommandRunner& selected, EvaluatorFactory evaluators);
void add_validate_command(CLI::App& root, CommandRunner& selected);
void add_score_command(CLI::App& root, CommandRunner& selected);
void add_archive_command(CLI::App& root, CommandRunner& selected);
void add_report_command(CLI::App& root, CommandRunner& selected);
void add_breed_command(CLI::App& root, CommandRunner& selected);

// What the commands' registrations share.

// When `cmd` is picked, `selected` becomes run(*options); `check`, if given,
// first vets the options together (throwing a CLI::Error).
template <class Options, class Run, class Check = std::nullptr_t>
void select_on_pick(CLI::App* cmd, CommandRunner& selected, std::shared_ptr<Options> options, Run run,
                    Check check = nullptr) {
    cmd->callback([options, run, check, &selected] {
        if constexpr (!std::is_same_v<Check, std::nullptr_t>) check();
        selected = [options, run] { return run(*options); };
    });
}

// --config FILE: an experiment config; what it omits (or everything, without
// the option) takes the defaults.
inline CLI::Option* add_config_option(CLI::App* cmd, std::string& path,
                                      const std::string& help = "Experiment config (JSON); defaults if omitted") {
    return cmd->add_option("--config", path, help)->check(CLI::ExistingFile);
}

// How messages name the config of --config: its path, or "default config".
inline std::string config_source(const std::string& path) { return path.empty() ? "default config" : path; }

}  // namespace morphogen
