#pragma once
// The cellular network of docs/algorithm.md §4: one feed-forward net, identical at
// every vertex. Layer sizes [3N, hidden..., N]; each neuron computes
//   sigmoid(-threshold + sum_k (in_k - 0.5) * weight_k).
// Genome layout (docs/algorithm.md §6.1): for each layer l = 1..L, for each neuron j, its weights
// weight_j0..weight_j(n-1) then its threshold.
#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/growth/network/network_kernel.hpp"

namespace morphogen {

struct Genome {
    std::vector<int> layers;     // neuron counts, input layer first
    std::vector<double> params;  // parameter_count(layers) numbers
};

// Number of parameters for these layer sizes.
std::size_t parameter_count(std::span<const int> layers);
// [offset, length) of each neuron's weights+threshold in the genome, all layers
// in genome order: the unit that crossover exchanges.
std::vector<std::pair<std::size_t, std::size_t>> neuron_blocks(std::span<const int> layers);
// Layer sizes from the config: [3*outputs, hidden..., outputs].
std::vector<int> layer_sizes(int outputs, std::span<const int> hidden);

// Scratch space reused across evaluations (one per thread).
struct NetworkWorkspace {
    std::vector<double> scratch;
    std::vector<kernel::Layer> layers;  // this network's layer table, rebuilt in place
};

class Network {
public:
    // Throws ConfigError if the genome's size does not match its layers, a
    // layer is empty, a parameter is not finite, or a neuron's parameters
    // are so large (near 1e308) that folding them overflows.
    explicit Network(const Genome& genome);

    int inputs() const { return layers_.front(); }
    int outputs() const { return layers_.back(); }
    const std::vector<int>& layers() const { return layers_; }

    // Batched evaluation of V vertices at once: `input` holds inputs() numbers
    // per vertex, vertex after vertex (V = input.size() / inputs()); `output`
    // must hold outputs() * V and receives each vertex's outputs the same way.
    // Agrees with evaluate_reference() to ~1e-15 relative.
    void evaluate(std::span<const double> input, std::span<double> output, NetworkWorkspace& workspace) const;
    // The same for output.size() / outputs() vertices whose inputs `source`
    // computes a block at a time (see kernel::InputSource).
    void evaluate(const kernel::InputSource& source, std::span<double> output, NetworkWorkspace& workspace) const;

    // The paper's pseudocode for one vertex, literally; the reference for tests.
    std::vector<double> evaluate_reference(std::span<const double> input) const;

private:
    // Points workspace.layers at this network's weights.
    const std::vector<kernel::Layer>& layer_table(NetworkWorkspace& workspace) const;

    std::vector<int> layers_;
    std::vector<double> params_;
    // Per layer: weights (out x in, row-major: row j = neuron j) and the
    // folded bias b_j = -threshold_j - 0.5 * sum_k weight_jk, so a = W x + b.
    std::vector<std::vector<double>> weights_;
    std::vector<std::vector<double>> biases_;
};

}  // namespace morphogen
