// The `plant` fitness (fitness/functions/plant_fitness.hpp, docs/fitness-plant.md "plant"):
// its light term on meshes whose irradiance is known, its moment, and its
// config keys. The tips come from fitness/architecture/architecture.hpp, tested there, on the
// finer bands that keep a crown's short shoots (tested here and on the labelled controls).
#include "fitness/fitness.hpp"
#include "fitness/functions/light.hpp"
#include "fitness/functions/plant_fitness.hpp"
#include "tests/fitness/limb_controls.hpp"
#include "tests/fitness/mesh_builders.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

using namespace morphogen;
using namespace morphogen::test;
using nlohmann::json;

namespace {

LightParams one_sun(double elevation_deg) {
    LightParams p;
    p.elevations_deg = {elevation_deg};
    p.azimuths_deg = {0.0};
    p.spacing = 0.05;
    return p;
}

double sum(const std::vector<double>& values) { return std::accumulate(values.begin(), values.end(), 0.0); }

// A side × side square at z = 0 cut into n × n cells of two triangles each.
MeshArrays grid_square(double side, int n) {
    MeshArrays m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) m.positions.emplace_back(side * i / n, side * j / n, 0.0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            m.faces.push_back({a, b, d});
            m.faces.push_back({a, d, c});
        }
    return m;
}

}  // namespace

TEST_CASE("plant fitness: the light per face adds up to the light captured", "[fitness][plant]") {
    MeshArrays sphere = make_icosphere(3);
    for (Vec3& p : sphere.positions) p = 3.0 * p + Vec3(0, 0, 3);
    LightParams p;  // five suns
    const std::vector<double> per_face = light_per_face(sphere.view(), p);
    REQUIRE(per_face.size() == sphere.faces.size());
    CHECK(sum(per_face) == Approx(light_captured(sphere.view(), p)).epsilon(1e-12));
    // The lower half is in its own shade under the overhead sun.
    const std::vector<double> overhead = light_per_face(sphere.view(), one_sun(90));
    for (std::size_t f = 0; f < sphere.faces.size(); ++f) {
        const Face& face = sphere.faces[f];
        if (sphere.positions[face[0]].z() < 2.9 && sphere.positions[face[1]].z() < 2.9 &&
            sphere.positions[face[2]].z() < 2.9)
            CHECK(overhead[f] == 0.0);
    }
}

TEST_CASE("plant fitness: a face's yield saturates with its light", "[fitness][plant]") {
    const MeshArrays square = make_square(0, 0, 10, 10, 0);
    // Square to an overhead sun: I = 1, so every face yields its area, whatever K.
    const std::vector<double> overhead = light_per_face(square.view(), one_sun(90));
    CHECK(sum(overhead) == Approx(100.0));
    for (double K : {0.1, 0.25, 4.0}) CHECK(saturating_light(square.view(), overhead, K) == Approx(100.0).epsilon(1e-4));
    // A sun 30 degrees up: I = sin 30 = 1/2, so the yield is (1 + K) / (1 + 2K) of the area.
    const std::vector<double> low = light_per_face(square.view(), one_sun(30));
    CHECK(sum(low) == Approx(50.0).epsilon(0.02));
    CHECK(saturating_light(square.view(), low, 0.25) == Approx(100.0 * 1.25 / 1.5).epsilon(0.02));
    // As K grows the yield becomes the plain light.
    CHECK(saturating_light(square.view(), low, 1e9) == Approx(sum(low)).epsilon(1e-6));
    // A half-lit face yields more than the light it catches: spreading light pays.
    CHECK(saturating_light(square.view(), low, 0.25) > sum(low));
}

