#include "gather_kernel.hpp"

#include <algorithm>
#include <cmath>

namespace morphogen::kernel {

namespace {

// Mean and population deviation of `count` neighbour rows, channel by channel,
// in two passes (no cancellation). Local accumulators: they cannot alias the
// outputs, so the channel loops vectorise without run-time overlap checks.
// Only the first D deviations are computed: the last four inputs (the
// deviations of channels N-4..N-1) are overwritten by direction and height.
template <int N, int D = N - 4>
[[gnu::always_inline]] inline void mean_and_deviation(const double* previous, const int* first, const int* last,
                                                      double* mean_out, double* deviation_out) {
    double mean[N] = {}, deviation[D] = {};
    const double inverse_count = 1.0 / static_cast<double>(last - first);
    for (const int* u = first; u != last; ++u) {
        const double* wu = previous + static_cast<std::ptrdiff_t>(N) * *u;
        for (int c = 0; c < N; ++c) mean[c] += wu[c];
    }
    for (int c = 0; c < N; ++c) mean[c] *= inverse_count;
    for (const int* u = first; u != last; ++u) {
        const double* wu = previous + static_cast<std::ptrdiff_t>(N) * *u;
        for (int c = 0; c < D; ++c) {
            const double d = wu[c] - mean[c];
            deviation[c] += d * d;
        }
    }
    for (int c = 0; c < N; ++c) mean_out[c] = mean[c];
    for (int c = 0; c < D; ++c) deviation_out[c] = std::sqrt(deviation[c] * inverse_count);
}

// Copies one row of N doubles with vector moves (GCC would call memcpy).
template <int N>
[[gnu::always_inline]] inline void copy_row(const double* from, double* to) {
    using v4 = double __attribute__((vector_size(32)));
    int c = 0;
    for (; c + 4 <= N; c += 4) {
        v4 v;
        __builtin_memcpy(&v, from + c, sizeof v);
        __builtin_memcpy(to + c, &v, sizeof v);
    }
    for (; c < N; ++c) to[c] = from[c];
}

// Any N: the same computation with the outputs as accumulators.
[[gnu::always_inline]] inline void mean_and_deviation(int N, const double* previous, const int* first,
                                                      const int* last, double* mean, double* deviation) {
    const double inverse_count = 1.0 / static_cast<double>(last - first);
    std::fill_n(mean, N, 0.0);
    std::fill_n(deviation, N, 0.0);
    for (const int* u = first; u != last; ++u)
        for (int c = 0; c < N; ++c) mean[c] += previous[static_cast<std::ptrdiff_t>(N) * *u + c];
    for (int c = 0; c < N; ++c) mean[c] *= inverse_count;
    for (const int* u = first; u != last; ++u)
        for (int c = 0; c < N; ++c) {
            const double d = previous[static_cast<std::ptrdiff_t>(N) * *u + c] - mean[c];
            deviation[c] += d * d;
        }
    for (int c = 0; c < N; ++c) deviation[c] = std::sqrt(deviation[c] * inverse_count);
}

// N_FIXED > 0 lets the compiler unroll and vectorise the channel loops fully.
template <int N_FIXED>
[[gnu::always_inline]] inline void gather_range(const GatherInput& in, int first, int count, double* inputs) {
    const int N = N_FIXED > 0 ? N_FIXED : in.outputs;
    for (int i = first; i < first + count; ++i) {
        double* own = inputs + static_cast<std::ptrdiff_t>(3 * N) * (i - first);
        if constexpr (N_FIXED > 0)
            copy_row<N_FIXED>(in.previous + static_cast<std::ptrdiff_t>(N) * i, own);
        else
            std::copy_n(in.previous + static_cast<std::ptrdiff_t>(N) * i, N, own);
        const int* neighbours_begin = in.neighbours + in.neighbour_offsets[i];
        const int* neighbours_end = in.neighbours + in.neighbour_offsets[i + 1];
        if constexpr (N_FIXED > 0)
            mean_and_deviation<N_FIXED>(in.previous, neighbours_begin, neighbours_end, own + N, own + 2 * N);
        else
            mean_and_deviation(N, in.previous, neighbours_begin, neighbours_end, own + N, own + 2 * N);

        const Eigen::Vector3d& h = in.directions[i];
        own[3 * N - 4] = 0.5 + 0.5 * h.x();
        own[3 * N - 3] = 0.5 + 0.5 * h.y();
        own[3 * N - 2] = 0.5 + 0.5 * h.z();
        own[3 * N - 1] = in.positions[i].z() / in.height_scale;
    }
}

}  // namespace

[[gnu::target_clones("arch=x86-64-v3", "default")]]
void gather_inputs(const GatherInput& in, int first, int count, double* inputs) {
    if (in.outputs == 15)
        gather_range<15>(in, first, count, inputs);  // the default network
    else
        gather_range<0>(in, first, count, inputs);
}

}  // namespace morphogen::kernel
