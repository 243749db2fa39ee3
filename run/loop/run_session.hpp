#pragma once
// The loop shared by `evolve` and `resume`: the birth pipeline
// (evolution/execution/pipeline.hpp) over the run's search (run_search.hpp) until
// run.generations is complete or a stop is requested; a RunRecorder
// (run_recorder.hpp) writes the rows, exports and checkpoints. Rows written
// after the last checkpoint are cut off by a resume, so the files always
// equal those of an uninterrupted run.
#include "evolution/execution/genome_evaluator.hpp"
#include "run/growth_problem.hpp"
#include "run/loop/session_files.hpp"

#include <functional>
#include <memory>

namespace morphogen {

// Where a session scores its genomes (docs/algorithm.md §8.4).
struct SessionEvaluator {
    std::unique_ptr<GenomeEvaluator> evaluator;
    bool remote = false;  // by other processes (cluster/): this one only conceives, inserts and writes
};
// Chosen by the command (app/main.cpp: this process, or the MPI workers),
// asked once per session when the run directory is ready.
using EvaluatorFactory = std::function<SessionEvaluator(const RunSession& session, GrowthProblem& problem)>;

// Scores in this process: a ThreadEvaluator of run.threads threads, capped
// at the cores and at the births that can be in flight at once (the log
// says so when it caps).
SessionEvaluator local_evaluator(const RunSession& session, GrowthProblem& problem);

// Runs the session's search with `evaluator` until run.generations is
// complete (exit_code::ok) or a Ctrl-C/SIGTERM (exit_code::interrupted, the
// checkpoint saved first; the caller holds the StopSignals). A file that
// cannot be written (a row, the log, an export, a checkpoint) throws IoError
// naming it and the reason; the last checkpoint is then intact and the run
// can be resumed.
int run_session(RunSession& session, GrowthProblem& problem, SessionEvaluator& evaluator);

}  // namespace morphogen
