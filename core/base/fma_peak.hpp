#pragma once
// The double-precision FMA throughput one core delivers right now, for the
// benchmark to state its figures as a fraction of the machine's peak (on a
// shared machine the peak itself moves from minute to minute).

namespace morphogen {

// Runs independent FMA chains (AVX2 where the CPU has it, as the network
// kernel does) for about `seconds` of CPU time; returns flop/s.
double measure_fma_peak(double seconds);

}  // namespace morphogen
