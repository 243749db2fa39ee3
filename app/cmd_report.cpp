// `morphogen report RUN_DIR [-o OUT_DIR]`: the static HTML report of a run
// (report.hpp, docs/report.md).
#include "app/commands.hpp"
#include "report/report.hpp"
#include "run/exit_codes.hpp"

#include <filesystem>
#include <iostream>
#include <memory>

namespace morphogen {

namespace {

struct ReportCliOptions {
    std::string dir, out;
    ReportOptions report;
};

int run_report(const ReportCliOptions& o) {
    namespace fs = std::filesystem;
    const fs::path out = o.out.empty() ? fs::path(o.dir) / "report" : fs::path(o.out);
    std::error_code ec;
    if (fs::exists(out) && fs::equivalent(out, o.dir, ec)) {
        std::cerr << "morphogen: -o " << o.out << " is the run directory itself; the report goes in a folder of its own\n";
        return exit_code::usage;
    }
    const ReportSummary summary = write_report(o.dir, out, o.report);
    std::cout << "wrote " << summary.index.string() << " (" << summary.meshes << " generations in the viewer, "
              << summary.ancestors << " ancestors, " << (summary.animation ? "growth animation" : "no animation");
    if (summary.elites > 0) std::cout << ", " << summary.elites << " elites";
    std::cout << ")\n";
    return exit_code::ok;
}

}  // namespace

void add_report_command(CLI::App& root, CommandRunner& selected) {
    auto options = std::make_shared<ReportCliOptions>();
    CLI::App* cmd = root.add_subcommand("report", "Write an HTML report of a run (plots, 3-D viewer, ancestry) that opens offline");
    cmd->add_option("dir", options->dir, "run directory (only read: a run in progress may be reported)")->required();
    cmd->add_option("-o,--out", options->out, "report folder (default RUN_DIR/report)");
    cmd->add_option("--elites", options->report.max_elites, "MAP-Elites: grow the N fittest elites for the viewer")
        ->check(CLI::Range(0, 100000));
    cmd->add_option("--frames", options->report.animation_frames, "frames of the best genome's growth (0 = none)")
        ->check(CLI::Range(0, 1000));
    cmd->add_option("--sheet", options->report.sheet_count, "generations on the contact sheet")
        ->check(CLI::Range(0, 100));
    cmd->add_flag("--no-colour", [options](std::int64_t) { options->report.colour = false; },
                  "the viewer's plants and the pictures in plain green, not in colours from growth history");
    select_on_pick(cmd, selected, options, run_report);
}

}  // namespace morphogen
