#include "run/searches/elites_search.hpp"
#include "run/searches/ga_search.hpp"
#include "run/searches/run_search.hpp"

#include <array>
#include <stdexcept>

namespace morphogen {

std::span<const SearchKind> search_kinds() {
    static const std::array kinds{ga_search_kind(), elites_search_kind()};
    return kinds;
}

const SearchKind& search_kind(Algorithm algorithm) {
    for (const SearchKind& kind : search_kinds())
        if (kind.algorithm == algorithm) return kind;
    throw std::logic_error(std::string("no search registered for evolution.algorithm ") + algorithm_name(algorithm));
}

void fill_statistics(HistoryRow& row, const PopulationStats& stats) {
    row.best = stats.best;
    row.mean = stats.mean;
    row.median = stats.median;
    row.worst = stats.worst;
    row.mean_vertices = stats.mean_size;
}

}  // namespace morphogen
