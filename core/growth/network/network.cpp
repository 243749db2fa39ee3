#include "core/growth/network/network.hpp"

#include "core/base/errors.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>

namespace morphogen {

std::size_t parameter_count(std::span<const int> layers) {
    std::size_t count = 0;
    for (std::size_t l = 1; l < layers.size(); ++l)
        count += static_cast<std::size_t>(layers[l]) * (static_cast<std::size_t>(layers[l - 1]) + 1);
    return count;
}

std::vector<std::pair<std::size_t, std::size_t>> neuron_blocks(std::span<const int> layers) {
    std::vector<std::pair<std::size_t, std::size_t>> blocks;
    std::size_t offset = 0;
    for (std::size_t l = 1; l < layers.size(); ++l) {
        const std::size_t length = static_cast<std::size_t>(layers[l - 1]) + 1;
        for (int j = 0; j < layers[l]; ++j) {
            blocks.emplace_back(offset, length);
            offset += length;
        }
    }
    return blocks;
}

std::vector<int> layer_sizes(int outputs, std::span<const int> hidden) {
    std::vector<int> layers{3 * outputs};
    layers.insert(layers.end(), hidden.begin(), hidden.end());
    layers.push_back(outputs);
    return layers;
}

Network::Network(const Genome& genome) : layers_(genome.layers), params_(genome.params) {
    if (layers_.size() < 2) throw ConfigError("network: needs at least an input and an output layer");
    for (std::size_t l = 0; l < layers_.size(); ++l)
        if (layers_[l] < 1)
            throw ConfigError("network: layer " + std::to_string(l) + " has " + std::to_string(layers_[l]) +
                              " neurons");
    if (params_.size() != parameter_count(layers_))
        throw ConfigError("network: layers need " + std::to_string(parameter_count(layers_)) +
                          " parameters, the genome has " + std::to_string(params_.size()));
    for (std::size_t i = 0; i < params_.size(); ++i)
        if (!std::isfinite(params_[i]))
            throw ConfigError("network: parameter " + std::to_string(i) + " is not finite");

    std::size_t offset = 0;
    for (std::size_t l = 1; l < layers_.size(); ++l) {
        const int in = layers_[l - 1], out = layers_[l];
        std::vector<double> weights(static_cast<std::size_t>(out) * in);
        std::vector<double> bias(out);
        for (int j = 0; j < out; ++j) {
            double weight_sum = 0.0;
            for (int k = 0; k < in; ++k) {
                weights[static_cast<std::size_t>(j) * in + k] = kernel::weight_scale * params_[offset + k];
                weight_sum += params_[offset + k];
            }
            const double threshold = params_[offset + in];
            // a = -t + sum (x - 0.5) w = sum x w + (-t - 0.5 sum w): the 0.5 is folded once.
            // Both scaled for the kernel (see kernel::weight_scale).
            bias[j] = kernel::weight_scale * (-threshold - 0.5 * weight_sum);
            // Finite parameters near the largest double can still overflow here.
            const auto row = std::span(weights).subspan(static_cast<std::size_t>(j) * in, in);
            if (!std::isfinite(bias[j]) || !std::ranges::all_of(row, [](double w) { return std::isfinite(w); }))
                throw ConfigError("network: neuron " + std::to_string(j) + " of layer " + std::to_string(l) +
                                  " has parameters too large to evaluate (params[" + std::to_string(offset) + ".." +
                                  std::to_string(offset + in) + "]: their sum overflows)");
            offset += static_cast<std::size_t>(in) + 1;
        }
        weights_.push_back(std::move(weights));
        biases_.push_back(std::move(bias));
    }
}

const std::vector<kernel::Layer>& Network::layer_table(NetworkWorkspace& workspace) const {
    std::vector<kernel::Layer>& layers = workspace.layers;  // keeps its capacity: no allocation per step
    layers.clear();
    for (std::size_t l = 0; l < weights_.size(); ++l)
        layers.push_back({layers_[l], layers_[l + 1], weights_[l].data(), biases_[l].data()});
    return layers;
}

void Network::evaluate(std::span<const double> input, std::span<double> output, NetworkWorkspace& workspace) const {
    const auto count = static_cast<std::ptrdiff_t>(input.size() / inputs());
    if (input.size() != static_cast<std::size_t>(count * inputs()) || output.size() != static_cast<std::size_t>(count * outputs()))
        throw std::invalid_argument("Network::evaluate: buffer sizes do not match the layers");
    kernel::evaluate(layer_table(workspace), input.data(), output.data(), count, workspace.scratch);
}

void Network::evaluate(const kernel::InputSource& source, std::span<double> output, NetworkWorkspace& workspace) const {
    const auto count = static_cast<std::ptrdiff_t>(output.size() / outputs());
    if (output.size() != static_cast<std::size_t>(count * outputs()) || source.fill == nullptr)
        throw std::invalid_argument("Network::evaluate: output size does not match the layers, or no input source");
    kernel::evaluate(layer_table(workspace), source, output.data(), count, workspace.scratch);
}

std::vector<double> Network::evaluate_reference(std::span<const double> input) const {
    std::vector<double> value(input.begin(), input.end());
    std::size_t offset = 0;
    for (std::size_t l = 1; l < layers_.size(); ++l) {
        const int in = layers_[l - 1], out = layers_[l];
        std::vector<double> next(out);
        for (int j = 0; j < out; ++j) {
            const double* weights = &params_[offset];
            double a = -weights[in];  // -threshold
            for (int k = 0; k < in; ++k) a += (value[k] - 0.5) * weights[k];
            next[j] = 1.0 / (1.0 + std::exp(-a));
            offset += static_cast<std::size_t>(in) + 1;
        }
        value = std::move(next);
    }
    return value;
}

}  // namespace morphogen
