#pragma once
// Summary of a MAP-Elites archive for the history (docs/algorithm.md §9.7).
#include "evolution/archives/archive.hpp"
#include "evolution/ga/population_stats.hpp"

#include <cstdint>

namespace morphogen {

struct ArchiveStats {
    std::size_t occupied = 0;
    std::uint64_t cells = 0;
    double coverage = 0.0;  // occupied / cells
    // Sum over occupied cells of (fitness - offset), in cell-index order.
    double qd_score = 0.0;
    // best/mean/median/worst fitness and mean size over the elites (empty when none).
    PopulationStats fitness;
};

ArchiveStats archive_stats(const Archive& archive, double qd_offset = 0.0);

}  // namespace morphogen
