// A run's species pack (see run_pack.hpp).
#include "run/exports/run_pack.hpp"

#include "evolution/operators.hpp"
#include "run/searches/elites_search.hpp"
#include "run/config/map_elites_config.hpp"
#include "engine/leaf_cards.hpp"
#include "run/exports/plant_exports.hpp"
#include "run/loop/stop_signals.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>

namespace morphogen {

namespace {

// A population's (GA, NSLC) valid members, ranked, one per genome.
std::vector<RunSpecies> population_species(const SearchState& search) {
    std::vector<const Individual*> members;
    for (const Individual* member : search.view().members)
        if (member->valid()) members.push_back(member);
    std::stable_sort(members.begin(), members.end(),
                     [](const Individual* a, const Individual* b) { return ranks_above(*a, *b); });
    std::vector<RunSpecies> species;
    std::set<std::string> genomes;
    for (const Individual* member : members)
        if (genomes.insert(genome_hash(member->params)).second) species.push_back({member, std::nullopt});
    return species;
}

}  // namespace

std::vector<RunSpecies> run_species(const SearchState& search, std::uint64_t top) {
    std::vector<RunSpecies> species;
    if (const MapElitesState* elites = elites_state(search)) {
        for (const auto& [cell, elite] : elites->archive.elites()) species.push_back({&elite, cell});
        if (top > 0 && top < species.size()) {
            std::stable_sort(species.begin(), species.end(), [](const RunSpecies& a, const RunSpecies& b) {
                return a.individual->fitness > b.individual->fitness;
            });
            species.resize(top);
            std::sort(species.begin(), species.end(),
                      [](const RunSpecies& a, const RunSpecies& b) { return *a.cell < *b.cell; });
        }
        return species;
    }
    species = population_species(search);
    if (top > 0 && top < species.size()) species.resize(top);
    return species;
}

std::optional<std::size_t> write_run_pack(const ExperimentConfig& config, const SearchState& search, const GenomeGrower& grower,
                           const PlantExportOptions& options, std::uint64_t top, const std::filesystem::path& dir) {
    const std::vector<RunSpecies> species = run_species(search, top);
    if (species.empty()) throw std::invalid_argument("the run has no valid genome to pack yet");
    const std::vector<std::string> measures = config.qd.measure_names();
    SpeciesPack pack(dir, PackSource{.run = config.run.name, .algorithm = algorithm_name(config.algorithm),
                                     .measures = measures},
                     options);
    try {
        for (const RunSpecies& one : species) {
            if (StopSignals::requested()) break;
            const DatedGrowth grown = grow_dated(grower, one.individual->params);
            GrownPlant plant = grown.plant();
            const std::vector<double> light =
                options.leaves ? leaf_light(grown.state, grower.params()) : std::vector<double>{};
            plant.light = light;
            pack.add(plant, birth_record(config, *one.individual, measures, one.cell));
        }
        if (StopSignals::requested()) {
            pack.abandon();
            return std::nullopt;
        }
        pack.finish();
    } catch (...) {  // a full disk, a plant refused: no half pack left behind
        pack.abandon();
        throw;
    }
    return pack.size();
}

}  // namespace morphogen
