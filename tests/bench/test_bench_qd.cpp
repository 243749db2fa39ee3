// The benchmarks beside the product (bench/): the sphere linear-projection
// problem, pyribs 0.4's CMA-ES update against the textbook's, and
// morphogen-bench-qd end to end, including what it refuses.
#include "bench/pyribs_cma.hpp"
#include "bench/sphere_projection.hpp"
#include "evolution/emitters/cma/cma_rates.hpp"
#include "evolution/emitters/cma/full_cma.hpp"
#include "evolution/rng.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace morphogen;

namespace {
struct BenchResult {
    int code = -1;
    std::string output;
};

// Runs `morphogen-bench-qd <args>` through the shell; output is stdout and stderr.
BenchResult run_bench(const std::string& args) {
    const std::filesystem::path out =
        std::filesystem::temp_directory_path() / ("morphogen-bench-out-" + std::to_string(::getpid()));
    const std::string command = std::string(MORPHOGEN_BENCH_QD_EXE) + " " + args + " > " + out.string() + " 2>&1";
    const int status = std::system(command.c_str());
    BenchResult r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(out);
    std::ostringstream text;
    text << in.rdbuf();
    r.output = text.str();
    std::filesystem::remove(out);
    return r;
}
}  // namespace

TEST_CASE("the sphere linear-projection benchmark: objective 100 at the optimum, clipped descriptors", "[bench]") {
    SphereProjection sphere(4);
    const Evaluation at_optimum = sphere.evaluate(std::vector<double>(4, 2.048), 0);
    CHECK(at_optimum.score == Approx(100.0));
    CHECK(at_optimum.descriptors == std::vector<double>{4.096, 4.096});
    const Evaluation worst = sphere.evaluate(std::vector<double>(4, -5.12), 0);
    CHECK(worst.score == Approx(0.0).margin(1e-12));
    // clip(x) = 5.12 / x beyond +-5.12.
    const Evaluation far = sphere.evaluate(std::vector<double>{10.24, 1.0, -20.48, 3.0}, 0);
    CHECK(far.descriptors[0] == Approx(0.5 + 1.0));
    CHECK(far.descriptors[1] == Approx(-0.25 + 3.0));
    CHECK(sphere.archive_ranges()[0].max == Approx(10.24));
}

TEST_CASE("pyribs' update: the textbook's at sigma 1, p_c in x units otherwise, B and d recomputed lazily",
          "[bench][cma]") {
    const std::vector<double> a{1.3, -2.2, 0.9}, b{0.7, -1.6, 0.2};
    const std::vector<const std::vector<double>*> parents{&a, &b};
    // sigma = 1, steps inside the clip, h_sigma true in both: the same mean
    // and paths as the textbook update, and its C but for the rank-one term
    // weighted c1^2 instead of c1 (sigma's rule differs too).
    FullCmaState textbook = full_cma_start({1.0, -2.0, 0.5}, 1.0), pyribs = textbook;
    full_cma_update(textbook, parents);
    std::uint64_t at = 0;
    pyribs_cma_update(pyribs, at, parents, 4);
    const double c1 = cma_rates(parents, 3, /*separable=*/false).c1;
    for (std::size_t i = 0; i < 3; ++i) {
        CHECK(pyribs.mean[i] == Approx(textbook.mean[i]).epsilon(1e-14));
        CHECK(pyribs.path_c[i] == Approx(textbook.path_c[i]).epsilon(1e-14));
        CHECK(pyribs.path_sigma[i] == Approx(textbook.path_sigma[i]).epsilon(1e-14));
        for (std::size_t j = 0; j < 3; ++j) {
            const double rank_one = textbook.path_c[i] * textbook.path_c[j];
            CHECK(pyribs.covariance[i * 3 + j] ==
                  Approx(textbook.covariance[i * 3 + j] - (c1 - c1 * c1) * rank_one).epsilon(1e-13));
        }
    }
    CHECK(pyribs.sigma != textbook.sigma);
    // sigma = 0.5: p_c is sigma times the textbook's (m' - m, not (m' - m) / sigma).
    FullCmaState half_t = full_cma_start({1.0, -2.0, 0.5}, 0.5), half_p = half_t;
    full_cma_update(half_t, parents);
    std::uint64_t half_at = 0;
    pyribs_cma_update(half_p, half_at, parents, 4);
    for (std::size_t i = 0; i < 3; ++i) CHECK(half_p.path_c[i] == Approx(0.5 * half_t.path_c[i]).epsilon(1e-14));
    // n = 100, lambda = 36: B and d stay I for two updates and follow C at the third.
    const std::size_t n = 100;
    FullCmaState lazy = full_cma_start(std::vector<double>(n, 0.0), 0.5);
    std::vector<std::vector<double>> xs;
    for (std::size_t k = 0; k < 18; ++k) {
        RandomStream stream(7, k);
        xs.push_back(full_cma_sample(lazy, stream));
    }
    std::vector<const std::vector<double>*> mu;
    for (const auto& x : xs) mu.push_back(&x);
    const std::vector<double> identity = lazy.basis;
    std::uint64_t lazy_at = 0;
    for (int u = 1; u <= 3; ++u) {
        pyribs_cma_update(lazy, lazy_at, mu, 36);
        INFO("update " << u);
        CHECK((lazy.basis == identity) == (u < 3));
        CHECK(lazy_at == (u < 3 ? 0u : 3u));
    }
}

