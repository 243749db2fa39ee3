#include "breed/plant_growth.hpp"

#include "core/base/parallel_for.hpp"
#include "fitness/architecture/architecture.hpp"
#include "engine/plant_colour.hpp"
#include "fitness/measures.hpp"
#include "run/exports/plant_exports.hpp"
#include "fitness/mesh_stats.hpp"
#include "core/growth/network/network.hpp"
#include "core/io/mesh_io.hpp"

#include <algorithm>
#include <exception>
#include <functional>
#include <stdexcept>

namespace morphogen {

PlantGrowth::PlantGrowth(const ExperimentConfig& config, const std::vector<std::string>& descriptors, bool colour)
    : grower_(config.network, config.growth),
      dimension_(parameter_count(grower_.layers())),
      fitness_(config.fitness),
      descriptors_(descriptors, config.fitness->canopy_params()),
      colour_(colour) {}

namespace {

// tips, limbs, first_fork_height (as `score --json` reports them) and
// first_fork: that height as a share of the plant's.
void add_architecture_measures(MeshView mesh, std::map<std::string, double>& measures) {
    ArchitectureParams params;
    params.with_solidity = false;  // not shown; the convex hull is the costly part
    Architecture a;
    try {
        a = measure_architecture(mesh, params);
    } catch (const std::invalid_argument&) {
        return;  // nothing to measure (no vertices)
    }
    measures["tips"] = a.tips;
    measures["limbs"] = static_cast<double>(a.limbs.size());
    measures["first_fork_height"] = a.first_fork_height;
    // As a share of the height from the lowest vertex, as the fork is measured.
    double zmin = mesh.positions.front().z(), zmax = zmin;
    for (const Vec3& p : mesh.positions) {
        zmin = std::min(zmin, p.z());
        zmax = std::max(zmax, p.z());
    }
    if (zmax > zmin) measures["first_fork"] = a.first_fork_height / (zmax - zmin);
}

}  // namespace

PlantOutcome PlantGrowth::grow(std::span<const double> params) const {
    const DatedGrowth dated = grow_dated(grower_, params);  // the same state as grower_.grow
    const GrowthState& state = dated.state;
    const MeshView mesh = state.mesh.view();
    const std::vector<float> colours =
        colour_ ? growth_colours(state, dated.birth_steps, grower_.params()) : std::vector<float>{};
    PlantOutcome out;
    const FitnessOutcome scored = fitness_->evaluate(mesh);
    if (scored.valid) out.fitness = scored.score;
    out.measures["vertices"] = state.mesh.num_vertices();
    out.measures["faces"] = state.mesh.num_faces();
    const MeshStats stats = mesh_stats(mesh);
    out.measures["height"] = stats.height;
    out.measures["width"] = stats.width;
    out.measures["area"] = mesh_area(mesh);
    add_architecture_measures(mesh, out.measures);
    try {
        out.descriptors = descriptors_(mesh);
        for (std::size_t i = 0; i < out.descriptors.size(); ++i)
            out.measures[descriptors_.names()[i]] = out.descriptors[i];
    } catch (const std::invalid_argument&) {
        out.descriptors.clear();  // a degenerate plant: the search cannot place it
    }
    out.glb = encode_mesh(mesh, mesh_format(".glb"), {.colours = colours}, "plant.glb");
    RenderOptions thumb;
    thumb.size = kThumbPixels;
    out.thumb = render_mesh(mesh, thumb, colours);
    return out;
}

Evaluation PlantGrowth::evaluate_with(std::span<const double> params,
                                      const std::function<void(MeshView, Evaluation&)>& place) const {
    GrowthWorkspace workspace;
    const GrowthState state = grower_.grow(params, workspace);
    const MeshView mesh = state.mesh.view();
    const FitnessOutcome scored = fitness_->evaluate(mesh);
    Evaluation out{scored.score, scored.valid, scored.error, static_cast<double>(state.mesh.num_vertices())};
    if (out.valid) place(mesh, out);
    return out;
}

Evaluation PlantGrowth::evaluate(std::span<const double> params) const {
    return evaluate_with(params, [this](MeshView mesh, Evaluation& out) {
        try {
            out.descriptors = descriptors_(mesh);
        } catch (const std::invalid_argument& e) {
            out.valid = false;
            out.error = std::string("descriptors: ") + e.what();
        }
    });
}

Evaluation PlantGrowth::evaluate_architecture(std::span<const double> params, double min_height) const {
    return evaluate_with(params, [min_height](MeshView mesh, Evaluation& out) {
        const double height = mesh_stats(mesh).height;
        if (height < min_height) {
            out.valid = false;
            out.error = "collapsed: height " + std::to_string(height) + " below " + std::to_string(min_height);
            return;
        }
        std::map<std::string, double> measures;
        add_architecture_measures(mesh, measures);
        if (!measures.contains("first_fork")) {
            out.valid = false;
            out.error = "no architecture measures (a plant of no height)";
            return;
        }
        out.descriptors = {measures.at("limbs"), measures.at("first_fork"), measures.at("tips")};
    });
}

std::vector<PlantOutcome> PlantGrowth::grow_all(const std::vector<std::vector<double>>& genomes, int threads) const {
    std::vector<PlantOutcome> out(genomes.size());
    parallel_for(genomes.size(), threads, [&](std::size_t i, int) { out[i] = grow(genomes[i]); });
    return out;
}

}  // namespace morphogen
