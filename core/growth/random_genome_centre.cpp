#include "core/growth/random_genome_centre.hpp"

#include <cstddef>

namespace morphogen {

std::vector<double> random_genome_centre(const std::vector<int>& layers, GrowthMode mode) {
    if (mode != GrowthMode::branching || layers.size() < 2) return {};
    std::size_t count = 0;
    for (std::size_t l = 1; l < layers.size(); ++l)
        count += static_cast<std::size_t>(layers[l]) * static_cast<std::size_t>(layers[l - 1] + 1);
    const auto outputs = static_cast<std::size_t>(layers.back());
    const auto fan_in = static_cast<std::size_t>(layers[layers.size() - 2]);
    if (outputs < 4) return {};
    std::vector<double> centre(count, 0.0);
    // The output layer is the last block of the genome; neuron j's threshold
    // follows its fan_in weights (§6.1).
    const std::size_t output_layer = count - outputs * (fan_in + 1);
    for (const std::size_t channel : {std::size_t{0}, std::size_t{3}})
        centre[output_layer + channel * (fan_in + 1) + fan_in] = -branching_shoot_bias;
    return centre;
}

}  // namespace morphogen
