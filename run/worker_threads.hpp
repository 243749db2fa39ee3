#pragma once
// How many threads score genomes in this process.

namespace morphogen {

// The worker threads for run.threads: 0 = all cores (OpenMP's default); a
// request beyond the machine's cores is capped to them, since more threads
// than cores only wait for one another.
int resolve_threads(int threads);

}  // namespace morphogen