TEST_CASE("plant fitness: a leaf saturates, not a triangle, so the light does not depend on the triangulation",
          "[fitness][plant]") {
    // A 10 x 10 square under a sun 30 degrees up: I = 1/2, so it yields (1 + K) / (1 + 2K) of its area.
    const double expected = 100.0 * 1.25 / 1.5;
    const MeshArrays coarse = grid_square(10.0, 1);  // 2 faces of 50 units²
    const MeshArrays fine = grid_square(10.0, 80);   // faces of 0.0078 units², smaller than a ray's 0.0625
    LightParams sun = one_sun(30);
    sun.spacing = 0.25;
    const std::vector<double> coarse_light = light_per_face(coarse.view(), sun);
    const std::vector<double> fine_light = light_per_face(fine.view(), sun);
    CHECK(sum(fine_light) == Approx(sum(coarse_light)).epsilon(0.02));  // the same rays land
    // Each face alone: the fine square's faces are hit by one ray or none, and the concave
    // hyperbola undercounts that sampled irradiance.
    CHECK(saturating_light(coarse.view(), coarse_light, 0.25, 0.0) == Approx(expected).epsilon(0.02));
    CHECK(saturating_light(fine.view(), fine_light, 0.25, 0.0) < 0.8 * expected);
    // Leaves of side 1 (about 8 rays each here): both give the square's yield.
    for (const MeshArrays* square : {&coarse, &fine}) {
        const std::vector<double> light = square == &coarse ? coarse_light : fine_light;
        CHECK(saturating_light(square->view(), light, 0.25, 1.0) == Approx(expected).epsilon(0.03));
        CHECK(sum(face_yields(square->view(), light, 0.25, 1.0)) ==
              Approx(saturating_light(square->view(), light, 0.25, 1.0)).epsilon(1e-12));
    }
    // Within a leaf every face takes the leaf's mean irradiance, lit by a ray or not.
    const std::vector<double> yields = face_yields(fine.view(), fine_light, 0.25, 1.0);
    CHECK(std::count(fine_light.begin(), fine_light.end(), 0.0) > 0);
    CHECK(std::count(yields.begin(), yields.end(), 0.0) == 0);
    // plant_score uses the leaves: the fine and the coarse square catch the same light.
    PlantFitnessParams params;
    params.light = sun;
    CHECK(plant_score(fine.view(), params).light == Approx(plant_score(coarse.view(), params).light).epsilon(0.03));
}

TEST_CASE("plant fitness: the score is its terms combined, and a plant must stand", "[fitness][plant]") {
    MeshArrays sphere = make_icosphere(3);
    for (Vec3& p : sphere.positions) p = 2.0 * p + Vec3(5, -3, 2);  // resting on z = 0
    PlantFitnessParams params;
    params.light = one_sun(90);
    const PlantScore s = plant_score(sphere.view(), params);
    REQUIRE(s.rooted);
    REQUIRE(s.tips >= 1);
    CHECK(s.reproduction > 0.0);
    CHECK(s.light > 0.0);
    CHECK(s.cost == Approx(1.0 + params.moment_cost * s.moment));
    CHECK(s.score == Approx(std::sqrt(s.light * s.reproduction) / s.cost));
    // The moment is about the foot: moving the plant changes nothing.
    MeshArrays moved = sphere;
    for (Vec3& p : moved.positions) p += Vec3(-40, 7, 0);
    CHECK(plant_score(moved.view(), params).moment == Approx(s.moment).epsilon(1e-9));
    // A plant that floats scores 0.
    for (Vec3& p : moved.positions) p.z() += 0.5;
    const PlantScore floating = plant_score(moved.view(), params);
    CHECK_FALSE(floating.rooted);
    CHECK(floating.score == 0.0);
}

