// `morphogen-bench-qd`: the sphere linear-projection benchmark (docs/algorithm.md
// §9.10, bench/sphere_projection.hpp) run through evolution/'s MAP-Elites
// with the settings of the CMA-MAE paper, so the emitters can be checked
// against its table: 540 births per iteration (one generation), a 100 x 100
// grid, n = 100, sigma 0.5; MAP-Elites (gaussian on every parameter),
// MAP-Elites (line) (iso_line 0.5 / 0.2), CMA-ME (15 cma_me emitters of 36,
// mu parents, basic restarts: the paper's baseline) and CMA-MAE (15 cma_mae
// emitters of 36, alpha 0.01, threshold_min 0); also cma_me_imp (CMA-ME with
// filter parents and no_improvement restarts, as Fontaine et al. 2020 first
// ran it and our cma_me's defaults). Generation 0 (540 random
// genomes, uniform in [-1, 1)) is part of the budget. Prints the QD-score as
// the paper normalises it (the sum of the elites' objectives / cells), the
// coverage, the best objective, and the time per birth of the whole loop (an
// upper bound on an emitter's own cost per birth).
#include "bench/pyribs_cma.hpp"
#include "bench/sphere_projection.hpp"
#include "evolution/emitters/cma/cma_emitter.hpp"
#include "evolution/emitters/gaussian_emitter.hpp"
#include "evolution/emitters/iso_line_emitter.hpp"
#include "evolution/schedulers/map_elites.hpp"
#include "evolution/emitters/cma/sep_cma.hpp"
#include "evolution/execution/thread_evaluator.hpp"

#include <CLI/CLI.hpp>
#include <unistd.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <stdexcept>

