#include "evolution/archives/cvt.hpp"

#include "core/base/parallel_for.hpp"
#include "evolution/rng.hpp"


#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>

namespace morphogen {

namespace {
// Samples handed to a thread at a time: one sample's nearest centroid is a
// few hundred flops, too little to hand out alone.
constexpr std::size_t kCvtGrain = 64;
}  // namespace

std::size_t nearest_centroid(std::span<const double> centroids, std::span<const double> point) {
    const std::size_t d = point.size();
    const std::size_t cells = centroids.size() / d;
    std::size_t best = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < cells; ++c) {
        const double* centroid = centroids.data() + c * d;
        double distance = 0.0;
        for (std::size_t k = 0; k < d; ++k) {
            const double delta = point[k] - centroid[k];
            distance += delta * delta;
        }
        if (distance < best_distance) {  // strict: ties keep the lower index
            best_distance = distance;
            best = c;
        }
    }
    return best;
}

std::vector<double> cvt_centroids(std::uint64_t seed, std::uint64_t cells, std::size_t dimensions, int threads,
                                  const CvtWatch& watch) {
    if (cells < 1 || cells > kMaxCvtCells)
        throw std::invalid_argument("a CVT archive places 1 to " + std::to_string(kMaxCvtCells) + " cells, not " +
                                    std::to_string(cells));
    if (dimensions < 1) throw std::invalid_argument("a CVT archive needs at least one descriptor");
    threads = resolve_threads(threads);
    const auto k = static_cast<std::size_t>(cells);
    const std::size_t count = std::max(kCvtMinSamples, kCvtSamplesPerCell * k);

    RandomStream stream(seed, kCvtStream);
    std::vector<double> samples(count * dimensions);
    for (double& x : samples) x = stream.uniform();
    std::vector<double> centroids(samples.begin(), samples.begin() + static_cast<std::ptrdiff_t>(k * dimensions));

    std::vector<std::size_t> assignment(count, k);  // k: not yet assigned
    std::vector<double> sums(k * dimensions);
    std::vector<std::size_t> members(k);
    for (int round = 0; round < kCvtLloydIterations; ++round) {
        std::atomic<bool> changed{false};
        // In blocks, so that a stop is noticed within a fraction of a round;
        // each sample's assignment is its own, so blocks change no result.
        for (std::size_t first = 0; first < count; first += kCvtStopBlock) {
            if (watch.stop && watch.stop()) return {};
            const std::size_t last = std::min(count, first + kCvtStopBlock);
            parallel_for(
                last - first, threads,
                [&](std::size_t i, int) {
                    const std::size_t j = first + i;
                    const std::size_t nearest = nearest_centroid(
                        centroids, std::span<const double>(samples.data() + j * dimensions, dimensions));
                    if (nearest != assignment[j]) {
                        assignment[j] = nearest;
                        changed.store(true, std::memory_order_relaxed);
                    }
                },
                kCvtGrain);
        }
        if (watch.round_done) watch.round_done(round + 1);
        if (!changed.load()) break;
        std::fill(sums.begin(), sums.end(), 0.0);
        std::fill(members.begin(), members.end(), 0);
        for (std::size_t j = 0; j < count; ++j) {
            const std::size_t c = assignment[j];
            ++members[c];
            for (std::size_t d = 0; d < dimensions; ++d) sums[c * dimensions + d] += samples[j * dimensions + d];
        }
        for (std::size_t c = 0; c < k; ++c) {
            if (members[c] == 0) continue;
            for (std::size_t d = 0; d < dimensions; ++d)
                centroids[c * dimensions + d] = sums[c * dimensions + d] / static_cast<double>(members[c]);
        }
    }
    return centroids;
}

}  // namespace morphogen
