#pragma once
// How many threads score genomes in this process, and starting them.

namespace morphogen {

// The worker threads for run.threads: 0 = all cores (OpenMP's default); a
// request beyond the machine's cores is capped to them, since more threads
// than cores only wait for one another.
int resolve_threads(int threads);

// Starts OpenMP's pool of `threads` workers once, up front. Where the system
// cannot create them (libgomp then ends the process with exit code 1), a
// morphogen line on stderr says how many were asked for and what to lower.
void start_worker_threads(int threads);

}  // namespace morphogen
