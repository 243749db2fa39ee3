#pragma once
// What `evolve` and `resume` do once their checks are done: run the session,
// then write the report of a complete run.
#include "run/loop/run_session.hpp"
#include "run/growth_problem.hpp"

#include <filesystem>

namespace morphogen {

// run_session with the evaluator `evaluators` makes (gone before the
// report), then (when it completed the run and `with_report`)
// report_at_end_of_run. Returns run_session's exit code.
int run_session_then_report(RunSession& session, GrowthProblem& problem, const EvaluatorFactory& evaluators,
                            bool with_report);

// The report into RUN_DIR/report with default options. A failure does not
// fail the run: it is printed (with the command that writes the report
// again) and false returned.
bool report_at_end_of_run(const std::filesystem::path& run_dir);

// True when RUN_DIR/report/index.html is missing or older than the
// checkpoint: a complete run whose report failed or was never written
// (`resume` writes it then).
bool report_is_stale(const std::filesystem::path& run_dir);

}  // namespace morphogen
