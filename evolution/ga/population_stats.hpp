#pragma once
// Summary of a population for the history: over valid members only (an
// invalid member has no score); every field is empty when none is valid.
#include "evolution/individual.hpp"

#include <optional>
#include <span>

namespace morphogen {

struct PopulationStats {
    std::optional<double> best, mean, median, worst, mean_size;
    std::size_t valid = 0;
};

// Sums run in slot order, so the result is a pure function of the population.
PopulationStats summarize(std::span<const Individual> population);
// The same over individuals held elsewhere (e.g. an archive's elites), in the given order.
PopulationStats summarize(std::span<const Individual* const> members);

}  // namespace morphogen
