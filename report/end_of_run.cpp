#include "report/end_of_run.hpp"

#include "report/report.hpp"
#include "run/exit_codes.hpp"
#include "run/persistence/run_directory.hpp"

#include <iostream>
#include <system_error>

namespace morphogen {

namespace fs = std::filesystem;

int run_session_then_report(RunSession& session, GrowthProblem& problem, const EvaluatorFactory& evaluators,
                            bool with_report) {
    int code = 0;
    {
        SessionEvaluator evaluator = evaluators(session, problem);
        code = run_session(session, problem, evaluator);
    }
    if (code == exit_code::ok && with_report) report_at_end_of_run(session.paths.dir);
    return code;
}

bool report_at_end_of_run(const fs::path& run_dir) {
    try {
        const ReportSummary summary = write_report(run_dir, run_dir / "report", ReportOptions{});
        std::cerr << "report: " << summary.index.string() << '\n';
        return true;
    } catch (const std::exception& e) {
        std::cerr << "morphogen: the run is complete but its report failed: " << e.what()
                  << "; write it with: morphogen report " << run_dir.string() << '\n';
        return false;
    }
}

bool report_is_stale(const fs::path& run_dir) {
    std::error_code ec;
    const auto report = fs::last_write_time(run_dir / "report" / "index.html", ec);
    if (ec) return true;
    const auto checkpoint = fs::last_write_time(run_paths(run_dir).checkpoint, ec);
    return !ec && report < checkpoint;
}

}  // namespace morphogen
