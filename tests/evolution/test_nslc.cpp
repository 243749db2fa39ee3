// Novelty search with local competition (docs/algorithm.md §14): novelty,
// local competition, fronts and ranking on a hand-made population; the
// search's state the same for any thread count and after a round trip
// through its checkpoint JSON; the archive; invalid children; bad states.
#include "evolution/novelty/novelty.hpp"
#include "evolution/novelty/nslc.hpp"
#include "evolution/novelty/nslc_state_json.hpp"
#include "tests/evolution/breeding.hpp"
#include "tests/evolution/toy_problems.hpp"

#include <catch2/catch.hpp>

#include <set>

using namespace morphogen;
using morphogen::test::DescribedSphereProblem;

namespace {
// One descriptor x in [0, 10]: the distance of two points is |x_a - x_b| / 10.
const std::vector<DescriptorRange> kNslcLine{{"x", 0.0, 10.0, 1}};

struct MadePoint {
    std::uint64_t id;
    double fitness;
    std::vector<double> x;
    BehaviourPoint point() const { return {id, fitness, x}; }
};

std::vector<BehaviourPoint> made_points(const std::vector<MadePoint>& made) {
    std::vector<BehaviourPoint> out;
    for (const MadePoint& m : made) out.push_back(m.point());
    return out;
}

// A (fitness 1, x 0), B (2, x 1), C (3, x 3), D (4, x 6); the archive holds E (5, x 10).
const std::vector<MadePoint> kNslcMembers{{0, 1.0, {0.0}}, {1, 2.0, {1.0}}, {2, 3.0, {3.0}}, {3, 4.0, {6.0}}};
const std::vector<MadePoint> kNslcArchive{{10, 5.0, {10.0}}};

GaParams nslc_params() {
    GaParams p;
    p.population = 16;
    p.tournament = 3;
    p.crossover = 0.5;
    p.mutation_rate = 0.3;
    p.schedule = ScheduleKind::batch;
    p.batch = 5;
    return p;
}

NoveltyParams nslc_novelty() { return {4, 12, 0.25}; }

const std::vector<DescriptorRange> kNslcPlane{{"x", -2.0, 2.0, 1}, {"y", -2.0, 2.0, 1}};

std::string dump_nslc(const NslcState& state) { return nslc_state_to_json(state).dump(); }

std::string run_nslc(Problem& problem, int threads, std::uint64_t births, NslcState from = {}) {
    Nslc search(nslc_params(), nslc_novelty(), kNslcPlane, 7, problem, std::move(from));
    test::breed_until(search, problem, 16, 5, threads, births);
    return dump_nslc(search.state());
}
}  // namespace

