#include "run/genome_source.hpp"

#include "core/base/errors.hpp"
#include "evolution/rng.hpp"
#include "core/growth/genome_io.hpp"
#include "core/growth/random_genome_centre.hpp"

namespace morphogen {

std::string show_layers(const std::vector<int>& layers) {
    std::string text = "[";
    for (std::size_t i = 0; i < layers.size(); ++i) text += (i ? ", " : "") + std::to_string(layers[i]);
    return text + "]";
}

Genome random_genome(const std::vector<int>& layers, GrowthMode mode, double init_range, std::uint64_t seed) {
    RandomStream stream(seed, 0);
    const std::vector<double> centre = random_genome_centre(layers, mode);
    return Genome{layers, random_parameters(parameter_count(layers), init_range, stream, centre)};
}

Genome load_genome_for(const std::vector<int>& layers, const std::string& path) {
    Genome genome = load_genome(path);
    if (genome.layers != layers)
        throw ConfigError(path + ": the genome's layers " + show_layers(genome.layers) +
                          " do not match the config's network " + show_layers(layers) +
                          " (set network.outputs and network.hidden to match)");
    return genome;
}

}  // namespace morphogen
