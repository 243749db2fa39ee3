#include "evolution/archives/archive_stats.hpp"

namespace morphogen {

ArchiveStats archive_stats(const Archive& archive, double qd_offset) {
    ArchiveStats stats;
    stats.occupied = archive.occupied();
    stats.cells = archive.cells();
    stats.coverage = static_cast<double>(stats.occupied) / static_cast<double>(stats.cells);
    for (const auto& [cell, elite] : archive.elites()) stats.qd_score += elite.fitness - qd_offset;
    const std::vector<const Individual*> elites = archive.snapshot();
    stats.fitness = summarize(elites);
    return stats;
}

}  // namespace morphogen