namespace morphogen {

namespace {

struct BenchQdOptions {
    std::vector<std::string> algorithms{"map_elites", "line", "cma_me", "cma_mae"};
    std::uint64_t iterations = 10000;
    std::size_t dimension = 100;
    int seeds = 1;
    std::uint64_t seed = 1;
    bool json = false;
    std::size_t covariance_cost = 0;  // > 0: time the covariance models at this n instead
    std::string covariance = "diagonal";  // the CMA emitters' model
    double init_range = 1.0;  // generation 0: uniform in [-R, R) per parameter
    double max_hours = 1.0;  // refuse a run estimated to take longer
};

constexpr int kPerIteration = 540, kCmaEmitters = 15;

MapElitesParams params_for(const std::string& algorithm, const std::string& covariance, double init_range) {
    MapElitesParams p;
    p.population = kPerIteration;
    p.batch = kPerIteration;
    p.crossover = 0.0;
    p.mutation_rate = 1.0;  // pyribs' GaussianEmitter steps every parameter
    p.mutation_sigma = 0.5;
    p.init_range = init_range;
    if (algorithm == "map_elites") {
        p.emitters = {{1.0, std::make_shared<GaussianEmitter>()}};
    } else if (algorithm == "line") {
        p.emitters = {{1.0, std::make_shared<IsoLineEmitter>(ParentSelection::uniform, IsoLineSettings{0.5, 0.2})}};
    } else if (algorithm == "cma_me" || algorithm == "cma_mae" || algorithm == "cma_me_imp") {
        CmaSettings s;
        s.ranking = algorithm == "cma_mae" ? CmaRanking::threshold : CmaRanking::improvement;
        s.sigma0 = 0.5;
        // cma_me_imp: filter and no_improvement, the original CMA-ME (our cma_me's defaults).
        const bool original = algorithm == "cma_me_imp";
        s.parents = original ? CmaParents::filter : CmaParents::mu;
        s.restart = original ? CmaRestart::no_improvement : CmaRestart::basic;
        s.thresholds = {0.01, 0.0};
        s.covariance = covariance == "diagonal" ? CmaCovariance::diagonal : CmaCovariance::full;
        if (covariance == "pyribs") s.full_update = pyribs_full_update();
        p.emitters.assign(kCmaEmitters, {1.0, std::make_shared<CmaEmitter>(ParentSelection::uniform, s)});
    } else {
        throw std::invalid_argument("unknown algorithm " + algorithm);
    }
    return p;
}

struct QdRun {
    double qd_score = 0, coverage = 0, best = 0, seconds = 0;
    std::uint64_t births = 0, restarts = 0;
};

QdRun run_one(const std::string& algorithm, const BenchQdOptions& o, std::uint64_t seed) {
    SphereProjection problem(o.dimension);
    Archive archive = Archive::grid(problem.archive_ranges());
    const double cells = static_cast<double>(archive.cells());
    MapElites me(params_for(algorithm, o.covariance, o.init_range), seed, problem, MapElitesState{0, std::move(archive), {}, 0, 0});
    const auto start = std::chrono::steady_clock::now();
    // The batch schedule of one iteration, one thread: the papers' ask/tell loop.
    ThreadEvaluator evaluator(problem, 1);
    BirthPipeline pipeline(BirthSchedule{ScheduleKind::batch, kPerIteration, kPerIteration}, me, evaluator);
    pipeline.run(o.iterations * kPerIteration, [](const Individual&, const std::string&, const Inserted&, const std::string&) {},
                 [] { return false; });
    QdRun run;
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.births = me.state().births;
    double sum = 0.0;
    for (const auto& [cell, elite] : me.state().archive.elites()) sum += elite.fitness;
    run.qd_score = sum / cells;
    run.coverage = 100.0 * static_cast<double>(me.state().archive.occupied()) / cells;
    run.best = me.state().best ? me.state().best->fitness : 0.0;
    for (const EmitterSlot& e : me.state().emitters)
        if (const auto* cma = dynamic_cast<const CmaEmitter*>(e.get())) run.restarts += cma->state().restarts;
    return run;
}

double mean_of(const std::vector<QdRun>& runs, double QdRun::*field) {
    double sum = 0.0;
    for (const QdRun& r : runs) sum += r.*field;
    return sum / static_cast<double>(runs.size());
}

// What one birth's sampling and one update cost with a diagonal covariance
// (sep-CMA-ES, ours) and with a full one (an n x n matrix-vector product per
// sample and an eigendecomposition per update, as full CMA-ES does), at n
// parameters: the measurement behind docs/algorithm.md §9.9's choice.
int run_covariance_cost(const BenchQdOptions& o) {
    const std::size_t n = o.covariance_cost;
    const int lambda = 25, samples = 200;
    auto seconds = [](auto&& work) {
        const auto start = std::chrono::steady_clock::now();
        work();
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    RandomStream stream(o.seed, 0);
    SepCmaState diagonal = sep_cma_start(std::vector<double>(n, 0.1), 0.1);
    std::vector<std::vector<double>> children;
    const double diag_sample = seconds([&] {
        for (int k = 0; k < samples; ++k) children.push_back(sep_cma_sample(diagonal, stream));
    }) / samples;
    std::vector<const std::vector<double>*> parents;
    for (int k = 0; k < lambda / 2; ++k) parents.push_back(&children[static_cast<std::size_t>(k)]);
    const double diag_update = seconds([&] { sep_cma_update(diagonal, parents); });

    Eigen::MatrixXd a = Eigen::MatrixXd::Random(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    const Eigen::MatrixXd c = a * a.transpose() / static_cast<double>(n) + Eigen::MatrixXd::Identity(a.rows(), a.cols());
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen;
    const double full_eigen = seconds([&] { eigen.compute(c); });
    const Eigen::MatrixXd bd = eigen.eigenvectors() * eigen.eigenvalues().cwiseSqrt().asDiagonal();
    Eigen::VectorXd z = Eigen::VectorXd::Random(a.rows()), x(a.rows());
    const double full_sample = seconds([&] {
        for (int k = 0; k < samples; ++k) {
            x.noalias() = bd * z;
            z[k % z.size()] += x[0] * 1e-300;  // keep the product live
        }
    }) / samples;
    Eigen::MatrixXd update = c;
    const double full_rank_mu = seconds([&] {
        for (int k = 0; k < lambda / 2; ++k) update.noalias() += 0.01 * (x * x.transpose());
    });
    const nlohmann::json report{{"n", n},
                                {"diagonal_sample_ms", 1e3 * diag_sample},
                                {"diagonal_update_ms", 1e3 * diag_update},
                                {"full_sample_ms", 1e3 * full_sample},
                                {"full_rank_mu_update_ms", 1e3 * full_rank_mu},
                                {"full_eigendecomposition_ms", 1e3 * full_eigen}};
    if (o.json) {
        std::printf("%s\n", report.dump(2).c_str());
    } else {
        std::printf("n = %zu: diagonal: sample %.4f ms, update (mu = %d) %.4f ms; full: sample %.4f ms, "
                    "rank-mu update %.2f ms, eigendecomposition %.1f ms\n",
                    n, 1e3 * diag_sample, lambda / 2, 1e3 * diag_update, 1e3 * full_sample, 1e3 * full_rank_mu,
                    1e3 * full_eigen);
    }
    return 0;
}

// What the machine can do: the memory the emitters' covariances and the
// archive take, and the time the eigendecompositions take (about n^3 / 1e9 s
// each: 0.1 s at n = 500 on one core of the development machine), against
// the physical memory and --max-hours. Throws std::invalid_argument saying
// what to change.
void check_resources(const BenchQdOptions& o) {
    const double n = static_cast<double>(o.covariance_cost > 0 ? o.covariance_cost : o.dimension);
    const bool full = o.covariance_cost > 0 || o.covariance != "diagonal";
    const double gib = 1024.0 * 1024.0 * 1024.0;
    // Full: C, B and a product per CMA emitter (15; one for --covariance-cost);
    // diagonal: a few vectors each. The archive: 10,000 elites of n doubles.
    const double matrices = o.covariance_cost > 0 ? 4.0 : 3.0 * kCmaEmitters;
    const double bytes = (full ? matrices * n * n : 8.0 * kCmaEmitters * n) * 8.0 + 1e4 * n * 8.0;
    const double physical = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGESIZE));
    if (bytes > 0.8 * physical)
        throw std::invalid_argument("n = " + std::to_string(static_cast<long long>(n)) + " needs about " +
                                    std::to_string(static_cast<long long>(bytes / gib + 1)) + " GiB, more than 80 % of " +
                                    "this machine's " + std::to_string(static_cast<long long>(physical / gib)) +
                                    " GiB: lower --dimension or --covariance-cost, or use --covariance diagonal");
    const double eigen_s = n * n * n / 1e9;
    const double updates = o.covariance_cost > 0 ? 1.0
                           : full ? static_cast<double>(o.iterations) * kCmaEmitters * static_cast<double>(o.seeds)
                                  : 0.0;
    const double hours = eigen_s * updates / 3600.0;
    if (hours > o.max_hours)
        throw std::invalid_argument("the full covariance's eigendecompositions alone would take about " +
                                    std::to_string(static_cast<long long>(hours + 1)) + " hours (--max-hours " +
                                    std::to_string(o.max_hours) + "): lower --dimension, --iterations or " +
                                    "--covariance-cost, or raise --max-hours");
}

int run_bench_qd(const BenchQdOptions& o) {
    check_resources(o);
    if (o.covariance_cost > 0) return run_covariance_cost(o);
    nlohmann::json report = nlohmann::json::object();
    report["iterations"] = o.iterations;
    report["births_per_iteration"] = kPerIteration;
    report["dimension"] = o.dimension;
    report["covariance"] = o.covariance;
    report["init_range"] = o.init_range;
    if (!o.json)
        std::printf("sphere linear projection, n = %zu, %llu iterations x %d births, 100 x 100 cells, %d seed(s), "
                    "%s covariance\n",
                    o.dimension, static_cast<unsigned long long>(o.iterations), kPerIteration, o.seeds,
                    o.covariance.c_str());
    for (const std::string& algorithm : o.algorithms) {
        std::vector<QdRun> runs;
        nlohmann::json rows = nlohmann::json::array();
        for (int s = 0; s < o.seeds; ++s) {
            runs.push_back(run_one(algorithm, o, o.seed + static_cast<std::uint64_t>(s)));
            const QdRun& r = runs.back();
            rows.push_back({{"seed", o.seed + static_cast<std::uint64_t>(s)}, {"qd_score", r.qd_score},
                            {"coverage_percent", r.coverage}, {"best", r.best}, {"seconds", r.seconds},
                            {"us_per_birth", 1e6 * r.seconds / static_cast<double>(r.births)},
                            {"restarts", r.restarts}});
            if (!o.json)
                std::printf("%-10s seed %llu: QD-score %6.2f  coverage %6.2f%%  best %6.2f  %5.2f us/birth  restarts %llu\n",
                            algorithm.c_str(), static_cast<unsigned long long>(o.seed + s), r.qd_score, r.coverage,
                            r.best, 1e6 * r.seconds / static_cast<double>(r.births),
                            static_cast<unsigned long long>(r.restarts));
        }
        report["algorithms"][algorithm] = {{"runs", rows},
                                           {"mean_qd_score", mean_of(runs, &QdRun::qd_score)},
                                           {"mean_coverage_percent", mean_of(runs, &QdRun::coverage)},
                                           {"mean_best", mean_of(runs, &QdRun::best)}};
        if (!o.json)
            std::printf("%-10s mean   : QD-score %6.2f  coverage %6.2f%%  best %6.2f\n", algorithm.c_str(),
                        mean_of(runs, &QdRun::qd_score), mean_of(runs, &QdRun::coverage), mean_of(runs, &QdRun::best));
    }
    if (o.json) std::printf("%s\n", report.dump(2).c_str());
    return 0;
}

}  // namespace

}  // namespace morphogen

