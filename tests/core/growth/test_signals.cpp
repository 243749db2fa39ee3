// The signals of docs/algorithm.md §5.9 (growth.exposure, growth.signal_diffusion):
// cases worked out by hand, the engine against the plain reference
// implementation, and growth with the keys off unchanged to the byte.
#include "core/base/config_reader.hpp"
#include "core/base/errors.hpp"
#include "core/growth/signals/exposure.hpp"
#include "core/growth/growth.hpp"
#include "core/growth/signals/signal_diffusion.hpp"
#include "tests/support/config_issues.hpp"
#include "tests/support/reference_compare.hpp"
#include "tests/support/test_genomes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

using namespace morphogen;
using namespace morphogen::testing;
using nlohmann::json;

namespace {

// Six points in unit voxels (I, J, K): A (0,0,2), B and E (0,0,0), C (1,0,1),
// D (5,0,0), F (0,0,3).
const std::vector<Vec3> kPoints = {{0.5, 0.5, 2.5}, {0.5, 0.5, 0.5}, {1.5, 0.5, 1.5},
                                   {5.5, 0.5, 0.5}, {0.2, 0.8, 0.1}, {0.5, 0.5, 3.5}};

std::vector<double> exposure_of(const std::vector<Vec3>& points, const ExposureParams& params,
                                std::uint64_t max_table_cells) {
    ExposureWorkspace workspace;
    std::vector<double> exposure;
    compute_exposure(points, params, workspace, exposure, max_table_cells);
    return exposure;
}

GrowthParams signal_params() {
    GrowthParams p;
    p.mode = GrowthMode::branching;
    p.exposure = true;
    p.exposure_depth = 3;
    p.exposure_full_shade = 4.0;
    p.signal_diffusion = 4;
    p.signal_rate = 0.6;
    return p;
}

bool same_bytes(const GrowthState& a, const GrowthState& b) {
    return a.mesh.faces() == b.mesh.faces() && a.outputs == b.outputs && a.active == b.active &&
           std::memcmp(a.mesh.positions().data(), b.mesh.positions().data(), sizeof(Vec3) * a.mesh.num_vertices()) == 0 &&
           std::memcmp(a.directions.data(), b.directions.data(), sizeof(Vec3) * a.directions.size()) == 0;
}

GrowthState grow(const Genome& genome, const GrowthParams& params) {
    const Network network(genome);
    GrowthWorkspace workspace;
    return Grower(network, params).grow(make_seed("icosahedron", 1.0), workspace);
}

// The problems of a growth section, and what it resolves to.
ConfigIssues read_growth(const json& section, json* resolved = nullptr) {
    ConfigIssues issues;
    ObjectReader reader(&section, "growth", issues);
    read_growth_params(reader);
    if (resolved != nullptr) *resolved = reader.resolved();
    return issues;
}

}  // namespace

TEST_CASE("exposure of six points, worked out by hand", "[growth][signals]") {
    // Depth 2, full shade 2: exposure = clamp((3 − s) / 2, 0, 1).
    //   A: itself 1 + F one level up 1/2            = 1.5  -> 0.75
    //   B, E: both 1 + 1, C (d = 1, dx = 1) 1/2,
    //         A (d = 2) 1/4; F is 3 levels up: none = 2.75 -> 0.125
    //   C: itself 1 + A (d = 1) 1/2 + F (d = 2) 1/4 = 1.75 -> 0.625
    //   D: itself only (C, A, F are beyond dx ≤ d)  = 1    -> 1
    //   F: itself only                              = 1    -> 1
    const std::vector<double> expected = {0.75, 0.125, 0.625, 1.0, 0.125, 1.0};
    const ExposureParams params{1.0, 2, 2.0};
    for (const std::uint64_t cells : {std::uint64_t{0}, std::uint64_t{1} << 20}) {
        INFO((cells == 0 ? "hash map" : "summed-area tables"));
        CHECK(exposure_of(kPoints, params, cells) == expected);
    }
    // The default choice of path gives the same; so does the set moved by
    // whole voxels (negative indices); a small full shade clamps at 0.
    ExposureWorkspace workspace;
    std::vector<double> exposure;
    compute_exposure(kPoints, params, workspace, exposure);
    CHECK(exposure == expected);
    std::vector<Vec3> moved = kPoints;
    for (Vec3& p : moved) p += Vec3(-10.0, -20.0, -5.0);
    CHECK(exposure_of(moved, params, 0) == expected);
    CHECK(exposure_of(moved, params, 1u << 20) == expected);
    CHECK(exposure_of(kPoints, ExposureParams{1.0, 2, 1.0}, 0)[1] == 0.0);
    // A cell of 2: B shares voxel (0,0,0) with C and E (3), and A and F, one
    // level up, add 1/2 each: s = 4 -> clamp(-0.5) = 0.
    CHECK(exposure_of(kPoints, ExposureParams{2.0, 2, 2.0}, 0)[1] == 0.0);
}

