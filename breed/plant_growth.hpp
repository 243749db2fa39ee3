#pragma once
// One plant of a breeding session grown from its genome: its score under the
// config's fitness, its measures, and the files the page shows (the plain
// GLB and a thumbnail, by the project's renderer). Growth and scoring are pure functions of the
// genome and the config, so a replay grows the same bytes.
#include "fitness/descriptors.hpp"
#include "evolution/individual.hpp"
#include "core/growth/genome_grower.hpp"
#include "report/render.hpp"
#include "run/config/experiment_config.hpp"

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace morphogen {

inline constexpr int kThumbPixels = 128;

struct PlantOutcome {
    std::optional<double> fitness;          // none when the fitness found it invalid
    std::map<std::string, double> measures;  // vertices, faces, height, width, area, tips, limbs, first_fork(_height), each descriptor
    std::vector<double> descriptors;        // the explore search's descriptors; empty when not measurable
    std::string glb;                        // the GLB bytes (with COLOR_0 where colour is on)
    Image thumb;                            // kThumbPixels square (report/render.hpp)
};

class PlantGrowth {
public:
    // `descriptors`: the measures the explore search places plants by.
    // `colour`: the GLB carries COLOR_0 and the thumbnail draws it (colours
    // from growth history, engine/plant_colour.hpp); scores do not change.
    PlantGrowth(const ExperimentConfig& config, const std::vector<std::string>& descriptors, bool colour = true);

    const GenomeGrower& grower() const { return grower_; }
    std::size_t dimension() const { return dimension_; }
    const std::vector<std::string>& descriptor_names() const { return descriptors_.names(); }

    // Grows and scores one genome; thread-safe (a workspace per call).
    // Throws ConfigError for a genome of the wrong size.
    PlantOutcome grow(std::span<const double> params) const;
    // The search's view of a genome (explore.hpp): valid when the fitness
    // is and the descriptors are measurable; no files made. Thread-safe.
    Evaluation evaluate(std::span<const double> params) const;
    // The architecture explore's view (breed/explore.hpp): descriptors
    // limbs, first_fork and tips (as grow()'s measures); invalid when the
    // fitness is, when they cannot be measured, or when the plant is shorter
    // than `min_height` (collapsed). Thread-safe.
    Evaluation evaluate_architecture(std::span<const double> params, double min_height) const;
    // grow() for many genomes on up to `threads` threads; results in order.
    std::vector<PlantOutcome> grow_all(const std::vector<std::vector<double>>& genomes, int threads) const;

private:
    // Grows and scores; `place` fills the descriptors of a valid plant (or makes it invalid).
    Evaluation evaluate_with(std::span<const double> params,
                             const std::function<void(MeshView, Evaluation&)>& place) const;
    GenomeGrower grower_;
    std::size_t dimension_;
    std::shared_ptr<const Fitness> fitness_;
    DescriptorSet descriptors_;
    bool colour_;
};

}  // namespace morphogen