int main(int argc, char** argv) {
    using namespace morphogen;
    auto options = std::make_shared<BenchQdOptions>();
    CLI::App app{"morphogen-bench-qd: the sphere linear-projection QD benchmark (emitters vs the papers)"};
    CLI::App* cmd = &app;
    // A number as typed: no sign where none is allowed, nothing non-finite.
    const CLI::Validator whole([](std::string& text) -> std::string {
        return text.find_first_of("-+") == std::string::npos ? "" : "expected a whole number >= 0, got '" + text + "'";
    }, "", "whole number");
    const CLI::Validator finite([](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        return end != text.c_str() && !std::isfinite(value) ? "expected a finite number, got '" + text + "'" : "";
    }, "", "finite number");
    cmd->add_option("--algorithm", options->algorithms,
                    "map_elites, line, cma_me, cma_mae (default: these four), cma_me_imp (filter, no_improvement)")
        ->check(CLI::IsMember({"map_elites", "line", "cma_me", "cma_mae", "cma_me_imp"}));
    cmd->add_option("--iterations", options->iterations, "Iterations of 540 births (default 10000, the papers')")
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1000000}));
    cmd->add_option("--dimension", options->dimension, "Parameters n (default 100)")->check(CLI::Range(2, 100000));
    cmd->add_option("--seeds", options->seeds, "Runs per algorithm, seeds seed, seed+1, ... (default 1)")
        ->check(CLI::Range(1, 1000));
    cmd->add_option("--seed", options->seed, "First seed (default 1)")->check(whole);
    cmd->add_flag("--json", options->json, "Print one JSON object");
    cmd->add_option("--covariance", options->covariance,
                    "The CMA emitters' covariance model: diagonal (sep-CMA-ES, default), full (CMA-ES), "
                    "or pyribs (full CMA-ES updated as pyribs 0.4 does, as the papers' code ran it)")
        ->check(CLI::IsMember({"diagonal", "full", "pyribs"}));
    cmd->add_option("--init-range", options->init_range,
                    "Generation 0 draws every parameter uniformly from [-R, R) (default 1); a tiny R starts "
                    "every CMA emitter at about x0 = 0, as the papers' code does")
        ->check(finite)
        ->check(CLI::Range(1e-300, 1e6));
    cmd->add_option("--covariance-cost", options->covariance_cost,
                    "Instead: time sampling and updating a diagonal and a full covariance at N parameters")
        ->check(CLI::Range(2, 20000));
    cmd->add_option("--max-hours", options->max_hours,
                    "Refuse a run whose full-covariance work is estimated above this (default 1)")
        ->check(finite)
        ->check(CLI::PositiveNumber);
    for (const char* name : {"--iterations", "--dimension", "--covariance-cost"}) app.get_option(name)->check(whole);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    try {
        return run_bench_qd(*options);
    } catch (const std::invalid_argument& e) {
        std::cerr << "morphogen-bench-qd: " << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "morphogen-bench-qd: " << e.what() << '\n';
        return 1;
    }
}
