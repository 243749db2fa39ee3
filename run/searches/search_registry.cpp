#include "run/searches/elites_search.hpp"
#include "run/searches/ga_search.hpp"
#include "run/searches/nslc_search.hpp"
#include "run/searches/run_search.hpp"

#include <array>
#include <stdexcept>

namespace morphogen {

std::span<const SearchKind> search_kinds() {
    static const std::array kinds{ga_search_kind(), elites_search_kind(), nslc_search_kind()};
    return kinds;
}

const SearchKind& search_kind(Algorithm algorithm) {
    for (const SearchKind& kind : search_kinds())
        if (kind.algorithm == algorithm) return kind;
    throw std::logic_error(std::string("no search registered for evolution.algorithm ") + algorithm_name(algorithm));
}

void each_population_genome(nlohmann::json& stored, const std::string& key,
                            const std::function<void(nlohmann::json&, const std::string&)>& genome) {
    if (!stored.is_object()) return;
    if (stored.contains("population") && stored["population"].is_array())
        for (std::size_t i = 0; i < stored["population"].size(); ++i)
            genome(stored["population"][i], key + ".population[" + std::to_string(i) + "]");
    if (stored.contains("best")) genome(stored["best"], key + ".best");
}

void fill_statistics(HistoryRow& row, const PopulationStats& stats) {
    row.best = stats.best;
    row.mean = stats.mean;
    row.median = stats.median;
    row.worst = stats.worst;
    row.mean_vertices = stats.mean_size;
}

}  // namespace morphogen
