#pragma once
// Genomes as the GA sees them: parameter vectors with an id and a score.
// Nothing here knows what the parameters mean.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace morphogen {

// [offset, length) of a group of parameters that crossover keeps together
// (for the growth network: one neuron's weights and threshold).
using Block = std::pair<std::size_t, std::size_t>;

inline constexpr double invalid_fitness = -std::numeric_limits<double>::infinity();

// What a Problem says about one genome. `score` matters only when `valid`.
struct Evaluation {
    double score = 0.0;
    bool valid = false;
    std::string error;  // why it is invalid
    double size = 0.0;  // a problem-defined size reported in the history (vertices for meshes)
    // Problem-defined behaviour descriptors that place a genome in a
    // MAP-Elites archive; empty for problems that have none (the GA ignores them).
    std::vector<double> descriptors = {};
    // Problem-defined bytes kept from the evaluation for export (the grown
    // mesh's files), only when asked for (Problem::evaluate_keeping).
    std::string kept = {};
};

struct Individual {
    std::uint64_t id = 0;                  // its birth index, unique in a run
    std::optional<std::uint64_t> parent1;  // none for the initial population
    std::optional<std::uint64_t> parent2;  // set only when the child came from crossover
    std::vector<double> params;
    double fitness = invalid_fitness;      // -infinity exactly when invalid, otherwise finite
    double size = 0.0;
    std::vector<double> descriptors = {};  // from its Evaluation; empty when invalid or none

    bool valid() const { return std::isfinite(fitness); }
};

}  // namespace morphogen