TEST_CASE("plant fitness: a tip is fed by the lit faces nearest to it within its shoot's reach", "[fitness][plant]") {
    MeshArrays sphere = make_icosphere(3);
    for (Vec3& p : sphere.positions) p = 3.0 * p + Vec3(0, 0, 3);
    const std::vector<double> overhead = light_per_face(sphere.view(), one_sun(90));
    const double all = saturating_light(sphere.view(), overhead, 0.25);
    const std::vector<Vec3> top_and_bottom = {Vec3(0, 0, 6), Vec3(0, 0, 0)};
    // Reach enough for every face: the lit faces split between the tips, each to the nearer.
    std::vector<double> shoots = shoot_light(sphere.view(), overhead, 0.25, top_and_bottom, 100.0);
    REQUIRE(shoots.size() == 2);
    CHECK(shoots[0] + shoots[1] == Approx(all).epsilon(1e-12));
    CHECK(shoots[1] == 0.0);  // the bottom is in the sphere's own shade
    CHECK(shoots[0] == Approx(all).epsilon(1e-12));
    // A short reach feeds the top tip only from the cap around it: the faces
    // with centroids within 2 of (0, 0, 6), a cap of height 2/3 of 9 units² in full sun.
    shoots = shoot_light(sphere.view(), overhead, 0.25, top_and_bottom, 2.0);
    CHECK(shoots[0] > 0.6 * 2 * M_PI * 3 * (2.0 / 3.0) * 0.8);
    CHECK(shoots[0] < 0.5 * all);
    // A tip out of reach of every lit face is fed nothing.
    CHECK(shoot_light(sphere.view(), overhead, 0.25, {Vec3(20, 0, 3)}, 2.0) == std::vector<double>{0.0});
}

TEST_CASE("plant fitness: a tip bears by its shoot's light; H = 0 bears every tip in full", "[fitness][plant]") {
    MeshArrays sphere = make_icosphere(3);
    for (Vec3& p : sphere.positions) p = 2.0 * p + Vec3(5, -3, 2);  // resting on z = 0
    PlantFitnessParams params;
    params.light = one_sun(90);
    params.shoot_half_light = 0.0;
    const PlantScore full = plant_score(sphere.view(), params);
    REQUIRE(full.tips >= 1);
    CHECK(full.bearing_tips == full.tips);
    double prev_reproduction = full.reproduction, prev_bearing = full.bearing_tips;
    for (double H : {0.5, 2.0, 8.0, 1000.0}) {
        params.shoot_half_light = H;
        const PlantScore s = plant_score(sphere.view(), params);
        CHECK(s.light == Approx(full.light).epsilon(1e-12));  // the light term is the whole plant's
        CHECK(s.bearing_tips < prev_bearing);
        CHECK(s.reproduction < prev_reproduction);
        CHECK(s.score == Approx(std::sqrt(s.light * s.reproduction) / s.cost));
        prev_reproduction = s.reproduction, prev_bearing = s.bearing_tips;
    }
    CHECK(prev_bearing < 0.05 * full.tips);
}

TEST_CASE("plant fitness: weight held away from the foot costs more", "[fitness][plant]") {
    // A post with a box on top, once centred and once held 6 units out on one side.
    const MeshArrays post = make_box({-0.5, -0.5, 0}, {0.5, 0.5, 8});
    const MeshArrays centred = merge(post, make_box({-1, -1, 8}, {1, 1, 10}));
    const MeshArrays aside = merge(post, make_box({5, -1, 8}, {7, 1, 10}));
    PlantFitnessParams params;
    params.light = one_sun(90);
    const double centred_moment = plant_score(centred.view(), params).moment;
    const double aside_moment = plant_score(aside.view(), params).moment;
    // The box's 24 units of area move 6 units out: 144 more, up to the faces'
    // spread about their centroids.
    CHECK(aside_moment > centred_moment + 100.0);
}

TEST_CASE("plant fitness: the wood of a solid body costs by its volume", "[fitness][plant]") {
    // A post 1 x 1 x 8 under a box 2 x 2 x 2: 16 units of volume.
    const MeshArrays tree = merge(make_box({-0.5, -0.5, 0}, {0.5, 0.5, 8}), make_box({-1, -1, 8}, {1, 1, 10}));
    PlantFitnessParams params;
    params.light = one_sun(90);
    const PlantScore free = plant_score(tree.view(), params);
    CHECK(free.volume == Approx(16.0));
    CHECK(free.cost == Approx(1.0 + params.moment_cost * free.moment));
    params.volume_cost = 0.05;
    const PlantScore costly = plant_score(tree.view(), params);
    CHECK(costly.cost == Approx(1.0 + params.moment_cost * free.moment + 0.05 * 16.0));
    CHECK(costly.score == Approx(free.score * free.cost / costly.cost));
}