TEST_CASE("exposure: the summed-area tables and the hash map agree to the bit on grown meshes",
          "[growth][signals]") {
    GrowthParams params = signal_params();
    params.steps = 60;
    params.max_vertices = 600;
    for (std::uint64_t g = 1; g <= 4; ++g) {
        const GrowthState state = grow(random_test_genome({45, 30, 15}, g), params);
        for (const double cell : {0.3, 1.0, 2.5}) {
            const ExposureParams exposure{cell, 5, 6.0};
            const std::vector<double> tables = exposure_of(state.mesh.positions(), exposure, 1u << 24);
            CHECK(tables == exposure_of(state.mesh.positions(), exposure, 0));
            for (const double e : tables) CHECK((e >= 0.0 && e <= 1.0));
        }
    }
}

TEST_CASE("one and two diffusion iterations, worked out by hand", "[growth][signals]") {
    // Tetrahedron: every vertex neighbours the other three. Channel 7 is
    // (0.9, 0.1, 0.1, 0.1); rate 0.5.
    const std::vector<int> offsets = {0, 3, 6, 9, 12};
    const std::vector<int> neighbours = {1, 2, 3, 0, 2, 3, 0, 1, 3, 0, 1, 2};
    constexpr int N = 8;
    std::vector<double> outputs(4 * N, 0.5);
    const double u0[4] = {0.9, 0.1, 0.1, 0.1};
    for (int i = 0; i < 4; ++i) outputs[i * N + kSignalChannel] = u0[i];
    std::vector<double> once = outputs, twice = outputs, scratch;
    diffuse_signal(once, N, offsets, neighbours, 1, 0.5, scratch);
    // vertex 0: 0.9 + 0.5 (0.1 − 0.9) = 0.5; the others: 0.1 + 0.5 ((0.9 + 0.2) / 3 − 0.1) = 0.7 / 3.
    CHECK(once[0 * N + kSignalChannel] == Approx(0.5).epsilon(1e-15));
    for (int i = 1; i < 4; ++i) CHECK(once[i * N + kSignalChannel] == Approx(0.7 / 3.0).epsilon(1e-15));
    // Jacobi, from the first iterate: 0.5 + 0.5 (0.7/3 − 0.5) = 11/30;
    // 0.7/3 + 0.5 ((0.5 + 1.4/3) / 3 − 0.7/3) = 0.7/6 + 2.9/18.
    diffuse_signal(twice, N, offsets, neighbours, 2, 0.5, scratch);
    CHECK(twice[0 * N + kSignalChannel] == Approx(11.0 / 30.0).epsilon(1e-14));
    for (int i = 1; i < 4; ++i) CHECK(twice[i * N + kSignalChannel] == Approx(0.7 / 6.0 + 2.9 / 18.0).epsilon(1e-14));
    // No other channel changes.
    for (int i = 0; i < 4; ++i)
        for (int c = 0; c < N; ++c)
            if (c != kSignalChannel) CHECK(twice[i * N + c] == 0.5);
}

TEST_CASE("k diffusion iterations carry a signal exactly k rings", "[growth][signals]") {
    // A path 0 - 1 - ... - 9 with the signal at vertex 0 alone.
    constexpr int V = 10, N = 8;
    std::vector<int> offsets{0}, neighbours;
    for (int i = 0; i < V; ++i) {
        if (i > 0) neighbours.push_back(i - 1);
        if (i + 1 < V) neighbours.push_back(i + 1);
        offsets.push_back(static_cast<int>(neighbours.size()));
    }
    for (const int k : {1, 3, 6}) {
        std::vector<double> outputs(V * N, 0.0), scratch;
        outputs[kSignalChannel] = 1.0;
        diffuse_signal(outputs, N, offsets, neighbours, k, 0.5, scratch);
        INFO("k = " << k);
        CHECK(outputs[k * N + kSignalChannel] > 0.0);
        CHECK(outputs[(k + 1) * N + kSignalChannel] == 0.0);
    }
}

