#pragma once
// Centroids of a centroidal Voronoi tessellation (CVT) of the unit cube
// [0,1]^d, drawn from the run's seed alone (docs/algorithm.md §9.3, docs/map-elites.md):
//
// - samples: S = max(kCvtMinSamples, kCvtSamplesPerCell * cells) points, all
//   from the one stream RandomStream(seed, kCvtStream) (an index no birth
//   reaches), point j's coordinates drawn in order k = 0..d-1 with uniform();
// - start: the centroids are the first `cells` samples (Forgy's method);
// - Lloyd: kCvtLloydIterations rounds of "assign every sample to its nearest
//   centroid (ties: the lower index), move every centroid to the mean of its
//   samples (summed in sample order); a centroid with no samples stays". A
//   round in which no assignment changes would leave every centroid as it is,
//   so the rounds stop there: the result is that of the full count.
//
// Assignment runs in parallel (it is per sample); sums are sequential, so the
// centroids are the same for every thread count.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <vector>

namespace morphogen {

inline constexpr std::uint64_t kCvtStream = std::numeric_limits<std::uint64_t>::max();
inline constexpr std::size_t kCvtMinSamples = 10'000;
inline constexpr std::size_t kCvtSamplesPerCell = 20;
inline constexpr int kCvtLloydIterations = 20;
// The most cells a CVT archive places: k-means costs samples x cells per
// round (20 x 10,000^2 x 20 rounds = 4e10 distances at the limit).
inline constexpr std::uint64_t kMaxCvtCells = 10'000;

// Index of the centroid nearest to `point` (squared Euclidean distance,
// summed over k in order; ties: the lower index). `centroids` is row-major,
// cells x point.size(), non-empty.
std::size_t nearest_centroid(std::span<const double> centroids, std::span<const double> point);

// Who watches a long placement (10,000 cells take minutes): `stop` is asked
// between blocks of kCvtStopBlock samples and ends the placement when true;
// `round_done(r)` is told after Lloyd round r (1-based). Either may be empty.
struct CvtWatch {
    std::function<bool()> stop;
    std::function<void(int round)> round_done;
};
inline constexpr std::size_t kCvtStopBlock = 4096;

// Row-major cells x dimensions centroids in [0,1]^dimensions; empty if
// watch.stop ended the placement. Throws std::invalid_argument unless
// 1 <= cells <= kMaxCvtCells and dimensions >= 1. threads: resolve_threads (core/base/parallel_for.hpp).
std::vector<double> cvt_centroids(std::uint64_t seed, std::uint64_t cells, std::size_t dimensions, int threads = 0,
                                  const CvtWatch& watch = {});

}  // namespace morphogen
