#include "run/growth_problem.hpp"

#include "core/atomic_file.hpp"
#include "core/genome_io.hpp"
#include "core/mesh_io.hpp"
#include "core/network.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace morphogen {

GrowthProblem::GrowthProblem(const ExperimentConfig& config)
    : layers_(config.network.layers()),
      dimension_(parameter_count(layers_)),
      growth_(config.growth),
      seed_(make_seed(config.growth.seed_mesh, config.growth.seed_radius)),
      fitness_(config.fitness),
      descriptors_decide_validity_(config.algorithm == Algorithm::map_elites) {
    if (!config.qd.descriptors.empty())
        descriptors_.emplace(config.qd.measure_names(), canopy_params_of(config.resolved.at("fitness")));
}

std::vector<Block> GrowthProblem::blocks() const { return neuron_blocks(layers_); }

void GrowthProblem::prepare(int workers) {
    if (workspaces_.size() < static_cast<std::size_t>(workers)) workspaces_.resize(static_cast<std::size_t>(workers));
}

Evaluation GrowthProblem::evaluate(std::span<const double> params, int worker) const {
    const Network network(Genome{layers_, std::vector<double>(params.begin(), params.end())});
    const Grower grower(network, growth_);
    const GrowthState state = grower.grow(seed_, workspaces_.at(static_cast<std::size_t>(worker)));
    const FitnessOutcome outcome = fitness_->evaluate(state.mesh.view());
    Evaluation evaluation{outcome.score, outcome.valid, outcome.error, static_cast<double>(state.mesh.num_vertices())};
    if (descriptors_ && evaluation.valid) {
        try {
            evaluation.descriptors = (*descriptors_)(state.mesh.view());
        } catch (const std::invalid_argument& e) {
            if (descriptors_decide_validity_) {
                evaluation.valid = false;
                evaluation.error = std::string("descriptors: ") + e.what();
            }
        }
        // A GA only records them: a birth it could not measure stays as it is,
        // with no descriptors (empty cells in lineage.csv), so declaring
        // descriptors never changes what a GA run computes.
        if (!descriptors_decide_validity_)
            for (double d : evaluation.descriptors)
                if (!std::isfinite(d)) {
                    evaluation.descriptors.clear();
                    break;
                }
    }
    return evaluation;
}

GrowthState GrowthProblem::grow(std::span<const double> params) const {
    const Network network(Genome{layers_, std::vector<double>(params.begin(), params.end())});
    const Grower grower(network, growth_);
    GrowthWorkspace workspace;
    return grower.grow(seed_, workspace);
}

void GrowthProblem::export_genome(std::span<const double> params, const std::filesystem::path& stem) const {
    const GrowthState state = grow(params);
    for (const auto& [extension, format] : {std::pair{".glb", MeshFormat::glb}, std::pair{".obj", MeshFormat::obj}}) {
        const std::string path = stem.string() + extension;
        write_file_atomically(path, encode_mesh(state.mesh.view(), format, {}, path));
    }
    save_genome(Genome{layers_, std::vector<double>(params.begin(), params.end())}, stem.string() + ".genome.json");
}

}  // namespace morphogen
