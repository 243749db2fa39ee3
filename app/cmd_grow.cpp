// `morphogen grow`: grow one genome and write its mesh.
#include "commands.hpp"
#include "experiment_config.hpp"
#include "genome_io.hpp"
#include "genome_source.hpp"
#include "growth.hpp"
#include "mesh_io.hpp"
#include "mesh_stats.hpp"
#include "resource_options.hpp"

#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>

namespace morphogen {

namespace {

struct GrowOptions {
    std::string config;
    std::optional<std::uint64_t> random_seed;
    std::string genome;
    std::optional<int> steps;
    std::string output;
    std::string save_genome;
    MeshWriteOptions mesh_options;
    ResourceOptions resources;
};

int run_grow(const GrowOptions& options) {
    ExperimentConfig config = load_experiment_config(options.config);
    if (options.steps) config.growth.steps = *options.steps;
    check_resource_limits(config, Workload{.scores = false, .writers = 1}, options.resources.limits(),
                          options.config.empty() ? "default config" : options.config);
    mesh_format_from_path(options.output);  // refuse an unknown extension before growing
    const std::vector<int> layers = config.network.layers();
    const Genome genome = options.random_seed ? random_genome(layers, config.evolution.init_range, *options.random_seed)
                                              : load_genome_for(layers, options.genome);
    const Network network(genome);
    const Seed seed = make_seed(config.growth.seed_mesh, config.growth.seed_radius);

    const auto start = std::chrono::steady_clock::now();
    GrowthWorkspace workspace;
    const GrowthState state = Grower(network, config.growth).grow(seed, workspace);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    write_mesh(state.mesh.view(), options.output, options.mesh_options);
    if (!options.save_genome.empty()) save_genome(genome, options.save_genome);
    const MeshStats stats = mesh_stats(state.mesh.view());
    std::printf("%s: %d vertices, %d faces, height %.3f, width %.3f, %d steps in %.3f s\n", options.output.c_str(),
                state.mesh.num_vertices(), state.mesh.num_faces(), stats.height, stats.width, state.steps_done,
                seconds);
    return 0;
}

}  // namespace

void add_grow_command(CLI::App& root, CommandRunner& selected) {
    auto options = std::make_shared<GrowOptions>();
    CLI::App* cmd = root.add_subcommand("grow", "Grow one genome from a seed mesh and write the mesh");
    cmd->add_option("--config", options->config, "Experiment config (JSON); defaults if omitted")
        ->check(CLI::ExistingFile);
    auto* random = cmd->add_option("--random", options->random_seed, "Grow a random genome from this seed");
    auto* genome = cmd->add_option("--genome", options->genome, "Grow this genome file")->check(CLI::ExistingFile);
    random->excludes(genome);
    cmd->add_option("--steps", options->steps, "Override growth.steps")->check(CLI::Range(0, 1'000'000));
    cmd->add_option("-o,--output", options->output, "Output mesh (.obj .ply .off .stl .glb)")->required();
    cmd->add_option("--save-genome", options->save_genome, "Also write the genome as JSON");
    cmd->add_flag("--ply-double", options->mesh_options.ply_double,
                  "PLY output: 64-bit coordinates and normals (exact) instead of float32 (what WebGL viewers draw)");
    add_resource_options(cmd, options->resources);
    cmd->callback([options, random, genome, &selected] {
        if (random->count() + genome->count() != 1)
            throw CLI::RequiredError("grow needs one of --random SEED or --genome FILE");
        selected = [options] { return run_grow(*options); };
    });
}

}  // namespace morphogen
