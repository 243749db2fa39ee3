#pragma once
// A random genome grown with the step each vertex was born at (the wind
// data's flutter channel reads it): the engine tests' shared plant.
#include "engine/birth_steps.hpp"
#include "engine/plant_export.hpp"
#include "core/growth/genome_grower.hpp"
#include "tests/support/test_genomes.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace morphogen::testing {

struct Grown {
    GrowthState state;
    std::vector<int> births;
    // What the exporters take; it views this plant's mesh.
    GrownPlant plant() const { return {.mesh = state.mesh.view(), .birth_steps = births, .steps = state.steps_done}; }
};

// random_test_genome(seed) grown for `steps` steps at the default settings,
// in the given growth mode (the default's when not given).
inline Grown grow_dated(std::uint64_t seed, int steps, GrowthMode mode = GrowthParams{}.mode) {
    GrowthParams growth;
    growth.steps = steps;
    growth.mode = mode;
    const GenomeGrower grower(NetworkParams{}, growth);
    const Network network(random_test_genome(grower.layers(), seed));
    BirthSteps births(grower.seed().mesh.num_vertices());
    GrowthWorkspace workspace;
    GrowthState state = grower.grow(network, workspace, births.observer());
    return {std::move(state), births.steps()};
}

}  // namespace morphogen::testing
