#pragma once
// A worker process (rank > 0) of `evolve` or `resume` under mpirun/srun: it
// waits for rank 0's config, builds its own GrowthProblem from it, then scores
// the genomes it is sent with a ThreadEvaluator of run.threads threads (the
// same evaluate_safely as a single-process run, so the same bits) until rank
// 0 says quit. SIGINT and
// SIGTERM are ignored here: rank 0 decides when the job stops (it finishes
// the batch and checkpoints first), and tells every worker.
#include "cluster/world.hpp"

namespace morphogen::cluster {

// Returns the exit code rank 0 sends with its quit message.
int serve(World& world);

}  // namespace morphogen::cluster
