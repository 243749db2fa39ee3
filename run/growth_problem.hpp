#pragma once
// The experiment as a GA Problem: a genome (parameter vector) grows into a
// mesh (GenomeGrower) that the config's Fitness scores. This is the one
// place where evolution meets meshes.
#include "evolution/problem.hpp"
#include "fitness/descriptors.hpp"
#include "core/growth/genome_grower.hpp"
#include "run/config/experiment_config.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace morphogen {

class GrowthProblem final : public Problem {
public:
    // Builds the seed mesh once (MeshError/IoError if a seed file is bad).
    explicit GrowthProblem(const ExperimentConfig& config);

    std::size_t dimension() const override { return dimension_; }
    // One block per neuron (weights and threshold), as crossover exchanges them.
    std::vector<Block> blocks() const override;
    // Branching mode: shoots of random genomes start growing (docs/algorithm.md §6.3).
    std::vector<double> random_centre() const override;
    // The genomes generation 0 starts from (seed_genomes.hpp); none by default.
    std::vector<std::vector<double>> seed_genomes() const override { return seeds_; }
    void set_seed_genomes(std::vector<std::vector<double>> seeds) { seeds_ = std::move(seeds); }
    void prepare(int workers) override;
    // Score = fitness of the grown mesh; size = its vertex count; when the
    // config has descriptors, descriptors = its measures of that same mesh.
    // Valid only with a finite score and finite descriptors: Fitness and
    // DescriptorSet check them where they are made (so nothing here does).
    // In a MAP-Elites run a valid score with a measure that throws or is
    // non-finite is invalid, with the reason; a GA run only records the
    // measures, so there such a measure leaves descriptors empty.
    Evaluation evaluate(std::span<const double> params, int worker) const override;
    // Also keeps, when valid with a score >= keep_from, the grown mesh's
    // export files (.glb and .obj bytes), so exporting it grows nothing.
    Evaluation evaluate_keeping(std::span<const double> params, int worker, double keep_from) const override;

    // What grows its genomes (the config's network, growth and seed).
    const GenomeGrower& grower() const { return grower_; }
    // Writes <stem>.glb, <stem>.obj and <stem>.genome.json for a genome, each
    // atomically (atomic_file.hpp). Throws IoError naming the file and the reason.
    void export_genome(std::span<const double> params, const std::filesystem::path& stem) const;
    // The same files from what evaluate_keeping kept for this genome: the
    // same bytes as export_genome, without growing it again.
    void export_kept(const std::string& kept, std::span<const double> params, const std::filesystem::path& stem) const;

private:
    Evaluation evaluate_mesh(std::span<const double> params, int worker, double keep_from) const;

    GenomeGrower grower_;
    std::size_t dimension_;
    std::shared_ptr<const Fitness> fitness_;
    std::optional<DescriptorSet> descriptors_;  // when the config has descriptors
    bool descriptors_decide_validity_;          // MAP-Elites, NSLC: a failed measure makes the birth invalid
    bool keeps_exports_;  // run.export_every > 0 with plain GLBs: evaluate_keeping keeps files
    // One per worker; evaluate() with worker w touches only workspaces_[w].
    mutable std::vector<GrowthWorkspace> workspaces_;
    std::vector<std::vector<double>> seeds_;
};

}  // namespace morphogen
