#pragma once
// How many threads score genomes in this process: one resolver for every
// caller (the run's evaluator, the MPI workers, the CVT, the resource
// estimate), so run.threads means the same everywhere.

namespace morphogen {

// The worker threads for a requested count: 0 (or less) = all cores
// (OpenMP's default, which OMP_NUM_THREADS may lower); a request beyond the
// machine's cores is capped to them, since more threads than cores only wait
// for one another. Never below 1.
int resolve_threads(int threads);

}  // namespace morphogen
