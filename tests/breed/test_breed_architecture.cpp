// Breeding toward trees (docs/breed.md): the architecture measures in the
// session's state, the explore search along them (collapsed births dropped,
// the most tree-like first), and its line in choices.jsonl, old lines
// without "along" replaying as before.
#include "breed/explore.hpp"
#include "breed/session.hpp"
#include "core/growth/genome_grower.hpp"
#include "fitness/architecture/architecture.hpp"
#include "fitness/mesh_stats.hpp"
#include "tests/breed/breed_test_support.hpp"
#include "tests/support/temp_dir.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

using namespace morphogen;
using namespace morphogen::testing;
using nlohmann::json;

namespace {

Individual elite(double fitness, double limbs, double fork, double tips) {
    Individual i;
    i.fitness = fitness;
    i.descriptors = {limbs, fork, tips};
    return i;
}

// The first plant of a state's grid with a valid fitness.
std::string valid_plant(const json& state) {
    for (const json& p : state.at("grid"))
        if (p.at("fitness").is_number()) return p.at("id");
    return "";
}

}  // namespace

TEST_CASE("the state carries each plant's tips, limbs and first fork, as the architecture measures give them", "[breed]") {
    TempDir tmp("breed");
    const ExperimentConfig config = tiny_breed_config();
    const auto s = BreedSession::create(tmp.path / "a", config, {});
    const json state = s->state_json();
    const GenomeGrower grower(config.network, config.growth);
    for (const json& p : state.at("grid")) {
        const json& m = p.at("measures");
        INFO(p.at("id") << " " << m.dump());
        REQUIRE(m.contains("tips"));
        REQUIRE(m.contains("limbs"));
        REQUIRE(m.contains("first_fork_height"));
        REQUIRE(m.contains("first_fork"));
        // The genome the session saved, grown and measured as `score` does.
        const json genome = json::parse(read_text(tmp.path / "a" / "genomes" / (p.at("id").get<std::string>() + ".genome.json")));
        const GrowthState grown = grower.grow(genome.at("params").get<std::vector<double>>());
        const Architecture a = measure_architecture(grown.mesh.view());
        CHECK(m.at("tips") == a.tips);
        CHECK(m.at("limbs") == a.limbs.size());
        CHECK(m.at("first_fork_height").get<double>() == Approx(a.first_fork_height).epsilon(1e-12));
        double zmin = grown.mesh.position(0).z(), zmax = zmin;
        for (const Vec3& v : grown.mesh.positions()) {
            zmin = std::min(zmin, v.z());
            zmax = std::max(zmax, v.z());
        }
        CHECK(m.at("first_fork").get<double>() == Approx(a.first_fork_height / (zmax - zmin)).epsilon(1e-12));
        CHECK(m.at("first_fork").get<double>() <= 1.0 + 1e-12);
    }
}

TEST_CASE("the tree-like pick: most limbs, then the lowest fork, for half the cells; the rest spread", "[breed]") {
    const std::vector<DescriptorRange> ranges = {{"limbs", 0, 10, 10}, {"first_fork", 0, 1, 10}, {"tips", 0, 20, 10}};
    const std::vector<Individual> e = {elite(50, 0, 1.0, 1), elite(10, 2, 0.5, 4), elite(5, 2, 0.3, 6),
                                       elite(1, 3, 0.8, 8),  elite(30, 0, 0.2, 2), elite(20, 1, 0.1, 20)};
    std::vector<const Individual*> elites;
    for (const Individual& i : e) elites.push_back(&i);
    // Half of 4: the 3-limbed, then the lower-forked 2-limbed; then the one
    // farthest from both (20 tips), then the farthest from all three (the
    // fittest, unbranched plant): not the fitter plants first.
    CHECK(pick_tree_like(elites, ranges, 4) == std::vector<std::size_t>{3, 2, 5, 0});
    CHECK(pick_tree_like(elites, ranges, 1) == std::vector<std::size_t>{3});
    CHECK(pick_tree_like(elites, ranges, 10).size() == 6);
    CHECK(pick_tree_like({}, ranges, 3).empty());
    // Equal limbs and fork: the fitter first.
    const std::vector<Individual> tie = {elite(1, 2, 0.5, 4), elite(9, 2, 0.5, 6)};
    std::vector<const Individual*> tied = {&tie[0], &tie[1]};
    CHECK(pick_tree_like(tied, ranges, 1) == std::vector<std::size_t>{1});
}

