#pragma once
// The plants the report's viewer shows (the final best, MAP-Elites elites):
// grown from their genomes into engine-ready GLBs (engine/plant_export.hpp)
// with wind data and up to kReportLods levels of detail, so the viewer can
// sway them and show each level (docs/report.md, "3-D viewer").
#include "evolution/individual.hpp"
#include "core/growth/genome_grower.hpp"
#include "run/config/experiment_config.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace morphogen {

// Three levels (LOD0, about 1/2 and 1/4 of its triangles): the levels the
// game-ready bounds cover (LOD1 within 1 %, LOD2 within 2 % of the
// diagonal), the pack's `--lods 3`, and 1.75 times LOD0's triangles in all.
inline constexpr int kReportLods = 3;

// The most levels (at most kReportLods) a plant of `faces` triangles can
// have: its last level keeps at least kMinLodFaces (engine/plant_lods.hpp);
// 0 when even one level cannot be made.
int report_lod_count(std::size_t faces);

struct ReportPlant {
    GrowthState grown;            // the plant as growth left it (for its measures and pictures)
    std::string glb;              // its engine-ready GLB, or the plain one when that cannot be made
    int lods = 0;                 // levels in glb (0: a single mesh)
    std::optional<std::string> why_plain;  // why glb is the plain mesh, when it is
};

// Grows `individual` (a birth of the run `config` describes; `cell` its
// MAP-Elites cell) and writes its GLB with `--wind` and report_lod_count
// levels, named and recorded as `archive` names it. A plant that cannot be
// placed (MeshError) falls back to the plain GLB with `why_plain` set.
// `colour`: COLOR_0 from growth history (engine/plant_colour.hpp), which
// the viewer draws. Throws what growth and encoding throw.
ReportPlant grow_report_plant(const ExperimentConfig& config, const GenomeGrower& grower,
                              const Individual& individual, std::optional<std::uint64_t> cell, bool colour = true);

// The colours from growth history (RGBA, 4 per vertex, as render_mesh takes
// them) of a run's exported plant of `vertices` vertices: its genome file
// (the <stem>.genome.json beside each export) grown again with `grower`.
// Throws what loading and growth throw, and MeshError when the grown plant
// does not have `vertices` vertices (a genome that is not the export's).
std::vector<float> export_colours(const GenomeGrower& grower, const std::filesystem::path& genome_file,
                                  std::size_t vertices);

}  // namespace morphogen