TEST_CASE("plant fitness: config keys, defaults and errors", "[fitness][plant][config]") {
    ConfigIssues issues;
    const json section = json::parse(R"({"type": "plant", "spacing": 0.25})");
    ObjectReader reader(&section, "fitness", issues);
    const std::unique_ptr<Fitness> fitness = read_fitness(reader);
    REQUIRE(issues.empty());
    REQUIRE(fitness);
    CHECK(fitness->function().type() == "plant");
    const json& resolved = reader.resolved();
    CHECK(resolved["half_saturation"] == 0.25);
    CHECK(resolved["moment_cost"] == 0.0002);
    CHECK(resolved["root_height"] == 0.1);
    CHECK(resolved["shoot_radius"] == 2.5);
    CHECK(resolved["shoot_half_light"] == 4.0);
    CHECK(resolved["shoot_band_edges"] == 1.0);
    CHECK(resolved["volume_cost"] == 0.0);
    CHECK(resolved["leaf_size"] == 1.0);
    CHECK(resolved["stand_spacing"] == 0.0);
    CHECK(resolved["spacing"] == 0.25);

    const auto first_issue = [](const char* text) {
        ConfigIssues found;
        const json bad = json::parse(text);
        ObjectReader r(&bad, "fitness", found);
        CHECK_FALSE(read_fitness(r));
        return found.empty() ? std::string() : found.list().front().path + ": " + found.list().front().message;
    };
    CHECK(first_issue(R"({"type": "plant", "half_saturation": 0})").starts_with("fitness.half_saturation"));
    CHECK(first_issue(R"({"type": "plant", "moment_cost": -1})").starts_with("fitness.moment_cost"));
    CHECK(first_issue(R"({"type": "plant", "shoot_radius": 0})").starts_with("fitness.shoot_radius"));
    CHECK(first_issue(R"({"type": "plant", "shoot_half_light": -1})").starts_with("fitness.shoot_half_light"));
    CHECK(first_issue(R"({"type": "plant", "shoot_band_edges": 0})").starts_with("fitness.shoot_band_edges"));
    CHECK(first_issue(R"({"type": "plant", "volume_cost": -1})").starts_with("fitness.volume_cost"));
    CHECK(first_issue(R"({"type": "plant", "leaf_size": -1})").starts_with("fitness.leaf_size"));
    CHECK(first_issue(R"({"type": "plant", "stand_spacing": -1})").starts_with("fitness.stand_spacing"));
    CHECK(first_issue(R"({"type": "plant", "trunk_target": 0.2})").starts_with("fitness.trunk_target: unknown key"));
}

TEST_CASE("plant fitness: at the growth's 1,000 vertices a crown's short shoots are tips", "[fitness][plant]") {
    // A trunk under one crown with 10 shoots standing out 2.5x as far as
    // they are thick, decimated as the labelled controls are: the
    // architecture measures' bands (two median edges) lose half of them, the
    // plant's (one edge) keep at least 8 (5 and 8 when written).
    constexpr double kPi = std::numbers::pi;
    const Vec3 centre(0, 0, 6);
    const auto field = [&](const Vec3& p) {
        double f = smooth_union(cylinder_field(p, {0, 0, 0}, 0.7, 6.0), sphere_field(p, centre, 2.7), 0.3);
        for (int i = 0; i < 10; ++i) {
            const double polar = 0.35 + 0.8 * (i % 2), azimuth = 2 * kPi * i / 10;
            const Vec3 dir(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
            f = smooth_union(f, capsule_field(p, centre + 1.9 * dir, centre + 3.7 * dir, 0.25), 0.1);
        }
        return f;
    };
    const MeshArrays mesh = testing::decimated(testing::implicit_mesh(field, {-4.5, -4.5, -0.5}, {4.5, 4.5, 10.5}, 0.2), 1000);
    PlantFitnessParams params;
    params.light = one_sun(90.0);
    params.light.spacing = 0.25;
    const int measured_tips = measure_architecture(mesh.view()).tips;
    const int plant_tips = plant_score(mesh.view(), params).tips;
    INFO(mesh.positions.size() << " vertices: the measures' tips " << measured_tips << ", the plant's " << plant_tips);
    CHECK(plant_tips >= 8);
    CHECK(measured_tips <= plant_tips - 3);
}