TEST_CASE("explore along the architecture drops births that collapse below half the parent's height", "[breed]") {
    const ExperimentConfig config = tiny_breed_config();
    const ExploreSettings settings = explore_settings(config, kBreedGridSize, ExploreAlong::architecture);
    REQUIRE(settings.descriptors.size() == 3);
    const PlantGrowth growth(config, {});
    TempDir tmp("breed");
    const auto s = BreedSession::create(tmp.path / "a", config, {});
    const json state = s->state_json();
    // The tallest valid plant of the first grid seeds the search.
    json parent;
    for (const json& p : state.at("grid"))
        if (p.at("fitness").is_number() &&
            (parent.is_null() || p.at("measures").at("height") > parent.at("measures").at("height")))
            parent = p;
    REQUIRE(!parent.is_null());
    const json genome =
        json::parse(read_text(tmp.path / "a" / "genomes" / (parent.at("id").get<std::string>() + ".genome.json")));
    const std::vector<double> params = genome.at("params").get<std::vector<double>>();
    const double height = parent.at("measures").at("height").get<double>();
    const Evaluation seed = growth.evaluate_architecture(params, 0.0);
    REQUIRE(seed.valid);
    CHECK(seed.descriptors == std::vector<double>{parent.at("measures").at("limbs"), parent.at("measures").at("first_fork"),
                                                  parent.at("measures").at("tips")});
    // A plant below the bar is refused as collapsed.
    const Evaluation under = growth.evaluate_architecture(params, height * 1.01);
    CHECK(!under.valid);
    CHECK(under.error.find("collapsed") != std::string::npos);

    ExploreSettings along = settings;
    along.min_height = kCollapsedHeight * height;
    ExploreSearch search(growth, along, {{params, seed.score, seed.descriptors}}, 11, 80, kBreedGridSize - 1);
    const ExploreResult result = search.run();
    CHECK(result.done == 80);
    REQUIRE(!result.picked.empty());
    for (const std::vector<double>& g : result.picked) {
        GrowthWorkspace workspace;
        const GrowthState grown = growth.grower().grow(g, workspace);
        CHECK(mesh_stats(grown.mesh.view()).height >= kCollapsedHeight * height);
        CHECK(growth.evaluate_architecture(g, 0.0).valid);
    }
}

TEST_CASE("an explore line records \"along\"; one without it replays along the config's descriptors", "[breed]") {
    TempDir tmp("breed");
    json descriptors_grid, architecture_grid;
    {
        const auto s = BreedSession::create(tmp.path / "a", tiny_breed_config(), {});
        const std::string parent = valid_plant(s->state_json());
        REQUIRE(!parent.empty());
        s->start_explore({parent}, 40, ExploreAlong::descriptors);
        s->wait_explore();
        descriptors_grid = s->state_json().at("grid");
        s->undo();
        s->start_explore({parent}, 40);  // the default: along the architecture
        s->wait_explore();
        architecture_grid = s->state_json().at("grid");
    }
    const std::string log = read_text(tmp.path / "a" / "choices.jsonl");
    CHECK(log.find("\"along\":\"descriptors\"") != std::string::npos);
    CHECK(log.find("\"along\":\"architecture\"") != std::string::npos);
    CHECK(descriptors_grid != architecture_grid);
    BreedSession::replay(tmp.path / "a", tmp.path / "b");
    CHECK(session_difference(tmp.path / "a", tmp.path / "b") == "");

    // A session written before "along": its explore line has none.
    std::filesystem::create_directories(tmp.path / "old");
    std::filesystem::copy(tmp.path / "a" / "config.json", tmp.path / "old" / "config.json");
    std::istringstream lines(log);
    std::ofstream old(tmp.path / "old" / "choices.jsonl");
    std::string line;
    for (int kept = 0; kept < 2 && std::getline(lines, line); ++kept) {  // start, then the first explore
        json choice = json::parse(line);
        choice.erase("along");
        old << choice.dump() << "\n";
    }
    old.close();
    const auto replayed = BreedSession::replay(tmp.path / "old", tmp.path / "c");
    CHECK(replayed->state_json().at("grid") == descriptors_grid);
}
