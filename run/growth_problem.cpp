#include "run/growth_problem.hpp"

#include "core/base/atomic_file.hpp"
#include "core/growth/genome_io.hpp"
#include "core/growth/network/network.hpp"
#include "core/growth/random_genome_centre.hpp"
#include "core/io/mesh_io.hpp"

#include <cstring>
#include <iterator>
#include <limits>
#include <string_view>
#include <stdexcept>
#include <string>
#include <utility>

namespace morphogen {

GrowthProblem::GrowthProblem(const ExperimentConfig& config)
    : grower_(config.network, config.growth),
      dimension_(parameter_count(grower_.layers())),
      fitness_(config.fitness),
      descriptors_decide_validity_(config.algorithm != Algorithm::steady_state),
      keeps_exports_(config.run.export_every > 0 && !config.run.export_glb) {
    if (!config.qd.descriptors.empty())
        descriptors_.emplace(config.qd.measure_names(), config.fitness->canopy_params());
}

std::vector<Block> GrowthProblem::blocks() const { return neuron_blocks(grower_.layers()); }

std::vector<double> GrowthProblem::random_centre() const {
    return random_genome_centre(grower_.layers(), grower_.params().mode);
}

void GrowthProblem::prepare(int workers) {
    if (workspaces_.size() < static_cast<std::size_t>(workers)) workspaces_.resize(static_cast<std::size_t>(workers));
}

Evaluation GrowthProblem::evaluate(std::span<const double> params, int worker) const {
    return evaluate_mesh(params, worker, std::numeric_limits<double>::infinity());
}

Evaluation GrowthProblem::evaluate_keeping(std::span<const double> params, int worker, double keep_from) const {
    return evaluate_mesh(params, worker, keep_from);
}

namespace {
constexpr const char* export_formats[] = {".glb", ".obj"};

// The export files of a mesh in one string: each file's byte count (8 bytes,
// native order) then its bytes, in export_formats order.
std::string pack_exports(MeshView mesh) {
    std::string out;
    for (const char* extension : export_formats) {
        const std::string bytes = encode_mesh(mesh, mesh_format(extension), {}, std::string("kept mesh") + extension);
        const std::uint64_t n = bytes.size();
        out.append(reinterpret_cast<const char*>(&n), sizeof n);
        out += bytes;
    }
    return out;
}

std::vector<std::string_view> unpack_exports(const std::string& kept) {
    std::vector<std::string_view> files;
    std::size_t at = 0;
    for (std::size_t i = 0; i < std::size(export_formats); ++i) {
        std::uint64_t n = 0;
        if (kept.size() - at < sizeof n) throw std::invalid_argument("kept export files are truncated");
        std::memcpy(&n, kept.data() + at, sizeof n);
        at += sizeof n;
        if (kept.size() - at < n) throw std::invalid_argument("kept export files are truncated");
        files.emplace_back(kept.data() + at, n);
        at += n;
    }
    if (at != kept.size()) throw std::invalid_argument("kept export files have trailing bytes");
    return files;
}
}  // namespace

Evaluation GrowthProblem::evaluate_mesh(std::span<const double> params, int worker, double keep_from) const {
    const GrowthState state = grower_.grow(params, workspaces_.at(static_cast<std::size_t>(worker)));
    const FitnessOutcome outcome = fitness_->evaluate(state.mesh.view());
    Evaluation evaluation{outcome.score, outcome.valid, outcome.error, static_cast<double>(state.mesh.num_vertices())};
    if (descriptors_ && evaluation.valid) {
        try {
            evaluation.descriptors = (*descriptors_)(state.mesh.view());
        } catch (const std::invalid_argument& e) {
            // A GA only records descriptors: a birth it could not measure
            // keeps none (empty cells in lineage.csv), so declaring
            // descriptors never changes what a GA run computes.
            if (descriptors_decide_validity_) {
                evaluation.valid = false;
                evaluation.error = std::string("descriptors: ") + e.what();
            }
        }
    }
    // Only a run that exports keeps files: a finished birth waits for its
    // turn to be inserted with them, so they cost memory per birth in flight.
    if (keeps_exports_ && evaluation.valid && evaluation.score >= keep_from)
        evaluation.kept = pack_exports(state.mesh.view());
    return evaluation;
}

void GrowthProblem::export_genome(std::span<const double> params, const std::filesystem::path& stem) const {
    const GrowthState state = grower_.grow(params);
    export_kept(pack_exports(state.mesh.view()), params, stem);
}

void GrowthProblem::export_kept(const std::string& kept, std::span<const double> params,
                                const std::filesystem::path& stem) const {
    const std::vector<std::string_view> files = unpack_exports(kept);
    for (std::size_t i = 0; i < files.size(); ++i)
        write_file_atomically(stem.string() + export_formats[i], files[i]);
    save_genome(Genome{grower_.layers(), std::vector<double>(params.begin(), params.end())},
                stem.string() + ".genome.json");
}

}  // namespace morphogen
