// The CMA emitters (sep_cma.hpp, full_cma.hpp, cma_emitter.hpp, docs/algorithm.md
// §9.9): separable and full CMA-ES against known cases, the textbook rate on a
// sphere and a rotated ellipsoid only the full model can learn, the
// CMA emitter alone, the same run for any threads, exact resume
// through the checkpoint's JSON and genome blob, and damaged states refused.
#include "evolution/emitters/cma/cma_emitter.hpp"
#include "evolution/emitters/cma/cma_rates.hpp"
#include "evolution/emitters/emitter_state_json.hpp"
#include "evolution/emitters/cma/full_cma.hpp"
#include "evolution/emitters/gaussian_emitter.hpp"
#include "evolution/schedulers/map_elites.hpp"
#include "evolution/schedulers/map_elites_state_json.hpp"
#include "evolution/execution/pipeline.hpp"
#include "evolution/emitters/cma/sep_cma.hpp"
#include "evolution/execution/thread_evaluator.hpp"
#include "tests/evolution/search_fixtures.hpp"
#include "tests/evolution/toy_problems.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

using namespace morphogen;
using namespace morphogen::test;
using morphogen::test::DescribedSphereProblem;

namespace {
double sphere(const std::vector<double>& x) {
    double s = 0.0;
    for (double v : x) s += v * v;
    return s;
}

CmaSettings cma_settings(CmaRanking ranking, CmaCovariance covariance = CmaCovariance::diagonal) {
    CmaSettings s;
    s.ranking = ranking;
    s.covariance = covariance;
    s.sigma0 = 0.3;
    if (ranking == CmaRanking::threshold) {
        s.parents = CmaParents::mu;
        s.restart = CmaRestart::basic;
        s.thresholds = {0.1, -30.0};
    }
    return s;
}

constexpr CmaRanking cma_me = CmaRanking::improvement, cma_mae = CmaRanking::threshold;

EmitterSpec cma(CmaRanking ranking, double share = 1.0, CmaCovariance covariance = CmaCovariance::diagonal) {
    return {share, std::make_shared<CmaEmitter>(ParentSelection::uniform, cma_settings(ranking, covariance))};
}

const CmaEmitter& cma_of(const EmitterSlot& slot) { return dynamic_cast<const CmaEmitter&>(*slot); }


MapElitesParams params_with(std::vector<EmitterSpec> emitters) {
    MapElitesParams p;
    p.population = 24;
    p.mutation_rate = 0.3;
    p.emitters = std::move(emitters);
    return p;
}

// The state as a checkpoint stores it: JSON plus the genome blob.
struct Stored {
    nlohmann::json document;
    std::string genomes;
    std::uint64_t count = 0;
};
Stored store(const MapElitesState& state) {
    GenomeBlobWriter writer;
    nlohmann::json document = map_elites_state_to_json(state, &writer);
    return {std::move(document), writer.bytes(), writer.count()};
}
MapElitesState load(const Stored& stored, const MapElitesParams& params, std::size_t dimension) {
    GenomeBlobReader reader(stored.genomes, stored.count, dimension);
    return map_elites_state_from_json(stored.document, ArchiveKind::grid, empty_state().archive.ranges(), 64,
                                      static_cast<std::uint64_t>(params.population), dimension, params.emitters, &reader);
}
}  // namespace

TEST_CASE("separable CMA-ES: one parent moves the mean onto it; a far parent's step is clipped", "[evolution][cma]") {
    SepCmaState s = sep_cma_start({1.0, -2.0, 0.5}, 0.5);
    const std::vector<double> x{1.3, -2.2, 0.9};
    const std::vector<const std::vector<double>*> parents{&x};
    sep_cma_update(s, parents);
    for (std::size_t i = 0; i < 3; ++i) CHECK(s.mean[i] == Approx(x[i]).epsilon(1e-14));
    // mu = 1: mu_eff = 1, c_sigma = 3 / (n + 6), p_sigma = sqrt(c_sigma (2 - c_sigma)) y with y = (x - m) / sigma.
    const double cs = 3.0 / 9.0, rate = std::sqrt(cs * (2.0 - cs));
    CHECK(s.path_sigma[0] == Approx(rate * 0.3 / 0.5));
    CHECK(s.path_sigma[1] == Approx(rate * -0.2 / 0.5));
    CHECK(s.path_sigma[2] == Approx(rate * 0.4 / 0.5));
    CHECK(s.updates == 1);

    // A parent 1000 sigma away (a child of an older distribution): its step
    // is cut to sqrt(n) + 2n / (n + 2) in Mahalanobis length.
    SepCmaState far = sep_cma_start({0.0, 0.0, 0.0}, 2.0);
    const std::vector<double> away{2000.0, 0.0, 0.0};
    const std::vector<const std::vector<double>*> one{&away};
    sep_cma_update(far, one);
    CHECK(far.mean[0] == Approx(2.0 * (std::sqrt(3.0) + 6.0 / 5.0)));
    CHECK(far.mean[1] == 0.0);
    CHECK_THROWS_AS(sep_cma_update(far, std::span<const std::vector<double>* const>{}), std::invalid_argument);
}

