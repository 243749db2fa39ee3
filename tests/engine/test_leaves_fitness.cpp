// Do the foliage cards (engine/leaf_cards.hpp) stand where the `plant`
// fitness puts its leaves? The fitness counts every face as leaf tissue,
// grouped in cubes of side leaf_size, each yielding by its cube's mean
// irradiance (fitness/functions/plant_fitness.hpp). Over 60 random genomes of
// tree.json's growth and fitness (15 carry cards, 1,345 cards), the faces
// around the cards' vertices yield 1.13 times the light per unit area of the
// plants' faces on average, and 114 cards (8.5 %) stand in leaves no ray
// reaches: the cards follow the growth's voxel shade (§5.9), not the fitness's
// rays. Asserted: more than the average, and at most 15 % in unlit leaves.
#include "engine/leaf_cards.hpp"
#include "engine/plant_frame.hpp"
#include "fitness/functions/plant_fitness.hpp"
#include "tests/engine/grow_dated.hpp"

#include <catch2/catch.hpp>

namespace morphogen {

TEST_CASE("leaf cards stand in the plant fitness's lit leaves", "[leaves][fitness]") {
    GrowthParams growth;  // tree.json's growth
    growth.mode = GrowthMode::branching;
    growth.steps = 150;
    growth.max_vertices = 1000;
    growth.exposure = true;
    growth.collisions = Collisions::touch;
    growth.signal_diffusion = 8;
    const GenomeGrower grower(NetworkParams{}, growth);
    const PlantFitnessParams fitness;  // leaf_size 1, half_saturation 0.25
    LightParams light_params = fitness.light;
    light_params.spacing = 0.25;  // tree.json's
    double card_yield = 0, card_area = 0, plant_yield = 0, plant_area = 0;
    std::size_t cards = 0, dark = 0, plants = 0;
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
        const Network network(testing::random_test_genome(grower.layers(), seed));
        BirthSteps births(grower.seed().mesh.num_vertices());
        GrowthWorkspace workspace;
        const GrowthState state = grower.grow(network, workspace, births.observer());
        const std::vector<double> light = leaf_light(state, growth);
        const MeshView mesh = state.mesh.view();
        const PlacedPlant placed = place_plant(mesh, std::nullopt);
        const std::vector<LeafCard> placed_cards =
            leaf_cards({.placed = placed.mesh.view(), .birth_steps = births.steps(), .steps = state.steps_done,
                        .light = light, .seed = leaf_seed(std::to_string(seed))},
                       {});
        if (placed_cards.empty()) continue;
        ++plants;
        const std::vector<double> yields =
            face_yields(mesh, light_per_face(mesh, light_params), fitness.half_saturation, fitness.leaf_size);
        std::vector<std::vector<int>> faces_of(mesh.positions.size());
        for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
            const Face& face = mesh.faces[f];
            const double area = 0.5 * (mesh.positions[face[1]] - mesh.positions[face[0]])
                                          .cross(mesh.positions[face[2]] - mesh.positions[face[0]])
                                          .norm();
            plant_yield += yields[f], plant_area += area;
            for (const int v : face) faces_of[static_cast<std::size_t>(v)].push_back(static_cast<int>(f));
        }
        for (const LeafCard& card : placed_cards) {
            double yield = 0, area = 0;
            for (const int f : faces_of[static_cast<std::size_t>(card.vertex)]) {
                const Face& face = mesh.faces[static_cast<std::size_t>(f)];
                yield += yields[static_cast<std::size_t>(f)];
                area += 0.5 * (mesh.positions[face[1]] - mesh.positions[face[0]])
                                  .cross(mesh.positions[face[2]] - mesh.positions[face[0]])
                                  .norm();
            }
            card_yield += yield, card_area += area, ++cards, dark += yield == 0.0;
        }
    }
    const double card_rate = card_yield / card_area, plant_rate = plant_yield / plant_area;
    WARN(plants << " plants, " << cards << " cards: yield per unit area around the cards " << card_rate
                << ", over the plants " << plant_rate << " (x" << card_rate / plant_rate << "); " << dark
                << " cards in unlit leaves");
    REQUIRE(cards > 100);
    CHECK(card_rate > plant_rate);
    CHECK(static_cast<double>(dark) <= 0.15 * static_cast<double>(cards));
}

}  // namespace morphogen
