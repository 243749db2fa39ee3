#include "growth/genome_grower.hpp"

namespace morphogen {

GenomeGrower::GenomeGrower(const NetworkParams& network, const GrowthParams& growth)
    : layers_(network.layers()), growth_(growth), seed_(make_seed(growth)) {}

GrowthState GenomeGrower::grow(const Network& network, GrowthWorkspace& workspace, const StepObserver& after_step,
                               GrowthObserver* phases) const {
    return Grower(network, growth_).grow(seed_, workspace, after_step, phases);
}

GrowthState GenomeGrower::grow(std::span<const double> genome, GrowthWorkspace& workspace) const {
    return grow(Network(Genome{layers_, std::vector<double>(genome.begin(), genome.end())}), workspace);
}

GrowthState GenomeGrower::grow(std::span<const double> genome) const {
    GrowthWorkspace workspace;
    return grow(genome, workspace);
}

}  // namespace morphogen
