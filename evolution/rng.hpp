#pragma once
// Counter-based random streams. A stream is keyed by (seed, stream index) —
// in the GA the stream index is the birth index — so any birth's randomness
// can be drawn on any thread, in any order, and a run is a pure function of
// (config, seed). The generator is SplitMix64 applied to a counter (a
// counter-based generator: output n = mix(key + n * gamma)); the
// distributions are our own so the numbers do not depend on the standard
// library's implementation.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

namespace morphogen {

class RandomStream {
public:
    RandomStream(std::uint64_t seed, std::uint64_t stream)
        : key_(mix(mix(seed ^ 0x6a09e667f3bcc909ULL) + stream * 0x9e3779b97f4a7c15ULL + 0xbb67ae8584caa73bULL)) {}

    // 64 random bits.
    std::uint64_t next_u64() { return mix(key_ + (++counter_) * 0x9e3779b97f4a7c15ULL); }
    // Uniform in [0, 1), 53 bits.
    double uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }
    // Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // Uniform integer in [0, n), n >= 1, without modulo bias (Lemire).
    std::uint64_t below(std::uint64_t n) {
        unsigned __int128 product = static_cast<unsigned __int128>(next_u64()) * n;
        auto low = static_cast<std::uint64_t>(product);
        if (low < n) {
            const std::uint64_t threshold = (0 - n) % n;
            while (low < threshold) {
                product = static_cast<unsigned __int128>(next_u64()) * n;
                low = static_cast<std::uint64_t>(product);
            }
        }
        return static_cast<std::uint64_t>(product >> 64);
    }
    bool bernoulli(double p) { return uniform() < p; }
    // Standard normal by Box-Muller (both values are not cached: one per call,
    // so the stream position depends only on the number of calls).
    double normal() {
        double u1 = uniform();
        while (u1 <= 0.0) u1 = uniform();
        const double u2 = uniform();
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
    }

    std::uint64_t draws() const { return counter_; }

private:
    static std::uint64_t mix(std::uint64_t z) {
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }

    std::uint64_t key_;
    std::uint64_t counter_ = 0;
};

// `count` parameters uniform in [-range, +range) (docs/algorithm.md §6.3 random
// genomes), each shifted by its `centre` when that is not empty (it then has
// `count` entries). The draws are the same with or without a centre.
inline std::vector<double> random_parameters(std::size_t count, double range, RandomStream& stream,
                                             std::span<const double> centre = {}) {
    std::vector<double> params(count);
    for (double& p : params) p = stream.uniform(-range, range);
    if (!centre.empty())
        for (std::size_t i = 0; i < count; ++i) params[i] += centre[i];
    return params;
}

}  // namespace morphogen