TEST_CASE("separable CMA-ES converges on a 10-D sphere at the textbook rate", "[evolution][cma]") {
    // lambda = 4 + floor(3 ln n) = 10, mu = 5, from m = (3, ..., 3), sigma = 1.
    const std::size_t n = 10, lambda = 10, mu = 5;
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        SepCmaState s = sep_cma_start(std::vector<double>(n, 3.0), 1.0);
        std::vector<double> log_f;
        for (std::uint64_t it = 0; it < 300; ++it) {
            std::vector<std::vector<double>> xs;
            for (std::size_t k = 0; k < lambda; ++k) {
                RandomStream stream(seed, it * lambda + k);
                xs.push_back(sep_cma_sample(s, stream));
            }
            std::vector<std::size_t> order(lambda);
            std::iota(order.begin(), order.end(), 0);
            std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return sphere(xs[a]) < sphere(xs[b]); });
            std::vector<const std::vector<double>*> parents;
            for (std::size_t k = 0; k < mu; ++k) parents.push_back(&xs[order[k]]);
            sep_cma_update(s, parents);
            log_f.push_back(std::log10(sphere(s.mean)));
        }
        // Linear convergence: from iteration 50 to 150 the mean's f falls by
        // a steady factor per iteration. CMA-ES on the 10-D sphere with
        // lambda = 10 needs about 1,500 evaluations for 12 decades of f
        // (Hansen's tutorial), 0.08 decades per iteration.
        const double per_iteration = (log_f[50] - log_f[150]) / 100.0;
        INFO("seed " << seed << ": " << per_iteration << " decades per iteration");
        CHECK(per_iteration > 0.06);
        CHECK(per_iteration < 0.12);
        CHECK(log_f[150] < -9.0);
        // An isotropic problem keeps C isotropic.
        const auto [low, high] = std::minmax_element(s.variances.begin(), s.variances.end());
        CHECK(*high / *low < 10.0);
    }
}

TEST_CASE("full CMA-ES: one parent moves the mean onto it; C stays symmetric; a far parent's step is clipped",
          "[evolution][cma]") {
    FullCmaState s = full_cma_start({1.0, -2.0, 0.5}, 0.5);
    const std::vector<double> x{1.3, -2.2, 0.9};
    const std::vector<const std::vector<double>*> parents{&x};
    full_cma_update(s, parents);
    for (std::size_t i = 0; i < 3; ++i) CHECK(s.mean[i] == Approx(x[i]).epsilon(1e-14));
    // From C = I the paths are those of the separable model (same rates).
    const double cs = 3.0 / 9.0, rate = std::sqrt(cs * (2.0 - cs));
    CHECK(s.path_sigma[0] == Approx(rate * 0.3 / 0.5));
    CHECK(s.path_sigma[2] == Approx(rate * 0.4 / 0.5));
    // The rank-one and rank-mu terms put y y^T into C: an off-diagonal entry
    // appears, exactly symmetric, and B diag(scales^2) B^T gives C back.
    CHECK(s.covariance[0 * 3 + 2] != 0.0);
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            CHECK(s.covariance[i * 3 + j] == s.covariance[j * 3 + i]);
            double back = 0.0;
            for (std::size_t k = 0; k < 3; ++k) back += s.basis[i * 3 + k] * s.scales[k] * s.scales[k] * s.basis[j * 3 + k];
            CHECK(back == Approx(s.covariance[i * 3 + j]).margin(1e-14));
        }
    FullCmaState far = full_cma_start({0.0, 0.0, 0.0}, 2.0);
    const std::vector<double> away{2000.0, 0.0, 0.0};
    const std::vector<const std::vector<double>*> one{&away};
    full_cma_update(far, one);
    CHECK(far.mean[0] == Approx(2.0 * (std::sqrt(3.0) + 6.0 / 5.0)));
    CHECK_THROWS_AS(full_cma_update(far, std::span<const std::vector<double>* const>{}), std::invalid_argument);
    // Damaged matrices are refused.
    FullCmaState bad = full_cma_start({0.0, 0.0}, 1.0);
    bad.covariance = {1.0, 2.0, 2.0, 1.0};  // eigenvalues 3 and -1
    CHECK_FALSE(full_cma_decompose(bad));
    bad.covariance = {1.0, 0.5, 0.25, 1.0};
    CHECK_FALSE(full_cma_decompose(bad));
    bad.covariance = {2.0, 0.5, 0.5, 1.0};
    CHECK(full_cma_decompose(bad));
}

