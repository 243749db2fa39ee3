#pragma once
// One function per CLI verb registers its subcommand. When the user picks a
// subcommand, its callback stores the work to do in `selected`; main() runs it
// and maps exceptions to exit codes (exit_codes.hpp).
#include <CLI/CLI.hpp>

#include <functional>

namespace morphogen {

using CommandRunner = std::function<int()>;

void add_grow_command(CLI::App& root, CommandRunner& selected);
void add_gallery_command(CLI::App& root, CommandRunner& selected);
void add_render_command(CLI::App& root, CommandRunner& selected);
void add_bench_command(CLI::App& root, CommandRunner& selected);
void add_evolve_command(CLI::App& root, CommandRunner& selected);
void add_resume_command(CLI::App& root, CommandRunner& selected);
void add_validate_command(CLI::App& root, CommandRunner& selected);
void add_score_command(CLI::App& root, CommandRunner& selected);
void add_archive_command(CLI::App& root, CommandRunner& selected);
void add_report_command(CLI::App& root, CommandRunner& selected);

}  // namespace morphogen
