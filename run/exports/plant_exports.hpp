#pragma once
// Engine-ready GLBs of a run's genomes (engine/plant_export.hpp): what their
// extras say about a birth of the run, and the files written for one, for
// `archive` and the best-of-generation export (run.export_plant).
#include "engine/plant_export.hpp"
#include "evolution/individual.hpp"
#include "core/growth/genome_grower.hpp"
#include "run/config/experiment_config.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace morphogen {

// The record of `individual`, a birth of the run `config` describes: named
// plant_<birth id>, with its fitness, its descriptors under `measure_names`
// (when it has them), its parents and, in a MAP-Elites run, its `cell`.
PlantRecord birth_record(const ExperimentConfig& config, const Individual& individual,
                         const std::vector<std::string>& measure_names, std::optional<std::uint64_t> cell);

// A genome grown with each vertex's birth step (engine/birth_steps.hpp), as
// the wind data of an engine-ready GLB needs it.
struct DatedGrowth {
    GrowthState state;
    std::vector<int> birth_steps;
    GrownPlant plant() const {
        return GrownPlant{.mesh = state.mesh.view(), .birth_steps = birth_steps, .steps = state.steps_done};
    }
};
DatedGrowth grow_dated(const GenomeGrower& grower, std::span<const double> params);

// Grows `params` and writes <stem>.glb (engine-ready, with `options`),
// <stem>.obj (the plain mesh, as export_genome writes it) and
// <stem>.genome.json, each atomically. Throws IoError naming the file.
void export_engine_plant(const GenomeGrower& grower, std::span<const double> params, const PlantRecord& record,
                         const PlantExportOptions& options, const std::filesystem::path& stem);

}  // namespace morphogen
