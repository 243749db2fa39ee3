// The `tree` fitness (fitness/functions/tree_fitness.hpp, docs/fitness-tree.md "tree") on
// meshes whose light, sections and volume are known, and its config keys.
#include "fitness/fitness.hpp"
#include "fitness/functions/tree_fitness.hpp"
#include "tests/fitness/mesh_builders.hpp"

#include <catch2/catch.hpp>

using namespace morphogen;
using namespace morphogen::test;
using nlohmann::json;

namespace {


TreeFitnessParams overhead_sun() {
    TreeFitnessParams p;
    p.light.elevations_deg = {90.0};
    return p;
}

}  // namespace

TEST_CASE("tree fitness: a tree counts its light in full, less its material", "[fitness][tree]") {
    const MeshArrays tree = three_crowned_tree();
    const TreeScore s = tree_score(tree.view(), overhead_sun());
    CHECK(s.trunk_factor == 1.0);
    CHECK(s.branch_factor == 1.0);
    CHECK(s.light == Approx(12.0));
    CHECK(s.volume == Approx(130.0));
    CHECK(s.score == Approx(12.0 - 0.05 * 130.0));
}

TEST_CASE("tree fitness: the factors saturate at their targets", "[fitness][tree]") {
    const MeshArrays tree = three_crowned_tree();
    TreeFitnessParams p = overhead_sun();
    p.loops_target = 2;  // 3 loops: no more than full marks
    CHECK(tree_score(tree.view(), p).branch_factor == 1.0);
    p.loops_target = 6;  // 3 of 6
    CHECK(tree_score(tree.view(), p).branch_factor == 0.5);
    p.trunk_target = 0.05;  // ratio 0.1: half marks
    const TreeScore s = tree_score(tree.view(), p);
    CHECK(s.trunk_factor == Approx(0.5));
    CHECK(s.score == Approx(12.0 * 0.5 * 0.5 - 0.05 * 130.0));
    p.trunk_power = 3.0;  // (0.05 / 0.1)^3
    CHECK(tree_score(tree.view(), p).trunk_factor == Approx(0.125));
    p.trunk_target = 0.2;  // at or below the target the power does not matter
    CHECK(tree_score(tree.view(), p).trunk_factor == 1.0);
    p.trunk_target = 0.05;
    p.trunk_power = 1.0;
    p.material_cost = 0.0;
    p.light.min_height = 21.0;  // above everything: no light, no score
    CHECK(tree_score(tree.view(), p).score == 0.0);
}

TEST_CASE("tree fitness: a box is no tree, a flat mesh has no trunk", "[fitness][tree]") {
    // A 3 x 1 x 7 box: one loop (B = 1/3) and trunk_ratio 1 (T = 0.25).
    const MeshArrays box = make_box({0, 0, 0}, {3, 1, 7});
    const TreeScore b = tree_score(box.view(), overhead_sun());
    CHECK(b.trunk_factor == 0.25);
    CHECK(b.branch_factor == Approx(1.0 / 3.0));
    CHECK(b.light == Approx(3.0));
    CHECK(b.score == Approx(3.0 * 0.25 / 3.0 - 0.05 * 21.0));
    // No height: trunk_ratio is undefined, so T = 0 and the light is not cast.
    const MeshArrays flat = make_square(0, 0, 4, 4, 0);
    const TreeScore f = tree_score(flat.view(), overhead_sun());
    CHECK(f.trunk_factor == 0.0);
    CHECK(f.light == 0.0);
    CHECK(f.score == 0.0);
}

TEST_CASE("tree fitness: a plant that floats has no trunk", "[fitness][tree]") {
    MeshArrays tree = three_crowned_tree();
    for (Vec3& p : tree.positions) p.z() += 0.5;  // the trunk's foot at 0.5
    TreeFitnessParams p = overhead_sun();
    const TreeScore floating = tree_score(tree.view(), p);
    CHECK_FALSE(floating.rooted);
    CHECK(floating.trunk_factor == 0.0);
    CHECK(floating.score == Approx(-0.05 * 130.0));
    p.root_height = 0.5;  // now it stands
    const TreeScore standing = tree_score(tree.view(), p);
    CHECK(standing.rooted);
    CHECK(standing.trunk_factor == 1.0);
}

TEST_CASE("tree fitness: config keys, defaults and errors", "[fitness][tree][config]") {
    ConfigIssues issues;
    const json section = json::parse(R"({"type": "tree", "min_height": 6, "spacing": 0.25})");
    ObjectReader reader(&section, "fitness", issues);
    const std::unique_ptr<Fitness> fitness = read_fitness(reader);
    REQUIRE(issues.empty());
    REQUIRE(fitness);
    CHECK(fitness->function().type() == "tree");
    const json& resolved = reader.resolved();
    CHECK(resolved["trunk_target"] == 0.25);
    CHECK(resolved["loops_target"] == 3);
    CHECK(resolved["material_cost"] == 0.05);
    CHECK(resolved["root_height"] == 0.1);
    CHECK(resolved["trunk_power"] == 1.0);
    CHECK(resolved["min_height"] == 6.0);
    CHECK(resolved["elevations_deg"] == json::parse("[90.0, 45.0]"));

    const auto first_issue = [](const char* text) {
        ConfigIssues found;
        const json bad = json::parse(text);
        ObjectReader r(&bad, "fitness", found);
        CHECK_FALSE(read_fitness(r));
        return found.empty() ? std::string() : found.list().front().path + ": " + found.list().front().message;
    };
    CHECK(first_issue(R"({"type": "tree", "trunk_target": 0})").starts_with("fitness.trunk_target"));
    CHECK(first_issue(R"({"type": "tree", "loops_target": 0})").starts_with("fitness.loops_target"));
    CHECK(first_issue(R"({"type": "tree", "trunk_power": 0.5})").starts_with("fitness.trunk_power"));
    CHECK(first_issue(R"({"type": "tree", "material_cost": -1})").starts_with("fitness.material_cost"));
    CHECK(first_issue(R"({"type": "tree", "height": 10})").starts_with("fitness.height: unknown key"));
    CHECK(first_issue(R"({"type": "tree", "elevations_deg": []})").starts_with("fitness.elevations_deg"));
}
