#pragma once
// A run's species pack (`archive RUN --pack DIR`; engine/species_pack.hpp):
// which genomes of the run are its species, grown and written as a pack.
#include "engine/species_pack.hpp"
#include "evolution/individual.hpp"
#include "core/growth/genome_grower.hpp"
#include "run/config/experiment_config.hpp"
#include "run/searches/search_state.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace morphogen {

struct RunSpecies {
    const Individual* individual;       // into the search state
    std::optional<std::uint64_t> cell;  // its MAP-Elites cell; none in a GA run
};

// The species of the run whose state is `search`:
// - MAP-Elites: the archive's elites, in cell order;
// - GA: the population's valid members, one per distinct genome (the one
//   ranking highest, ranks_above), fittest first.
// With top > 0, only the `top` fittest (ties: the lower cell, or the GA's
// order), kept in that order.
std::vector<RunSpecies> run_species(const SearchState& search, std::uint64_t top);

// Grows every species of run_species(search, top) with `grower` (each
// vertex dated for the wind data) and writes the pack to `dir`; returns how
// many species it holds. Between species it looks at StopSignals: on a stop
// request it removes what it wrote (SpeciesPack::abandon) and returns
// nothing; so it does before it throws. Throws as SpeciesPack, and std::invalid_argument when the run has
// no species yet.
std::optional<std::size_t> write_run_pack(const ExperimentConfig& config, const SearchState& search, const GenomeGrower& grower,
                           const PlantExportOptions& options, std::uint64_t top, const std::filesystem::path& dir);

}  // namespace morphogen
