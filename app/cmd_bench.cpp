// `morphogen bench`: the project's own speed measurement. Grows a fixed set of
// random genomes on one thread (with the time split between phases by
// GrowthPhaseTimer) and on all threads, `--repeat` times in alternation;
// prints the median of each figure (shared machines are noisy: one pass
// proves little).
#include "app/commands.hpp"
#include "core/base/fma_peak.hpp"
#include "core/growth/growth_phase_timer.hpp"
#include "core/base/parallel_for.hpp"
#include "core/growth/genome_grower.hpp"
#include "run/config/experiment_config.hpp"
#include "run/genome_source.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>

namespace morphogen {

namespace {

struct BenchOptions {
    std::string config;
    int genomes = 32;
    int repeat = 5;
    std::uint64_t seed = 1;
    int threads = 0;
    bool json = false;
};

std::string cpu_model() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line))
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown";
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// One repetition: the timed one-thread pass, then the all-threads pass.
struct BenchPass {
    PhaseTimes phases;
    std::uint64_t vertices_out = 0;
    double wall_1t = 0, wall_all = 0;
};

BenchPass run_pass(const std::vector<Network>& networks, const GenomeGrower& grower, int threads) {
    BenchPass pass;
    GrowthWorkspace workspace;
    GrowthPhaseTimer timer(grower.params().height_scale);
    auto start = std::chrono::steady_clock::now();
    for (const Network& network : networks)
        pass.vertices_out += grower.grow(network, workspace, {}, &timer).mesh.num_vertices();
    // The timer's own measuring is no part of growth.
    pass.wall_1t = seconds_since(start) - timer.own_seconds();
    pass.phases = timer.times();

    // All threads, one genome per thread at a time (as evolution runs).
    start = std::chrono::steady_clock::now();
    std::vector<GrowthWorkspace> workspaces(static_cast<std::size_t>(threads));
    parallel_for(networks.size(), threads, [&](std::size_t i, int worker) {
        grower.grow(networks[i], workspaces[static_cast<std::size_t>(worker)]);
    });
    pass.wall_all = seconds_since(start);
    return pass;
}

