#pragma once
// Novelty and local competition (docs/algorithm.md §14.2-§14.3; Lehman &
// Stanley 2011): the two objectives of novelty search with local
// competition, and the one strict order that ranks individuals by them. Pure
// functions of the points they are given, so the search that uses them is
// the same for every thread count.
#include "evolution/archives/archive.hpp"
#include "evolution/individual.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace morphogen {

// One point of behaviour space: an individual's id, fitness and descriptors
// (its behaviour, one value per range).
struct BehaviourPoint {
    std::uint64_t id = 0;
    double fitness = 0.0;
    std::span<const double> descriptors;
};

// Distance of two behaviours (§14.1): the Euclidean norm of
// (a_k - b_k) / (max_k - min_k) over the ranges, summed in order k = 0, 1, ...
double behaviour_distance(std::span<const double> a, std::span<const double> b,
                          std::span<const DescriptorRange> ranges);

struct NoveltyScore {
    double novelty = 0.0;      // mean distance to the k nearest neighbours
    double competition = 0.0;  // fraction of those neighbours with a lower fitness
    std::uint64_t front = 0;   // Pareto front of (novelty, competition), 0 = not dominated
};

// The novelty and local competition of each of `members` (§14.2): its
// neighbours are every point of `members` and `others` but itself, one point
// per id (a point of `others` whose id is a member's is that member); the k
// nearest by (distance, id) count, k = min(k, neighbours). No neighbour: both
// 0. `front` is left 0 (see pareto_fronts).
std::vector<NoveltyScore> novelty_scores(std::span<const BehaviourPoint> members, std::span<const BehaviourPoint> others,
                                         std::span<const DescriptorRange> ranges, int k);

// Sets every score's front (§14.3): 0 for the scores no other dominates, f
// for those whose longest chain of dominating scores has f links (NSGA-II's
// non-dominated sorting). a dominates b when a is at least as high in both
// objectives and higher in one.
void pareto_fronts(std::span<NoveltyScore> scores);

// True if member a ranks above member b (§14.3): the lower front; then the
// higher novelty; then the higher local competition; then the younger (the
// higher id). A strict total order for distinct ids.
bool novelty_ranks_above(const NoveltyScore& a, std::uint64_t a_id, const NoveltyScore& b, std::uint64_t b_id);

// Novelty, local competition and fronts of `members` against themselves and
// `others` (the archive): novelty_scores then pareto_fronts.
std::vector<NoveltyScore> ranked_scores(std::span<const BehaviourPoint> members, std::span<const BehaviourPoint> others,
                                        std::span<const DescriptorRange> ranges, int k);

// The point of a valid individual (its descriptors must outlive the point).
inline BehaviourPoint behaviour_point(const Individual& individual) {
    return {individual.id, individual.fitness, individual.descriptors};
}

}  // namespace morphogen
