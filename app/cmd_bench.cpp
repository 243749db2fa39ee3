// `morphogen bench`: the project's own speed measurement. Grows a fixed set of
// random genomes once on one thread (with the time split between phases) and
// once on all threads; prints genomes/s and vertex-steps/s.
#include "commands.hpp"
#include "experiment_config.hpp"
#include "genome_source.hpp"
#include "growth.hpp"

#include <nlohmann/json.hpp>
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>

namespace morphogen {

namespace {

struct BenchOptions {
    std::string config;
    int genomes = 16;
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

int run_bench(const BenchOptions& options) {
    const ExperimentConfig config = load_experiment_config(options.config);
    const std::vector<int> layers = config.network.layers();
    const Seed seed = make_seed(config.growth.seed_mesh, config.growth.seed_radius);
    std::vector<Network> networks;
    for (int i = 0; i < options.genomes; ++i)
        networks.emplace_back(random_genome(layers, config.evolution.init_range, options.seed + i));

    // One thread, phases timed.
    PhaseTimes phases;
    GrowthWorkspace workspace;
    std::uint64_t vertices_out = 0;
    auto start = std::chrono::steady_clock::now();
    for (const Network& network : networks)
        vertices_out += Grower(network, config.growth).grow(seed, workspace, &phases).mesh.num_vertices();
    const double wall_1t = seconds_since(start);

    // All threads, one genome per thread at a time (as evolution runs).
    const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
    start = std::chrono::steady_clock::now();
#pragma omp parallel num_threads(threads)
    {
        GrowthWorkspace local;
#pragma omp for schedule(dynamic)
        for (int i = 0; i < options.genomes; ++i) Grower(networks[i], config.growth).grow(seed, local);
    }
    const double wall_all = seconds_since(start);

    const double vs = static_cast<double>(phases.vertex_steps);
    nlohmann::json report{
        {"cpu", cpu_model()},
        {"genomes", options.genomes},
        {"steps", config.growth.steps},
        {"layers", layers},
        {"threads", threads},
        {"vertex_steps", phases.vertex_steps},
        {"mean_final_vertices", static_cast<double>(vertices_out) / options.genomes},
        {"wall_s_1t", wall_1t},
        {"wall_s_all", wall_all},
        {"genomes_per_s_1t", options.genomes / wall_1t},
        {"genomes_per_s_all", options.genomes / wall_all},
        {"vertex_steps_per_s_1t", vs / wall_1t},
        {"vertex_steps_per_s_all", vs / wall_all},
        {"speedup", wall_1t / wall_all},
        {"think_s", phases.think},
        {"gather_s", phases.gather},
        {"move_s", phases.move},
        {"split_s", phases.split},
        {"flip_s", phases.flip},
        {"think_vertex_steps_per_s", vs / phases.think},
        {"network_gflops", vs * 2.0 * static_cast<double>(parameter_count(layers)) / phases.think * 1e-9},
    };
    if (options.json) {
        std::printf("%s\n", report.dump(2).c_str());
        return 0;
    }
    std::printf("cpu: %s\n", cpu_model().c_str());
    std::printf("%d genomes x %d steps, layers %s, mean final vertices %.0f\n", options.genomes,
                config.growth.steps, nlohmann::json(layers).dump().c_str(),
                static_cast<double>(vertices_out) / options.genomes);
    std::printf("1 thread : %8.3f s  %7.2f genomes/s  %6.2f M vertex-steps/s\n", wall_1t, options.genomes / wall_1t,
                vs / wall_1t * 1e-6);
    std::printf("%d threads: %8.3f s  %7.2f genomes/s  %6.2f M vertex-steps/s  (x%.2f)\n", threads, wall_all,
                options.genomes / wall_all, vs / wall_all * 1e-6, wall_1t / wall_all);
    std::printf("phases (1 thread): think %.1f%%  gather %.1f%%  move %.1f%%  split %.1f%%  flip %.1f%%\n",
                100 * phases.think / phases.total(), 100 * phases.gather / phases.total(),
                100 * phases.move / phases.total(), 100 * phases.split / phases.total(),
                100 * phases.flip / phases.total());
    std::printf("think: %.2f M vertex-steps/s (%.1f GFLOP/s)\n", vs / phases.think * 1e-6,
                report["network_gflops"].get<double>());
    return 0;
}

}  // namespace

void add_bench_command(CLI::App& root, CommandRunner& selected) {
    auto options = std::make_shared<BenchOptions>();
    CLI::App* cmd = root.add_subcommand("bench", "Measure growth speed (1 thread and all threads)");
    cmd->add_option("--config", options->config, "Experiment config (JSON); defaults if omitted")
        ->check(CLI::ExistingFile);
    cmd->add_option("--genomes", options->genomes, "Number of random genomes to grow")->check(CLI::Range(1, 100000));
    cmd->add_option("--seed", options->seed, "Seed of the first genome");
    cmd->add_option("--threads", options->threads, "Threads of the parallel pass (0 = all cores)")
        ->check(CLI::Range(0, 4096));
    cmd->add_flag("--json", options->json, "Print one JSON object");
    cmd->callback([options, &selected] { selected = [options] { return run_bench(*options); }; });
}

}  // namespace morphogen
