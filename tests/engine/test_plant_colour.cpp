// Colour from growth history (docs/algorithm.md §13) on random genomes in
// both growth modes: in range, deterministic, woodier at the foot than at
// the tips, and a tint that follows the genome.
#include "engine/birth_steps.hpp"
#include "engine/plant_colour.hpp"
#include "core/growth/genome_grower.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <stdexcept>

namespace morphogen {
namespace {

struct Coloured {
    std::vector<Rgb> colours;
    std::vector<Vec3> positions;
    double tint = 0.5;
};

Coloured grow_coloured(std::uint64_t seed, GrowthMode mode) {
    GrowthParams growth;
    growth.steps = 60;
    growth.mode = mode;
    const GenomeGrower grower(NetworkParams{}, growth);
    const Network network(testing::random_test_genome(grower.layers(), seed));
    BirthSteps births(grower.seed().mesh.num_vertices());
    GrowthWorkspace workspace;
    const GrowthState state = grower.grow(network, workspace, births.observer());
    const ExposureParams exposure_params{};
    const std::vector<double> exposure =
        mode == GrowthMode::branching ? final_exposure(state.mesh, exposure_params) : std::vector<double>{};
    Coloured out;
    out.positions = state.mesh.positions();
    out.tint = genome_tint(state);
    out.colours = plant_colours({.positions = state.mesh.positions(),
                                 .birth_steps = births.steps(),
                                 .steps = state.steps_done,
                                 .active = state.active,
                                 .exposure = exposure,
                                 .tint = out.tint});
    return out;
}

// How brown a colour is: red over green (bark ~1.9, greens < 1).
double brownness(const Rgb& c) { return c[0] / std::max(c[1], 1e-6f); }

}  // namespace

TEST_CASE("plant colours: in range, deterministic, wood at the foot and green at the tips", "[colour]") {
    for (const GrowthMode mode : {GrowthMode::paper, GrowthMode::branching}) {
        int wood_below = 0, plants = 0;
        for (std::uint64_t seed = 1; seed <= 12; ++seed) {
            const Coloured a = grow_coloured(seed, mode);
            const Coloured b = grow_coloured(seed, mode);
            REQUIRE(a.colours == b.colours);
            REQUIRE(a.colours.size() == a.positions.size());
            for (const Rgb& c : a.colours)
                for (const float x : c) REQUIRE((x >= 0.0f && x <= 1.0f));
            REQUIRE((a.tint >= 0.0 && a.tint <= 1.0));
            // The lowest and highest tenth of the vertices by height.
            std::vector<int> order(a.positions.size());
            for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
            std::sort(order.begin(), order.end(),
                      [&](int x, int y) { return a.positions[x].z() < a.positions[y].z(); });
            const std::size_t tenth = std::max<std::size_t>(order.size() / 10, 1);
            double foot = 0.0, top = 0.0;
            for (std::size_t i = 0; i < tenth; ++i) {
                foot += brownness(a.colours[order[i]]);
                top += brownness(a.colours[order[order.size() - 1 - i]]);
            }
            ++plants;
            if (foot > top) ++wood_below;
        }
        INFO("mode " << (mode == GrowthMode::paper ? "paper" : "branching"));
        CHECK(wood_below == plants);
    }
}

TEST_CASE("plant colours: the tint shifts the hue, and bad sizes are refused", "[colour]") {
    const std::vector<Vec3> positions{Vec3(0, 0, 0), Vec3(0, 0, 1)};
    const std::vector<int> births{0, 10};
    ColourInputs in;
    in.positions = positions;
    in.birth_steps = births;
    in.steps = 10;
    in.tint = 0.0;
    const std::vector<Rgb> low = plant_colours(in);
    in.tint = 1.0;
    const std::vector<Rgb> high = plant_colours(in);
    CHECK(low[1] != high[1]);
    // The seed's vertex at the foot is bark; the newest at the top foliage.
    CHECK(brownness(low[0]) > 1.5);
    CHECK(brownness(high[1]) < 1.0);
    const std::vector<int> short_births{0};
    in.birth_steps = short_births;
    CHECK_THROWS_AS(plant_colours(in), std::invalid_argument);
}

}  // namespace morphogen