TEST_CASE("novelty and local competition of a hand-made population", "[evolution][nslc]") {
    // k = 2. A: B 0.1, C 0.3 -> novelty 0.2, neither lower. B: A 0.1, C 0.2 ->
    // 0.15, A lower. C: B 0.2, then A and D both at 0.3: A by its lower id ->
    // 0.25, both lower (D would not be). D: C 0.3, E 0.4 -> 0.35, C lower.
    const std::vector<NoveltyScore> s = novelty_scores(made_points(kNslcMembers), made_points(kNslcArchive), kNslcLine, 2);
    REQUIRE(s.size() == 4);
    CHECK(s[0].novelty == Approx(0.2));
    CHECK(s[0].competition == 0.0);
    CHECK(s[1].novelty == Approx(0.15));
    CHECK(s[1].competition == 0.5);
    CHECK(s[2].novelty == Approx(0.25));
    CHECK(s[2].competition == 1.0);
    CHECK(s[3].novelty == Approx(0.35));
    CHECK(s[3].competition == 0.5);

    // k beyond the neighbours: all four count. A: (0.1 + 0.3 + 0.6 + 1.0) / 4.
    const std::vector<NoveltyScore> all = novelty_scores(made_points(kNslcMembers), made_points(kNslcArchive), kNslcLine, 10);
    CHECK(all[0].novelty == Approx(0.5));
    CHECK(all[3].competition == 0.75);  // D (4) is fitter than A, B, C, not E

    // A member that is also in the archive counts once.
    std::vector<MadePoint> archive = kNslcArchive;
    archive.push_back(kNslcMembers[1]);
    const std::vector<NoveltyScore> again = novelty_scores(made_points(kNslcMembers), made_points(archive), kNslcLine, 2);
    for (std::size_t i = 0; i < s.size(); ++i) {
        CHECK(again[i].novelty == s[i].novelty);
        CHECK(again[i].competition == s[i].competition);
    }
    // Alone: no neighbour, both 0.
    const std::vector<NoveltyScore> alone = novelty_scores(made_points({kNslcMembers[0]}), {}, kNslcLine, 15);
    CHECK(alone[0].novelty == 0.0);
    CHECK(alone[0].competition == 0.0);
    // Distances are in units of each range.
    const std::vector<DescriptorRange> two{{"a", 0.0, 10.0, 1}, {"b", 0.0, 100.0, 1}};
    const std::vector<double> p{0.0, 0.0}, q{3.0, 40.0};
    CHECK(behaviour_distance(p, q, two) == Approx(0.5));  // sqrt(0.3^2 + 0.4^2)
}

TEST_CASE("Pareto fronts and the ranking of novelty search", "[evolution][nslc]") {
    // C (0.25, 1) and D (0.35, 0.5) dominate A (0.2, 0) and B (0.15, 0.5);
    // neither of each pair dominates the other.
    const std::vector<NoveltyScore> s = ranked_scores(made_points(kNslcMembers), made_points(kNslcArchive), kNslcLine, 2);
    CHECK(s[0].front == 1);
    CHECK(s[1].front == 1);
    CHECK(s[2].front == 0);
    CHECK(s[3].front == 0);
    // The order: front, then novelty: D, C, A, B.
    const auto above = [&](std::size_t a, std::size_t b) { return novelty_ranks_above(s[a], a, s[b], b); };
    CHECK(above(3, 2));
    CHECK(above(2, 0));
    CHECK(above(0, 1));
    CHECK_FALSE(above(1, 0));
    // A chain of three: fronts 0, 1, 2; equal scores share a front; ties go to the younger.
    std::vector<NoveltyScore> chain{{0.1, 0.1, 9}, {0.3, 0.3, 9}, {0.2, 0.2, 9}, {0.2, 0.2, 9}};
    pareto_fronts(chain);
    CHECK(chain[1].front == 0);
    CHECK(chain[2].front == 1);
    CHECK(chain[3].front == 1);
    CHECK(chain[0].front == 2);
    CHECK(novelty_ranks_above(chain[3], 3, chain[2], 2));
    CHECK_FALSE(novelty_ranks_above(chain[2], 2, chain[3], 3));
}

TEST_CASE("an NSLC search is the same for any thread count and after a round trip of its state",
          "[evolution][nslc][determinism]") {
    DescribedSphereProblem problem(6, 2, true);  // some children throw or have a NaN descriptor
    const std::string one = run_nslc(problem, 1, 160);
    CHECK(run_nslc(problem, 4, 160) == one);

    // Stopped at 80 births, its state written and read back, continued to 160.
    Nslc half(nslc_params(), nslc_novelty(), kNslcPlane, 7, problem);
    test::breed_until(half, problem, 16, 5, 2, 80);
    const nlohmann::json stored = nslc_state_to_json(half.state());
    NslcState read = nslc_state_from_json(stored, nslc_params(), nslc_novelty(), kNslcPlane, 6);
    CHECK(dump_nslc(read) == dump_nslc(half.state()));
    CHECK(run_nslc(problem, 3, 160, std::move(read)) == one);
    // Another seed is another run.
    Nslc other(nslc_params(), nslc_novelty(), kNslcPlane, 8, problem);
    test::breed_until(other, problem, 16, 5, 1, 160);
    CHECK(dump_nslc(other.state()) != one);
}