namespace {
// A rotated ellipsoid: f(x) = sum_i 10^(4 i / (n - 1)) (Q x)_i^2, Q the
// Householder reflection through (1, ..., 1): every axis of the ellipsoid is
// diagonal to the coordinates, so a diagonal C cannot follow it.
double rotated_ellipsoid(const std::vector<double>& x) {
    const std::size_t n = x.size();
    double dot = 0.0;
    for (double v : x) dot += v;
    double f = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double qx = x[i] - 2.0 * dot / static_cast<double>(n);
        f += std::pow(10.0, 4.0 * static_cast<double>(i) / static_cast<double>(n - 1)) * qx * qx;
    }
    return f;
}

// Iterations of CMA-ES (lambda = 4 + floor(3 ln n), mu = lambda / 2) until
// f(mean) < 1e-10, at most `limit`.
template <class State, class Sample, class Update>
std::uint64_t iterations_to_solve(State s, Sample sample, Update update, std::uint64_t seed, std::uint64_t limit) {
    const std::size_t n = s.mean.size(), lambda = 4 + static_cast<std::size_t>(3.0 * std::log(static_cast<double>(n)));
    for (std::uint64_t it = 0; it < limit; ++it) {
        std::vector<std::vector<double>> xs;
        for (std::size_t k = 0; k < lambda; ++k) {
            RandomStream stream(seed, it * lambda + k);
            xs.push_back(sample(s, stream));
        }
        std::vector<std::size_t> order(lambda);
        std::iota(order.begin(), order.end(), 0);
        std::stable_sort(order.begin(), order.end(),
                         [&](auto a, auto b) { return rotated_ellipsoid(xs[a]) < rotated_ellipsoid(xs[b]); });
        std::vector<const std::vector<double>*> parents;
        for (std::size_t k = 0; k < lambda / 2; ++k) parents.push_back(&xs[order[k]]);
        update(s, parents);
        if (rotated_ellipsoid(s.mean) < 1e-10) return it + 1;
    }
    return limit;
}
}  // namespace

TEST_CASE("full CMA-ES learns a rotated ellipsoid the separable model cannot", "[evolution][cma]") {
    const std::size_t n = 8;
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        const std::uint64_t full = iterations_to_solve(full_cma_start(std::vector<double>(n, 1.0), 0.5), full_cma_sample,
                                                       full_cma_update, seed, 3000);
        const std::uint64_t separable = iterations_to_solve(sep_cma_start(std::vector<double>(n, 1.0), 0.5),
                                                            sep_cma_sample, sep_cma_update, seed, 3000);
        INFO("seed " << seed << ": full " << full << " iterations, separable " << separable);
        // Measured: 294-312 iterations for the full model; the separable one
        // is still above 1e-10 after 3,000.
        CHECK(full < 500);
        CHECK(separable > 2000);
    }
}