TEST_CASE("morphogen-bench-qd runs the sphere benchmark: every algorithm, reproducibly, and the covariance costs", "[bench][cli]") {
    const BenchResult r = run_bench("--iterations 4 --seeds 2 --json");
    REQUIRE(r.code == 0);
    const auto report = nlohmann::json::parse(r.output);
    CHECK(report["iterations"] == 4);
    for (const char* algorithm : {"map_elites", "line", "cma_me", "cma_mae"}) {
        INFO(algorithm);
        const auto& a = report["algorithms"][algorithm];
        REQUIRE(a["runs"].size() == 2);
        // 2,160 births cannot fill 10,000 cells, and the objective is at most 100.
        CHECK(a["mean_coverage_percent"].get<double>() > 0.5);
        CHECK(a["mean_coverage_percent"].get<double>() < 21.7);
        CHECK(a["mean_best"].get<double>() <= 100.0);
        CHECK(a["runs"][0]["qd_score"] != a["runs"][1]["qd_score"]);  // two seeds, two runs
    }
    // The same seed gives the same numbers.
    const BenchResult again = run_bench("--iterations 4 --seeds 1 --algorithm cma_mae --json");
    REQUIRE(again.code == 0);
    CHECK(nlohmann::json::parse(again.output)["algorithms"]["cma_mae"]["runs"][0]["qd_score"] ==
          report["algorithms"]["cma_mae"]["runs"][0]["qd_score"]);
    const BenchResult cost = run_bench("--covariance-cost 50 --json");
    REQUIRE(cost.code == 0);
    for (const char* key : {"diagonal_sample_ms", "diagonal_update_ms", "full_sample_ms", "full_eigendecomposition_ms"})
        CHECK(nlohmann::json::parse(cost.output).contains(key));
    CHECK(run_bench("--algorithm nsga").code != 0);
    // The papers' CMA-ES update from x0 ~ 0: recorded in the report, reproducible, and
    // not the textbook full update's numbers.
    const char* pyribs = "--iterations 4 --algorithm cma_me --covariance pyribs --init-range 1e-9 --json";
    const BenchResult p1 = run_bench(pyribs), p2 = run_bench(pyribs);
    REQUIRE(p1.code == 0);
    const auto pr = nlohmann::json::parse(p1.output);
    CHECK(pr["covariance"] == "pyribs");
    CHECK(pr["init_range"].get<double>() == 1e-9);
    REQUIRE(p2.code == 0);
    CHECK(nlohmann::json::parse(p2.output)["algorithms"]["cma_me"]["runs"][0]["qd_score"] ==
          pr["algorithms"]["cma_me"]["runs"][0]["qd_score"]);
    const BenchResult full = run_bench("--iterations 4 --algorithm cma_me --covariance full --init-range 1e-9 --json");
    REQUIRE(full.code == 0);
    CHECK(nlohmann::json::parse(full.output)["algorithms"]["cma_me"]["mean_qd_score"] !=
          pr["algorithms"]["cma_me"]["mean_qd_score"]);
    CHECK(run_bench("--covariance sparse").code != 0);
    CHECK(run_bench("--init-range 0").code != 0);
}

TEST_CASE("morphogen-bench-qd refuses what the machine cannot do and numbers that are no numbers", "[bench][cli]") {
    // An 80 GB covariance per emitter: refused at once, naming the way out.
    const BenchResult huge = run_bench("--covariance full --dimension 100000 --iterations 1");
    CHECK(huge.code == 2);
    CHECK_THAT(huge.output, Catch::Contains("GiB") && Catch::Contains("--dimension"));
    // An eigendecomposition of 20,000^2: hours.
    const BenchResult slow = run_bench("--covariance-cost 20000");
    CHECK(slow.code == 2);
    CHECK_THAT(slow.output, Catch::Contains("hours") && Catch::Contains("--max-hours"));
    for (const char* args : {"--init-range nan", "--init-range inf", "--seed -1", "--iterations -1", "--max-hours nan"}) {
        CAPTURE(args);
        const BenchResult r = run_bench(args);
        CHECK(r.code == 2);
        CHECK_THAT(r.output, Catch::Contains(std::string(args).substr(0, std::string(args).find(' '))));
    }
}
