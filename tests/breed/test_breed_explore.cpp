// "Explore around this one" (breed/explore.hpp): the pick of the most
// different good elites, and the search in a session, stopped or not,
// replayed to the same bytes.
#include "breed/breed_errors.hpp"
#include "breed/explore.hpp"
#include "breed/session.hpp"
#include "tests/breed/breed_test_support.hpp"
#include "tests/support/temp_dir.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <thread>

using namespace morphogen;
using namespace morphogen::testing;
using nlohmann::json;

namespace {
Individual elite(double fitness, double x, double y) {
    Individual i;
    i.fitness = fitness;
    i.descriptors = {x, y};
    return i;
}
}  // namespace

TEST_CASE("the pick: fittest first, then the farthest among the elites at or above the median", "[breed]") {
    const std::vector<DescriptorRange> ranges = {{"a", 0, 1, 10}, {"b", 0, 10, 10}};
    // Good (>= median 5): 0 (9, at the origin), 1 (5, near it), 2 (6, far in a), 3 (7, far in b).
    const std::vector<Individual> e = {elite(9, 0, 0), elite(5, 0.05, 0.5), elite(6, 1, 0), elite(7, 0, 10),
                                       elite(1, 0.5, 5), elite(2, 0.9, 9)};
    std::vector<const Individual*> elites;
    for (const Individual& i : e) elites.push_back(&i);
    CHECK(pick_different_good(elites, ranges, 3) == std::vector<std::size_t>{0, 2, 3});
    CHECK(pick_different_good(elites, ranges, 4) == std::vector<std::size_t>{0, 2, 3, 1});
    // More cells than good elites: the rest by fitness.
    CHECK(pick_different_good(elites, ranges, 6) == std::vector<std::size_t>{0, 2, 3, 1, 5, 4});
    CHECK(pick_different_good({}, ranges, 3).empty());
    // A plateau at the bottom: the median is the lowest fitness, and only
    // the elites above it are good.
    const std::vector<Individual> p = {elite(0, 0, 0), elite(0, 1, 10), elite(0, 0.5, 5), elite(3, 0.1, 1),
                                       elite(5, 0.2, 2)};
    std::vector<const Individual*> plateau;
    for (const Individual& i : p) plateau.push_back(&i);
    CHECK(pick_different_good(plateau, ranges, 3) == std::vector<std::size_t>{4, 3, 0});
}

TEST_CASE("explore runs in the background, reports progress, and its elites become the next grid", "[breed]") {
    TempDir tmp("breed");
    {
        const auto s = BreedSession::create(tmp.path / "a", tiny_breed_config(), {});
        // A parent the search can place (a valid fitness and descriptors).
        std::string parent;
        const json first = s->state_json();
        for (const json& p : first.at("grid"))
            if (parent.empty() && p.at("fitness").is_number() && p.at("measures").contains("spread")) parent = p.at("id").get<std::string>();
        REQUIRE(!parent.empty());
        s->start_explore({parent}, 60);
        const json during = s->state_json();
        CHECK(during.at("search").at("total") == 60);
        s->wait_explore();
        const json after = s->state_json();
        CHECK(after.at("search").at("running") == false);
        CHECK(after.at("search").at("done") == 60);
        CHECK(after.at("generation") == 1);
        CHECK(after.at("chosen") == json({parent}));
        REQUIRE(after.at("grid").size() == kBreedGridSize);
        CHECK(after.at("grid")[0].at("id") == parent);
        for (std::size_t i = 1; i < kBreedGridSize; ++i) CHECK(after.at("grid")[i].at("parents") == json({parent}));
        CHECK(after.at("can_undo") == true);
        s->undo();
        s->redo();
    }
    BreedSession::replay(tmp.path / "a", tmp.path / "b");
    CHECK(session_difference(tmp.path / "a", tmp.path / "b") == "");
}

TEST_CASE("a search refuses other choices while it runs; stopped, it gives what it found so far and replays to the same bytes", "[breed]") {
    TempDir tmp("breed");
    {
        const auto s = BreedSession::create(tmp.path / "a", tiny_breed_config(), {});
        std::vector<std::string> parents;
        const json first = s->state_json();
        for (const json& p : first.at("grid"))
            if (parents.size() < 2 && p.at("fitness").is_number() && p.at("measures").contains("spread"))
                parents.push_back(p.at("id"));
        REQUIRE(parents.size() == 2);
        s->start_explore(parents, kMaxExploreBirths);
        // Nothing else while it runs: its 100,000 births take minutes, so it
        // is still running here on any machine.
        int refused = 0;
        try {
            s->breed({parents[0]}, 0.5);
        } catch (const BreedRequestError& e) {
            refused = e.status;
        }
        CHECK(refused == 409);
        while (s->state_json().at("search").at("done").get<int>() < 5)
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        s->stop_explore();
        s->wait_explore();
        const json after = s->state_json();
        const auto done = after.at("search").at("done").get<int>();
        CHECK(done >= 5);
        CHECK(done < kMaxExploreBirths);
        CHECK(after.at("generation") == 1);
        CHECK(after.at("grid")[1].at("id") == parents[1]);
        int status = 0;
        try {
            s->stop_explore();
        } catch (const BreedRequestError& e) {
            status = e.status;
        }
        CHECK(status == 409);
    }
    BreedSession::replay(tmp.path / "a", tmp.path / "b");
    CHECK(session_difference(tmp.path / "a", tmp.path / "b") == "");
}