TEST_CASE("a CMA emitter alone: random until started, ranks what the archive told, restarts", "[evolution][cma]") {
    const std::vector<Block> blocks{{0, 2}, {2, 2}};
    const BirthRules rules{4, 2.0, 0.3, 0.05, 0.3, {}};
    const ParentPool none({});
    CmaSettings settings = cma_settings(cma_me);
    settings.parents = CmaParents::filter;
    settings.restart = CmaRestart::no_improvement;
    CmaEmitter emitter(ParentSelection::uniform, settings);
    const EmitterSource source{rules, blocks, 4, 9, none};
    // Not started: the birth is a random genome, and children are not collected.
    CHECK(emitter.conceive(source, 7).params == conceive_birth(rules, blocks, 4, 9, 7, {}).params);
    Individual elite;
    elite.id = 2;
    elite.params = {1.0, 2.0, 3.0, 4.0};
    elite.fitness = 1.0;
    const ElitePicker nothing = [](ParentSelection) -> const Individual* { return nullptr; };
    const ElitePicker picks_elite = [&](ParentSelection) -> const Individual* { return &elite; };
    emitter.told(elite, {}, false, nothing);
    CHECK(emitter.state().children.empty());
    emitter.generation_ended(nothing);  // an empty archive: still not started
    CHECK_FALSE(emitter.state().started);
    emitter.generation_ended(picks_elite);
    REQUIRE(emitter.state().started);
    CHECK(emitter.state().cma.mean == elite.params);
    CHECK(emitter.state().origin == 2u);
    // Started: samples of N(mean, sigma0^2 I) from the birth's stream, parent1 the origin.
    const Individual child = emitter.conceive(source, 8);
    RandomStream stream(9, 8);
    CHECK(child.params == sep_cma_sample(emitter.state().cma, stream));
    CHECK(child.parent1 == 2u);
    // The ranks: a new cell (2), an improvement (1), neither (0), invalid.
    Individual scored = child;
    scored.fitness = 3.0;
    Archive::Insertion filled{Archive::Placement::filled, 5, std::nullopt, 0.0};
    Archive::Insertion improved{Archive::Placement::replaced, 5, 2.5, 0.0};
    Archive::Insertion worse{Archive::Placement::rejected, 5, 4.0, 0.0};
    CHECK(rank_cma_child(CmaRanking::improvement, scored, filled).status == 2);
    CHECK(rank_cma_child(CmaRanking::improvement, scored, filled).value == 3.0);
    CHECK(rank_cma_child(CmaRanking::improvement, scored, improved).status == 1);
    CHECK(rank_cma_child(CmaRanking::improvement, scored, improved).value == 0.5);
    CHECK(rank_cma_child(CmaRanking::improvement, scored, worse).status == 0);
    Archive::Insertion below_threshold{Archive::Placement::rejected, 5, 4.0, 2.0};
    CHECK(rank_cma_child(CmaRanking::threshold, scored, below_threshold).status == 1);
    CHECK(rank_cma_child(CmaRanking::threshold, scored, below_threshold).value == 1.0);
    Individual invalid = child;
    invalid.fitness = invalid_fitness;
    CHECK(rank_cma_child(CmaRanking::improvement, invalid, {}).value == invalid_fitness);
    CHECK(rank_cma_child(CmaRanking::improvement, invalid, {}).status == 0);
    // An iteration of children that improve nothing ends in a restart (no_improvement).
    emitter.told(scored, worse, false, picks_elite);
    CHECK(emitter.state().children.size() == 1);
    elite.params = {0.0, 0.0, 0.0, 0.0};
    emitter.told(scored, worse, /*last=*/true, picks_elite);
    CHECK(emitter.state().restarts == 1);
    CHECK(emitter.state().cma.mean == elite.params);
    CHECK(emitter.state().children.empty());
    // Its state goes to JSON and back, into a fresh emitter of the same settings.
    emitter.told(scored, improved, false, picks_elite);
    const nlohmann::json saved = emitter.state_to_json(nullptr);
    CmaEmitter back(ParentSelection::uniform, settings);
    back.state_from_json(saved, {4, 9, 0, 4, 4}, "e", nullptr);  // births 9: one child of this iteration
    CHECK(back.state_to_json(nullptr) == saved);
    CHECK_THROWS_WITH(back.state_from_json(saved, {4, 10, 0, 4, 4}, "e", nullptr), Catch::Contains("e.children"));
    CHECK_FALSE(emitter.thresholds());
    CHECK(CmaEmitter(ParentSelection::uniform, cma_settings(cma_mae)).thresholds() == ThresholdParams{0.1, -30.0});
}

