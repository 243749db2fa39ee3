#include "gather_kernel.hpp"

#include <algorithm>
#include <cmath>

namespace morphogen::kernel {

namespace {

// N_FIXED > 0 lets the compiler unroll and vectorise the channel loops fully.
template <int N_FIXED>
[[gnu::always_inline]] inline void gather_all(const GatherInput& in, double* inputs) {
    const int N = N_FIXED > 0 ? N_FIXED : in.outputs;
    for (int i = 0; i < in.vertices; ++i) {
        double* own = inputs + static_cast<std::ptrdiff_t>(3 * N) * i;
        double* mean = own + N;
        double* deviation = own + 2 * N;
        std::copy_n(in.previous + static_cast<std::ptrdiff_t>(N) * i, N, own);

        const int* first = in.neighbours + in.neighbour_offsets[i];
        const int* last = in.neighbours + in.neighbour_offsets[i + 1];
        const double inverse_count = 1.0 / static_cast<double>(last - first);
        for (int c = 0; c < N; ++c) mean[c] = 0.0;
        for (const int* u = first; u != last; ++u) {
            const double* wu = in.previous + static_cast<std::ptrdiff_t>(N) * *u;
            for (int c = 0; c < N; ++c) mean[c] += wu[c];
        }
        for (int c = 0; c < N; ++c) mean[c] *= inverse_count;
        // Two passes: the deviation without cancellation.
        for (int c = 0; c < N; ++c) deviation[c] = 0.0;
        for (const int* u = first; u != last; ++u) {
            const double* wu = in.previous + static_cast<std::ptrdiff_t>(N) * *u;
            for (int c = 0; c < N; ++c) {
                const double d = wu[c] - mean[c];
                deviation[c] += d * d;
            }
        }
        for (int c = 0; c < N; ++c) deviation[c] = std::sqrt(deviation[c] * inverse_count);

        const Eigen::Vector3d& h = in.directions[i];
        own[3 * N - 4] = 0.5 + 0.5 * h.x();
        own[3 * N - 3] = 0.5 + 0.5 * h.y();
        own[3 * N - 2] = 0.5 + 0.5 * h.z();
        own[3 * N - 1] = in.positions[i].z() / in.height_scale;
    }
}

}  // namespace

[[gnu::target_clones("arch=x86-64-v3", "default")]]
void gather_inputs(const GatherInput& in, double* inputs) {
    if (in.outputs == 15)
        gather_all<15>(in, inputs);  // the default network
    else
        gather_all<0>(in, inputs);
}

}  // namespace morphogen::kernel
