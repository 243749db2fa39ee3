#include "run/exports/plant_exports.hpp"

#include "engine/leaf_cards.hpp"
#include "engine/plant_colour.hpp"
#include "core/growth/genome_io.hpp"
#include "core/io/mesh_io.hpp"

namespace morphogen {

PlantRecord birth_record(const ExperimentConfig& config, const Individual& individual,
                         const std::vector<std::string>& measure_names, std::optional<std::uint64_t> cell) {
    PlantRecord record;
    record.id = std::to_string(individual.id);
    record.genome_hash = genome_hash(individual.params);
    if (individual.valid()) record.fitness = individual.fitness;
    if (individual.descriptors.size() == measure_names.size())
        for (std::size_t i = 0; i < measure_names.size(); ++i)
            record.measures.emplace_back(measure_names[i], individual.descriptors[i]);
    record.run = config.run.name;
    record.birth = individual.id;
    if (individual.parent1) record.parents.push_back(*individual.parent1);
    if (individual.parent2) record.parents.push_back(*individual.parent2);
    record.cell = cell;
    return record;
}

DatedGrowth grow_dated(const GenomeGrower& grower, std::span<const double> params) {
    GrowthWorkspace workspace;
    const Network network(Genome{grower.layers(), std::vector<double>(params.begin(), params.end())});
    std::vector<int> births;
    GrowthState state = grower.grow_dated(network, workspace, births);
    return DatedGrowth{.state = std::move(state), .birth_steps = std::move(births)};
}

void export_engine_plant(const GenomeGrower& grower, std::span<const double> params, const PlantRecord& record,
                         const PlantExportOptions& options, const std::filesystem::path& stem) {
    const DatedGrowth grown = grow_dated(grower, params);
    GrownPlant plant = grown.plant();
    const std::vector<double> light =
        options.leaves ? leaf_light(grown.state, grower.params()) : std::vector<double>{};
    const std::vector<float> colours =  // the leaves' light is the final exposure: computed once
        options.colour ? growth_colours(grown.state, grown.birth_steps, grower.params(), light) : std::vector<float>{};
    plant.colours = colours;
    plant.light = light;
    write_plant_glb(stem.string() + ".glb", plant, record, options);
    write_mesh(grown.state.mesh.view(), stem.string() + ".obj");
    save_genome(Genome{grower.layers(), std::vector<double>(params.begin(), params.end())},
                stem.string() + ".genome.json");
}

}  // namespace morphogen