TEST_CASE("the exposure reaches the network as input 3N-6", "[growth][signals]") {
    // N = 8, no hidden layer, zero weights but input 3N−6 → output 7 with
    // weight 4: after step 0, w[7] = sigmoid(4 (E − 0.5)), E the seed's exposure.
    constexpr int N = kSignalOutputs;
    Genome genome{{3 * N, N}, std::vector<double>(static_cast<std::size_t>(N) * (3 * N + 1), 0.0)};
    genome.params[static_cast<std::size_t>(kSignalChannel) * (3 * N + 1) + (3 * N - 6)] = 4.0;
    const Network network(genome);
    GrowthParams params = signal_params();
    params.signal_diffusion = 0;  // output 7 as the network gave it
    params.split_area = 1e6;
    const Grower grower(network, params);
    const Seed seed = make_seed("icosahedron", 1.0);
    GrowthState state = grower.start(seed);
    GrowthWorkspace workspace;
    grower.step(state, workspace);
    ExposureWorkspace scratch;
    std::vector<double> exposure;
    compute_exposure(seed.mesh.positions(), ExposureParams{params.exposure_cell, params.exposure_depth, params.exposure_full_shade},
                     scratch, exposure);
    REQUIRE(workspace.exposure == exposure);
    // The top of the icosahedron is lit, its bottom shaded by the rest.
    CHECK(*std::max_element(exposure.begin(), exposure.end()) == 1.0);
    CHECK(*std::min_element(exposure.begin(), exposure.end()) < 1.0);
    for (int i = 0; i < seed.mesh.num_vertices(); ++i)
        CHECK(state.output(i, kSignalChannel) == Approx(1.0 / (1.0 + std::exp(-4.0 * (exposure[i] - 0.5)))).epsilon(1e-13));
}

TEST_CASE("branching growth with both signals matches the plain reference implementation",
          "[growth][signals][reference]") {
    GrowthParams params = signal_params();
    params.steps = 40;
    params.max_vertices = 500;
    const std::vector<GrowthState> grown = require_same_as_reference(params, 301);
    // The signals change what grows (else the comparison would prove little).
    GrowthParams off = params;
    off.exposure = false;
    off.signal_diffusion = 0;
    int changed = 0;
    for (std::uint64_t g = 301; g < 307; ++g)
        changed += !same_bytes(grown[g - 301], grow(random_test_genome({45, 30, 15}, g), off));
    CHECK(changed >= 5);
}

TEST_CASE("growth with the signals off is the growth of before, bit for bit", "[growth][signals]") {
    const Genome genome = random_test_genome({45, 30, 15}, 11);
    GrowthParams branching;
    branching.mode = GrowthMode::branching;
    branching.steps = 40;
    // Their own keys set while the signals are off change nothing.
    GrowthParams off = branching;
    off.exposure_cell = 0.25;
    off.exposure_depth = 9;
    off.exposure_full_shade = 1.5;
    off.signal_rate = 0.9;
    CHECK(same_bytes(grow(genome, branching), grow(genome, off)));
    // The paper's mode ignores them even when on.
    GrowthParams paper;
    paper.steps = 40;
    GrowthParams paper_on = paper;
    paper_on.exposure = true;
    paper_on.signal_diffusion = 5;
    const GrowthState a = grow(genome, paper), b = grow(genome, paper_on);
    CHECK(same_bytes(a, b));
    CHECK(a.active.empty());
}

