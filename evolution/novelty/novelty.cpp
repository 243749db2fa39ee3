#include "evolution/novelty/novelty.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace morphogen {

double behaviour_distance(std::span<const double> a, std::span<const double> b, std::span<const DescriptorRange> ranges) {
    double sum = 0.0;
    for (std::size_t k = 0; k < ranges.size(); ++k) {
        const double d = (a[k] - b[k]) / (ranges[k].max - ranges[k].min);
        sum += d * d;
    }
    return std::sqrt(sum);
}

namespace {
struct Neighbour {
    double distance;
    std::uint64_t id;
    double fitness;
};

NoveltyScore score_of(const BehaviourPoint& self, std::span<const BehaviourPoint> members,
                      std::span<const BehaviourPoint> others, std::span<const DescriptorRange> ranges, int k,
                      std::vector<Neighbour>& scratch) {
    scratch.clear();
    for (std::span<const BehaviourPoint> points : {members, others})
        for (const BehaviourPoint& p : points)
            if (p.id != self.id)
                scratch.push_back({behaviour_distance(self.descriptors, p.descriptors, ranges), p.id, p.fitness});
    NoveltyScore score;
    const std::size_t n = std::min(scratch.size(), static_cast<std::size_t>(std::max(k, 0)));
    if (n == 0) return score;
    // (distance, id) is a strict total order, so the k nearest and their
    // order do not depend on the sort's algorithm.
    std::partial_sort(scratch.begin(), scratch.begin() + static_cast<std::ptrdiff_t>(n), scratch.end(),
                      [](const Neighbour& a, const Neighbour& b) {
                          return a.distance != b.distance ? a.distance < b.distance : a.id < b.id;
                      });
    double sum = 0.0;
    std::size_t lower = 0;
    for (std::size_t i = 0; i < n; ++i) {
        sum += scratch[i].distance;
        lower += scratch[i].fitness < self.fitness ? 1 : 0;
    }
    score.novelty = sum / static_cast<double>(n);
    score.competition = static_cast<double>(lower) / static_cast<double>(n);
    return score;
}

bool dominates(const NoveltyScore& a, const NoveltyScore& b) {
    return a.novelty >= b.novelty && a.competition >= b.competition &&
           (a.novelty > b.novelty || a.competition > b.competition);
}
}  // namespace

std::vector<NoveltyScore> novelty_scores(std::span<const BehaviourPoint> members, std::span<const BehaviourPoint> others,
                                         std::span<const DescriptorRange> ranges, int k) {
    // A point of `others` that is also a member counts once, as the member.
    std::vector<std::uint64_t> ids;
    ids.reserve(members.size());
    for (const BehaviourPoint& m : members) ids.push_back(m.id);
    std::sort(ids.begin(), ids.end());
    std::vector<BehaviourPoint> rest;
    rest.reserve(others.size());
    for (const BehaviourPoint& p : others)
        if (!std::binary_search(ids.begin(), ids.end(), p.id)) rest.push_back(p);
    std::vector<NoveltyScore> scores;
    scores.reserve(members.size());
    std::vector<Neighbour> scratch;
    scratch.reserve(members.size() + rest.size());
    for (const BehaviourPoint& self : members) scores.push_back(score_of(self, members, rest, ranges, k, scratch));
    return scores;
}

void pareto_fronts(std::span<NoveltyScore> scores) {
    // In order of (novelty, competition) descending every dominating score
    // comes before the scores it dominates, so one pass finds each longest chain.
    std::vector<std::size_t> order(scores.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (scores[a].novelty != scores[b].novelty) return scores[a].novelty > scores[b].novelty;
        return scores[a].competition > scores[b].competition;
    });
    for (std::size_t i = 0; i < order.size(); ++i) {
        NoveltyScore& s = scores[order[i]];
        s.front = 0;
        for (std::size_t j = 0; j < i; ++j)
            if (const NoveltyScore& q = scores[order[j]]; dominates(q, s)) s.front = std::max(s.front, q.front + 1);
    }
}

bool novelty_ranks_above(const NoveltyScore& a, std::uint64_t a_id, const NoveltyScore& b, std::uint64_t b_id) {
    if (a.front != b.front) return a.front < b.front;
    if (a.novelty != b.novelty) return a.novelty > b.novelty;
    if (a.competition != b.competition) return a.competition > b.competition;
    return a_id > b_id;
}

std::vector<NoveltyScore> ranked_scores(std::span<const BehaviourPoint> members, std::span<const BehaviourPoint> others,
                                        std::span<const DescriptorRange> ranges, int k) {
    std::vector<NoveltyScore> scores = novelty_scores(members, others, ranges, k);
    pareto_fronts(scores);
    return scores;
}

}  // namespace morphogen
