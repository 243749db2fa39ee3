#include "report/report_plants.hpp"

#include "core/base/errors.hpp"
#include "engine/plant_colour.hpp"
#include "engine/plant_export.hpp"
#include "engine/plant_lods.hpp"
#include "core/io/mesh_io.hpp"
#include "run/exports/plant_exports.hpp"
#include "run/genome_source.hpp"

namespace morphogen {

int report_lod_count(std::size_t faces) {
    int lods = 0;
    while (lods < kReportLods && faces >= kMinLodFaces << lods) ++lods;
    return lods;
}

ReportPlant grow_report_plant(const ExperimentConfig& config, const GenomeGrower& grower,
                              const Individual& individual, std::optional<std::uint64_t> cell, bool colour) {
    DatedGrowth dated = grow_dated(grower, individual.params);  // birth steps: the wind data's flutter
    ReportPlant plant{std::move(dated.state), {}, 0, {}};
    const MeshView mesh = plant.grown.mesh.view();
    PlantExportOptions options;
    options.wind = true;
    options.lods = report_lod_count(static_cast<std::size_t>(mesh.faces.size()));
    options.colour = colour;
    const std::vector<float> colours =
        colour ? growth_colours(plant.grown, dated.birth_steps, grower.params()) : std::vector<float>{};
    try {
        GrownPlant grown{.mesh = mesh, .birth_steps = dated.birth_steps, .steps = plant.grown.steps_done};
        grown.colours = colours;
        const EnginePlant ready =
            make_engine_plant(grown, birth_record(config, individual, config.qd.measure_names(), cell), options);
        plant.glb = plant_glb_bytes(ready, "plant " + std::to_string(individual.id));
        plant.lods = static_cast<int>(ready.levels.size());  // fewer than asked where the chain stopped (plant_lods.hpp)
    } catch (const MeshError& e) {
        plant.glb = encode_mesh(mesh, mesh_format(".glb"));
        plant.why_plain = e.what();
    }
    return plant;
}

std::vector<float> export_colours(const GenomeGrower& grower, const std::filesystem::path& genome_file,
                                  std::size_t vertices) {
    const Genome genome = load_genome_for(grower.layers(), genome_file.string());
    const DatedGrowth dated = grow_dated(grower, genome.params);
    if (static_cast<std::size_t>(dated.state.mesh.num_vertices()) != vertices)
        throw MeshError(genome_file.string() + ": grows " + std::to_string(dated.state.mesh.num_vertices()) +
                        " vertices, its export has " + std::to_string(vertices));
    return growth_colours(dated.state, dated.birth_steps, grower.params());
}

}  // namespace morphogen