TEST_CASE("the novelty archive grows by its rate and keeps its newest points", "[evolution][nslc]") {
    DescribedSphereProblem problem(6, 2, true);
    Nslc search(nslc_params(), nslc_novelty(), kNslcPlane, 7, problem);
    std::size_t invalid = 0, archived = 0;
    std::uint64_t last_archived = 0;
    test::breed_until(search, problem, 16, 5, 2, 200, [&](const test::Bred& bred) {
        const NslcState& s = search.state();
        if (!bred.child.valid()) {
            ++invalid;
            // An invalid child enters neither the population nor the archive.
            for (const Individual& member : s.population) CHECK(member.id != bred.child.id);
            CHECK((s.archive.empty() || s.archive.back().id != bred.child.id));
            return;
        }
        if (!s.archive.empty() && s.archive.back().id == bred.child.id) {
            ++archived;
            last_archived = bred.child.id;
        }
        CHECK(s.population.size() <= 16);
        CHECK(s.archive.size() <= 12);
        CHECK(search.scores().size() == s.population.size());
    });
    const NslcState& s = search.state();
    CHECK(invalid > 0);
    CHECK(archived > 12);  // about a quarter of the valid births entered; only the newest 12 stay
    REQUIRE(s.archive.size() == 12);
    CHECK(s.archive.back().id == last_archived);
    for (std::size_t i = 1; i < s.archive.size(); ++i) CHECK(s.archive[i - 1].id < s.archive[i].id);
    std::set<std::uint64_t> ids;
    for (const Individual& member : s.population) {
        CHECK(member.valid());
        CHECK(member.descriptors.size() == 2);
        ids.insert(member.id);
    }
    CHECK(ids.size() == 16);
    CHECK(s.best);
}

TEST_CASE("a stored NSLC state that contradicts itself is refused", "[evolution][nslc]") {
    DescribedSphereProblem problem(6, 2);
    Nslc search(nslc_params(), nslc_novelty(), kNslcPlane, 7, problem);
    test::breed_until(search, problem, 16, 5, 1, 64);
    const nlohmann::json good = nslc_state_to_json(search.state());
    REQUIRE(good["archive"].size() > 1);
    const auto refused = [&](nlohmann::json bad, const std::string& why) {
        CHECK_THROWS_WITH(nslc_state_from_json(bad, nslc_params(), nslc_novelty(), kNslcPlane, 6), Catch::Contains(why));
    };
    nlohmann::json bad = good;
    bad["population"][0]["fitness"] = nullptr;
    refused(bad, "nslc.population[0].fitness: an invalid birth never enters the search");
    bad = good;
    bad["population"][1]["descriptors"] = {0.5};
    refused(bad, "nslc.population[1].descriptors: 1 values, the run has 2 descriptors");
    bad = good;
    std::swap(bad["archive"][0], bad["archive"][1]);
    refused(bad, "the archive is in birth order");
    bad = good;
    bad["archive"][0]["id"] = std::uint64_t{64};
    refused(bad, "nslc.archive[0].id: not below the birth counter");
    NoveltyParams smaller = nslc_novelty();
    smaller.archive = 1;
    CHECK_THROWS_WITH(nslc_state_from_json(good, nslc_params(), smaller, kNslcPlane, 6),
                      Catch::Contains("more than novelty_archive 1"));
    CHECK_THROWS_WITH(Nslc(nslc_params(), {0, 10, 0.1}, kNslcPlane, 7, problem), Catch::Contains("novelty_k >= 1"));
    CHECK_THROWS_WITH(Nslc(nslc_params(), nslc_novelty(), {}, 7, problem), Catch::Contains("at least one descriptor"));
}
