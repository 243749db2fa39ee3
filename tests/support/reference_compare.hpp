#pragma once
// Grows 6 random genomes on each built-in seed with the engine and with the
// plain reference implementation (reference_growth.hpp), step by step, and
// requires the same faces, positions, directions, outputs (to 1e-9) and, in
// the branching mode, growth states after every step. Returns the final
// states, for further checks.
#include "core/growth/growth.hpp"
#include "tests/support/reference_growth.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace morphogen::testing {

inline std::vector<GrowthState> require_same_as_reference(const GrowthParams& params, std::uint64_t first_genome) {
    const bool branching = params.mode == GrowthMode::branching;
    std::vector<GrowthState> grown;
    for (const std::string seed_name : {"icosahedron", "octahedron", "tetrahedron"}) {
        const Seed seed = make_seed(seed_name, 1.0);
        for (std::uint64_t g = first_genome; g < first_genome + 6; ++g) {
            const Network network(random_test_genome({45, 30, 15}, g));
            const Grower grower(network, params);
            GrowthWorkspace workspace;
            GrowthState state = grower.start(seed);
            ReferenceGrowth reference(seed, network.outputs(), branching);
            for (int t = 0; t < params.steps; ++t) {
                grower.step(state, workspace);
                reference.step(t, network, params);
                INFO(seed_name << " genome " << g << " step " << t);
                REQUIRE(state.mesh.faces() == reference.faces);
                for (int v = 0; v < state.mesh.num_vertices(); ++v) {
                    if (branching) REQUIRE(int{state.active[v]} == reference.active[v]);
                    REQUIRE((state.mesh.position(v) - reference.x[v]).norm() < 1e-9);
                    REQUIRE((state.directions[v] - reference.h[v]).norm() < 1e-9);
                    for (int c = 0; c < network.outputs(); ++c)
                        REQUIRE(std::abs(state.output(v, c) - reference.w[v][c]) < 1e-9);
                }
            }
            grown.push_back(std::move(state));
        }
    }
    return grown;
}

}  // namespace morphogen::testing