TEST_CASE("cma_mae emitters rank by the archive's thresholds, which MapElites makes it keep", "[evolution][cma]") {
    DescribedSphereProblem problem(6, 2);
    CmaSettings settings = cma_settings(cma_mae);
    settings.thresholds = {0.5, 0.0};
    MapElitesParams params = params_with({{1.0, std::make_shared<CmaEmitter>(ParentSelection::uniform, settings)}});
    params.population = 4;
    MapElites me(params, 3, problem, empty_state());
    REQUIRE(me.state().archive.threshold_params() == ThresholdParams{0.5, 0.0});
    Individual c;
    c.id = 0;
    c.params.assign(6, 0.1);
    c.fitness = 10.0;
    c.descriptors = {0.1, 0.1};
    std::string error;
    me.insert(c, error);
    CHECK(me.state().archive.thresholds().at(*me.last_insertion().cell) == 5.0);
    // Emitters that disagree on the thresholds are refused.
    CmaSettings other = settings;
    other.thresholds.threshold_min = -1.0;
    const MapElitesParams clash =
        params_with({{1.0, std::make_shared<CmaEmitter>(ParentSelection::uniform, settings)},
                     {1.0, std::make_shared<CmaEmitter>(ParentSelection::uniform, other)}});
    CHECK_THROWS_WITH(MapElites(clash, 3, problem, empty_state()), Catch::Contains("same learning_rate"));
}

TEST_CASE("CMA-ME and CMA-MAE runs are the same for 1, 2 and 8 threads and continue exactly from a checkpoint",
          "[evolution][cma][determinism][resume]") {
    DescribedSphereProblem problem(6, 2, /*faulty=*/true);
    const BirthSchedule schedule{ScheduleKind::pipeline, 24, 9};
    const std::vector<std::vector<EmitterSpec>> setups{
        {cma(cma_me)},
        {cma(cma_mae), cma(cma_mae, 2.0)},
        {gaussian(), cma(cma_me), cma(cma_mae)},
        {cma(cma_me, 1.0, CmaCovariance::full), cma(cma_mae, 1.0, CmaCovariance::full)},
    };
    for (const std::vector<EmitterSpec>& emitters : setups) {
        const MapElitesParams params = params_with(emitters);
        auto run_to = [&](GenomeEvaluator& evaluator, std::uint64_t births) {
            MapElites me(params, 17, problem, empty_state());
            BirthPipeline pipeline(schedule, me, evaluator);
            REQUIRE(pipeline.run(births, ignore, never));
            return me.state();
        };
        ThreadEvaluator one(problem, 1), two(problem, 2), eight(problem, 8);
        const MapElitesState done = run_to(one, 1200);
        const std::string expected = map_elites_state_to_json(done).dump();
        CHECK(map_elites_state_to_json(run_to(two, 1200)).dump() == expected);
        CHECK(map_elites_state_to_json(run_to(eight, 1200)).dump() == expected);
        // The CMA emitters did work: updates since their last start, or restarts.
        std::uint64_t work = 0;
        for (const EmitterSlot& slot : done.emitters) {
            if (slot->kind() == "gaussian") continue;
            const CmaEmitterState& e = cma_of(slot).state();
            work += e.cma.updates + e.full.updates + e.restarts;
        }
        CHECK(work > 0);

        for (std::uint64_t stop_at : {23u, 24u, 30u, 47u, 500u, 1111u}) {
            Stored stored;
            std::vector<Individual> kept;
            {
                MapElites me(params, 17, problem, empty_state());
                BirthPipeline pipeline(schedule, me, two);
                CHECK_FALSE(pipeline.run(1200, ignore, [&] { return me.births() >= stop_at; }));
                stored = store(me.state());
                kept = pipeline.kept();
            }
            MapElites me(params, 17, problem, load(stored, params, 6));
            CHECK(store(me.state()).document == stored.document);
            BirthPipeline pipeline(schedule, me, eight, kept);
            REQUIRE(pipeline.run(1200, ignore, never));
            CHECK(map_elites_state_to_json(me.state()).dump() == expected);
        }
    }
}

