#include "evolution/ga/population_stats.hpp"

#include <algorithm>
#include <vector>

namespace morphogen {

namespace {
template <class Range, class Get>
PopulationStats summarize_range(const Range& members, Get get) {
    PopulationStats stats;
    std::vector<double> scores;
    double size_sum = 0.0;
    for (const auto& entry : members) {
        const Individual& member = get(entry);
        if (!member.valid()) continue;
        scores.push_back(member.fitness);
        size_sum += member.size;
    }
    stats.valid = scores.size();
    if (scores.empty()) return stats;
    double sum = 0.0;
    for (double s : scores) sum += s;
    const auto n = static_cast<double>(scores.size());
    stats.mean = sum / n;
    stats.mean_size = size_sum / n;
    std::sort(scores.begin(), scores.end());
    stats.best = scores.back();
    stats.worst = scores.front();
    const std::size_t mid = scores.size() / 2;
    stats.median = scores.size() % 2 == 1 ? scores[mid] : 0.5 * (scores[mid - 1] + scores[mid]);
    return stats;
}
}  // namespace

PopulationStats summarize(std::span<const Individual> population) {
    return summarize_range(population, [](const Individual& member) -> const Individual& { return member; });
}

PopulationStats summarize(std::span<const Individual* const> members) {
    return summarize_range(members, [](const Individual* member) -> const Individual& { return *member; });
}

}  // namespace morphogen