int run_bench(const BenchOptions& options) {
    const ExperimentConfig config = load_experiment_config(options.config);
    const GenomeGrower grower(config.network, config.growth);
    const std::vector<int>& layers = grower.layers();
    std::vector<Network> networks;
    for (int i = 0; i < options.genomes; ++i)
        networks.emplace_back(random_genome(layers, config.growth.mode, config.evolution.init_range, options.seed + i));
    const int threads = resolve_threads(options.threads);

    std::vector<BenchPass> passes;
    std::vector<double> peaks;  // measured between passes: the machine's speed drifts
    for (int r = 0; r < options.repeat; ++r) {
        peaks.push_back(measure_fma_peak(0.05));
        passes.push_back(run_pass(networks, grower, threads));
    }
    const double peak = median(peaks);
    // Every pass grows the same meshes, so vertex-steps are the same in each.
    const double vs = static_cast<double>(passes.front().phases.vertex_steps);
    const auto values_of = [&](auto measure) {
        std::vector<double> values;
        for (const BenchPass& pass : passes) values.push_back(measure(pass));
        return values;
    };
    const auto median_of = [&](auto measure) { return median(values_of(measure)); };
    const auto range_of = [&](auto measure) {
        const auto [low, high] = std::ranges::minmax(values_of(measure));
        return nlohmann::json::array({low, high});
    };
    const double wall_1t = median_of([](const BenchPass& p) { return p.wall_1t; });
    const double wall_all = median_of([](const BenchPass& p) { return p.wall_all; });
    const double think = median_of([](const BenchPass& p) { return p.phases.think; });
    const auto speedup = [](const BenchPass& p) { return p.wall_1t / p.wall_all; };
    const auto think_rate = [vs](const BenchPass& p) { return vs / p.phases.think; };
    const auto rate_1t = [vs](const BenchPass& p) { return vs / p.wall_1t; };
    const double flop_per_vertex_step = 2.0 * static_cast<double>(parameter_count(layers));

    nlohmann::json report{
        {"cpu", cpu_model()},
        {"genomes", options.genomes},
        {"steps", config.growth.steps},
        {"layers", layers},
        {"threads", threads},
        {"repeat", options.repeat},
        {"vertex_steps", passes.front().phases.vertex_steps},
        {"mean_final_vertices", static_cast<double>(passes.front().vertices_out) / options.genomes},
        {"wall_s_1t", wall_1t},
        {"wall_s_all", wall_all},
        {"genomes_per_s_1t", options.genomes / wall_1t},
        {"genomes_per_s_all", options.genomes / wall_all},
        {"vertex_steps_per_s_1t", median_of(rate_1t)},
        {"vertex_steps_per_s_1t_range", range_of(rate_1t)},
        {"vertex_steps_per_s_all", vs / wall_all},
        {"speedup", median_of(speedup)},
        {"speedup_range", range_of(speedup)},
        {"think_s", think},
        {"gather_s", median_of([](const BenchPass& p) { return p.phases.gather; })},
        {"move_s", median_of([](const BenchPass& p) { return p.phases.move; })},
        {"split_s", median_of([](const BenchPass& p) { return p.phases.split; })},
        {"flip_s", median_of([](const BenchPass& p) { return p.phases.flip; })},
        {"collide_s", median_of([](const BenchPass& p) { return p.phases.collide; })},
        {"collide_fraction", median_of([](const BenchPass& p) { return p.phases.collide / p.phases.total(); })},
        {"think_vertex_steps_per_s", median_of(think_rate)},
        {"think_vertex_steps_per_s_range", range_of(think_rate)},
        {"network_gflops", median_of(think_rate) * flop_per_vertex_step * 1e-9},
        {"fma_peak_gflops", peak * 1e-9},
        {"network_bound_vertex_steps_per_s", peak / flop_per_vertex_step},
        {"think_fraction_of_bound", median_of(think_rate) * flop_per_vertex_step / peak},
        {"growth_fraction_of_bound", median_of(rate_1t) * flop_per_vertex_step / peak},
    };
    if (options.json) {
        std::printf("%s\n", report.dump(2).c_str());
        return 0;
    }
    const double gather = report["gather_s"], move = report["move_s"], split = report["split_s"],
                 flip = report["flip_s"], collide = report["collide_s"];
    const double total = think + gather + move + split + flip + collide;
    std::printf("cpu: %s\n", cpu_model().c_str());
    std::printf("%d genomes x %d steps, layers %s, mean final vertices %.0f; medians of %d passes\n",
                options.genomes, config.growth.steps, nlohmann::json(layers).dump().c_str(),
                report["mean_final_vertices"].get<double>(), options.repeat);
    std::printf("1 thread : %8.3f s  %7.2f genomes/s  %6.2f M vertex-steps/s\n", wall_1t, options.genomes / wall_1t,
                report["vertex_steps_per_s_1t"].get<double>() * 1e-6);
    std::printf("%d threads: %8.3f s  %7.2f genomes/s  %6.2f M vertex-steps/s  (x%.2f, range %.2f-%.2f)\n", threads,
                wall_all, options.genomes / wall_all, vs / wall_all * 1e-6, report["speedup"].get<double>(),
                report["speedup_range"][0].get<double>(), report["speedup_range"][1].get<double>());
    std::printf("phases (1 thread): think %.1f%%  gather %.1f%%  move %.1f%%  split %.1f%%  flip %.1f%%", 100 * think / total,
                100 * gather / total, 100 * move / total, 100 * split / total, 100 * flip / total);
    // Only "prevent" and "touch" have a collide phase (docs/algorithm.md §5.7).
    if (config.growth.collisions != Collisions::allow) std::printf("  collide %.1f%%", 100 * collide / total);
    std::printf("\n");
    std::printf("think: %.2f M vertex-steps/s (%.1f GFLOP/s)\n", report["think_vertex_steps_per_s"].get<double>() * 1e-6,
                report["network_gflops"].get<double>());
    std::printf("FMA peak now: %.1f GFLOP/s, so the network bounds growth at %.2f M vertex-steps/s; "
                "think reaches %.0f%% of it, whole growth %.0f%%\n",
                peak * 1e-9, peak / flop_per_vertex_step * 1e-6, 100 * report["think_fraction_of_bound"].get<double>(),
                100 * report["growth_fraction_of_bound"].get<double>());
    return 0;
}

}  // namespace

void add_bench_command(CLI::App& root, CommandRunner& selected) {
    auto options = std::make_shared<BenchOptions>();
    CLI::App* cmd = root.add_subcommand("bench", "Measure growth speed (1 thread and all threads)");
    add_config_option(cmd, options->config);
    cmd->add_option("--genomes", options->genomes, "Number of random genomes to grow (default 32)")
        ->check(CLI::Range(1, 100000));
    cmd->add_option("--repeat", options->repeat, "Passes to take medians over (default 5)")->check(CLI::Range(1, 1000));
    cmd->add_option("--seed", options->seed, "Seed of the first genome");
    cmd->add_option("--threads", options->threads, "Threads of the parallel pass (0 = all cores)")
        ->check(CLI::Range(0, 4096));
    cmd->add_flag("--json", options->json, "Print one JSON object");
    select_on_pick(cmd, selected, options, run_bench);
}

}  // namespace morphogen