TEST_CASE("a damaged emitter state or threshold is refused, naming it", "[evolution][cma][checkpoint]") {
    DescribedSphereProblem problem(6, 2);
    const MapElitesParams params = params_with({gaussian(), cma(cma_mae), cma(cma_me)});
    ThreadEvaluator pool(problem, 2);
    MapElites me(params, 5, problem, empty_state());
    BirthPipeline pipeline({ScheduleKind::batch, 24, 24}, me, pool);
    REQUIRE(pipeline.run(24 * 6 + 13, ignore, never));  // mid-generation: emitter 1 (births 8-15) holds 5 children
    const Stored good = store(me.state());
    REQUIRE_NOTHROW(load(good, params, 6));
    REQUIRE(good.document["emitters"][1]["children"].size() == 5);
    REQUIRE(good.document["archive"]["elites"][0].contains("threshold"));

    const std::vector<std::pair<std::string, std::function<void(nlohmann::json&)>>> edits{
        {"map_elites.emitters[1].sigma", [](nlohmann::json& d) { d["emitters"][1]["sigma"] = -0.1; }},
        {"map_elites.emitters[1].sigma", [](nlohmann::json& d) { d["emitters"][1]["sigma"] = "big"; }},
        {"map_elites.emitters[1].children", [](nlohmann::json& d) { d["emitters"][1]["children"].erase(0); }},
        {"map_elites.emitters[1].children[0].status", [](nlohmann::json& d) { d["emitters"][1]["children"][0]["status"] = 3; }},
        {"map_elites.emitters[1].origin", [](nlohmann::json& d) { d["emitters"][1]["origin"] = 1u << 30; }},
        {"map_elites.emitters[0]", [](nlohmann::json& d) { d["emitters"][0] = d["emitters"][1]; }},
        {"map_elites.emitters", [](nlohmann::json& d) { d["emitters"].erase(2); }},
        {"map_elites.emitters[1]", [](nlohmann::json& d) { d["emitters"][1].erase("path_c"); }},
        {"missing \"emitters\"", [](nlohmann::json& d) { d.erase("emitters"); }},
        {"map_elites.archive.elites[0].threshold", [](nlohmann::json& d) {
             d["archive"]["elites"][0]["threshold"] = d["archive"]["elites"][0]["fitness"].get<double>() + 1.0;
         }},
        {"map_elites.archive.elites[0].threshold", [](nlohmann::json& d) { d["archive"]["elites"][0]["threshold"] = -30.0; }},
    };
    for (const auto& [where, edit] : edits) {
        Stored bad = good;
        edit(bad.document);
        INFO(where);
        try {
            load(bad, params, 6);
            FAIL("accepted");
        } catch (const std::invalid_argument& e) {
            CHECK_THAT(e.what(), Catch::Contains(where));
        }
    }
    // A variance of 0 in the binary part.
    Stored zero = good;
    const std::uint64_t index = zero.document["emitters"][1]["variances"]["genome"].get<std::uint64_t>();
    std::fill_n(zero.genomes.begin() + static_cast<std::ptrdiff_t>(index * 6 * 8), 8, '\0');
    CHECK_THROWS_WITH(load(zero, params, 6), Catch::Contains("map_elites.emitters[1].variances"));
    // A full covariance that is not symmetric, or not positive definite.
    const MapElitesParams full = params_with({gaussian(), cma(cma_me, 1.0, CmaCovariance::full)});
    MapElites full_me(full, 5, problem, empty_state());
    BirthPipeline full_pipeline({ScheduleKind::batch, 24, 24}, full_me, pool);
    REQUIRE(full_pipeline.run(24 * 6, ignore, never));
    REQUIRE(cma_of(full_me.state().emitters[1]).state().full.covariance.size() == 36);
    const Stored full_good = store(full_me.state());
    REQUIRE_NOTHROW(load(full_good, full, 6));
    REQUIRE(full_good.document["emitters"][1]["covariance"].size() == 6);
    auto damaged = [&](std::size_t row, std::size_t column, double value) {
        Stored bad = full_good;
        const std::uint64_t g = bad.document["emitters"][1]["covariance"][row]["genome"].get<std::uint64_t>();
        std::memcpy(bad.genomes.data() + (g * 6 + column) * 8, &value, 8);  // little-endian, as the blob
        return bad;
    };
    const double c01 = cma_of(full_me.state().emitters[1]).state().full.covariance[1];
    CHECK_THROWS_WITH(load(damaged(0, 1, c01 + 1e-9), full, 6),
                      Catch::Contains("map_elites.emitters[1].covariance") && Catch::Contains("symmetric positive definite"));
    CHECK_THROWS_WITH(load(damaged(2, 2, -1.0), full, 6), Catch::Contains("map_elites.emitters[1].covariance"));
    Stored short_rows = full_good;
    short_rows.document["emitters"][1]["covariance"].erase(5);
    CHECK_THROWS_WITH(load(short_rows, full, 6), Catch::Contains("map_elites.emitters[1].covariance"));
    // A full state under a config that asks for the diagonal model.
    CHECK_THROWS_WITH(load(full_good, params_with({gaussian(), cma(cma_me)}), 6),
                      Catch::Contains("map_elites.emitters[1]"));
    // Thresholds in a run without cma_mae.
    const MapElitesParams no_mae = params_with({gaussian(), cma(cma_me)});
    CHECK_THROWS_WITH(load(good, no_mae, 6), Catch::Contains("map_elites"));
}