TEST_CASE("the signals' keys: branching mode only, in range, recorded only when on", "[growth][signals][config]") {
    for (const char* key : {"exposure", "exposure_cell", "exposure_depth", "exposure_full_shade", "signal_diffusion",
                            "signal_rate"}) {
        INFO(key);
        CHECK(has_issue(read_growth(json{{key, 1}}), std::string("growth.") + key, "growth.mode \"branching\""));
    }
    const auto branching = [](json keys) {
        keys["mode"] = "branching";
        return keys;
    };
    CHECK(has_issue(read_growth(branching({{"exposure_cell", 2}})), "growth.exposure_cell", "growth.exposure true"));
    CHECK(has_issue(read_growth(branching({{"signal_rate", 0.3}})), "growth.signal_rate", "growth.signal_diffusion > 0"));
    CHECK(has_issue(read_growth(branching({{"exposure", true}, {"exposure_depth", 17}})), "growth.exposure_depth", "17"));
    CHECK(has_issue(read_growth(branching({{"exposure", true}, {"exposure_cell", 0}})), "growth.exposure_cell", "0"));
    CHECK(has_issue(read_growth(branching({{"exposure", true}, {"exposure_full_shade", 0}})),
                    "growth.exposure_full_shade", "0"));
    CHECK(has_issue(read_growth(branching({{"signal_diffusion", 65}})), "growth.signal_diffusion", "65"));
    CHECK(has_issue(read_growth(branching({{"signal_diffusion", 2}, {"signal_rate", 0}})), "growth.signal_rate", "0"));
    CHECK(has_issue(read_growth(branching({{"signal_diffusion", 2}, {"signal_rate", 1.5}})), "growth.signal_rate", "1.5"));
    CHECK(has_issue(read_growth(branching({{"exposure", "yes"}})), "growth.exposure", "yes"));
    // Off: the switches recorded as off (every key resolved), their own keys not.
    json resolved, plain;
    CHECK(read_growth(branching(json::object()), &plain).empty());
    CHECK(read_growth(branching({{"exposure", false}, {"signal_diffusion", 0}}), &resolved).empty());
    CHECK(resolved == plain);
    CHECK(plain["exposure"] == false);
    CHECK(plain["signal_diffusion"] == 0);
    for (const char* key : {"exposure_cell", "exposure_depth", "exposure_full_shade", "signal_rate"})
        CHECK_FALSE(plain.contains(key));
    // On: recorded with every default of their own keys.
    CHECK(read_growth(branching({{"exposure", true}, {"signal_diffusion", 3}}), &resolved).empty());
    CHECK(resolved["exposure"] == true);
    CHECK(resolved["exposure_cell"] == 1.0);
    CHECK(resolved["exposure_depth"] == 4);
    CHECK(resolved["exposure_full_shade"] == 32.0);
    CHECK(resolved["signal_diffusion"] == 3);
    CHECK(resolved["signal_rate"] == 0.5);
}

TEST_CASE("growth.signal_diffusion needs 8 outputs", "[growth][signals][config]") {
    GrowthParams params;
    params.mode = GrowthMode::branching;
    const Network seven(random_test_genome({21, 7}, 1));
    CHECK_NOTHROW(Grower(seven, params));
    params.exposure = true;
    CHECK_NOTHROW(Grower(seven, params));
    params.signal_diffusion = 1;
    CHECK_THROWS_WITH(Grower(seven, params), Catch::Contains("network.outputs") && Catch::Contains("signal_diffusion"));
    const Network eight(random_test_genome({24, 8}, 1));
    CHECK_NOTHROW(Grower(eight, params));
}

TEST_CASE("schema.json gives the signals' keys the reader's defaults and bounds", "[growth][signals][config]") {
    const json schema = load_json_file(MORPHOGEN_SOURCE_DIR "/configs/schema.json")["properties"]["growth"]["properties"];
    // Every key with both signals on, so each is read.
    const auto with = [](const std::string& key, const json& value) {
        json section = {{"mode", "branching"}, {"exposure", true}, {"signal_diffusion", 1}};
        section[key] = value;
        return section;
    };
    json resolved;
    REQUIRE(read_growth(with("exposure", true), &resolved).empty());
    CHECK(schema["exposure"]["default"] == false);
    CHECK(schema["signal_diffusion"]["default"] == 0);
    for (const char* key : {"exposure_cell", "exposure_depth", "exposure_full_shade", "signal_diffusion", "signal_rate"}) {
        INFO(key);
        const json& s = schema[key];
        if (std::string(key) != "signal_diffusion") CHECK(s["default"] == resolved[key]);
        const bool integer = s["type"] == "integer";
        const auto beyond = [&](double bound, double direction) {
            return integer ? json(static_cast<long long>(bound + direction))
                           : json(std::nextafter(bound, direction * std::numeric_limits<double>::infinity()));
        };
        if (s.contains("minimum")) {
            CHECK(read_growth(with(key, s["minimum"])).empty());
            CHECK_FALSE(read_growth(with(key, beyond(s["minimum"].get<double>(), -1))).empty());
        }
        if (s.contains("exclusiveMinimum")) {
            CHECK_FALSE(read_growth(with(key, s["exclusiveMinimum"])).empty());
            CHECK(read_growth(with(key, beyond(s["exclusiveMinimum"].get<double>(), 1))).empty());
        }
        REQUIRE(s.contains("maximum"));
        CHECK(read_growth(with(key, s["maximum"])).empty());
        CHECK_FALSE(read_growth(with(key, beyond(s["maximum"].get<double>(), 1))).empty());
    }
}
