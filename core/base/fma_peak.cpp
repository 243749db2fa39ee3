#include "core/base/fma_peak.hpp"

#include <ctime>

namespace morphogen {

namespace {

double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

using v4 = double __attribute__((vector_size(32)));

// 12 independent accumulators cover the FMA latency (4-5 cycles) times the
// two FMA pipes; `rounds` iterations of 12 four-wide FMAs = 96 * rounds flop.
[[gnu::target_clones("arch=x86-64-v3", "default"), gnu::noinline]]
double fma_rounds(long rounds, double factor, double offset) {
    v4 acc[12];
    for (int i = 0; i < 12; ++i) acc[i] = v4{} + 1e-3 * i;
    const v4 x = v4{} + factor, y = v4{} + offset;
    for (long n = 0; n < rounds; ++n)
        for (int i = 0; i < 12; ++i) acc[i] = acc[i] * x + y;
    double sum = 0;
    for (int i = 0; i < 12; ++i) sum += acc[i][0] + acc[i][3];
    return sum;
}

}  // namespace

double measure_fma_peak(double seconds) {
    long rounds = 1 << 16;
    double best = 0;
    double spent = 0;
    volatile double sink = 0, factor = 0.999999, offset = 1e-9;  // unknown to the compiler
    while (spent < seconds) {
        const double start = thread_cpu_seconds();
        sink = sink + fma_rounds(rounds, factor, offset);
        const double elapsed = thread_cpu_seconds() - start;
        spent += elapsed;
        if (elapsed > 0.005) {
            const double rate = 96.0 * static_cast<double>(rounds) / elapsed;
            if (rate > best) best = rate;  // the least disturbed slice
        } else {
            rounds *= 2;
        }
    }
    return best;
}

}  // namespace morphogen
