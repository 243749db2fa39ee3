#include "core/growth/signals/signal_diffusion.hpp"

#include <cstddef>
#include <utility>

namespace morphogen {

void diffuse_signal(std::span<double> outputs, int N, std::span<const int> neighbour_offsets,
                    std::span<const int> neighbours, int iterations, double rate, std::vector<double>& scratch) {
    const std::size_t V = neighbour_offsets.size() - 1;
    const auto stride = static_cast<std::size_t>(N);
    // The channel in a compact array: each iteration reads it from every
    // neighbour, and a whole output row per read would pull N doubles into the cache.
    scratch.resize(2 * V);
    double* u = scratch.data();
    double* next = scratch.data() + V;
    for (std::size_t i = 0; i < V; ++i) u[i] = outputs[i * stride + kSignalChannel];
    for (int iteration = 0; iteration < iterations; ++iteration) {
        for (std::size_t i = 0; i < V; ++i) {
            const int first = neighbour_offsets[i], last = neighbour_offsets[i + 1];
            if (last == first) {
                next[i] = u[i];
                continue;
            }
            double sum = 0.0;
            for (int k = first; k < last; ++k) sum += u[neighbours[k]];
            next[i] = u[i] + rate * (sum / static_cast<double>(last - first) - u[i]);
        }
        std::swap(u, next);
    }
    for (std::size_t i = 0; i < V; ++i) outputs[i * stride + kSignalChannel] = u[i];
}

}  // namespace morphogen
