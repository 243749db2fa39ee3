// `morphogen gallery`: grow many random genomes in parallel (the paper's Figure 2).
#include "app/commands.hpp"
#include "fitness/mesh_stats.hpp"
#include "app/resource_options.hpp"
#include "core/base/errors.hpp"
#include "core/base/parallel_for.hpp"
#include "core/growth/genome_grower.hpp"
#include "core/io/mesh_io.hpp"
#include "report/render.hpp"
#include "run/config/experiment_config.hpp"
#include "run/genome_source.hpp"


#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

namespace morphogen {

namespace {

struct GalleryOptions {
    std::string config;
    int count = 0;
    std::uint64_t seed = 1;
    std::string out;
    std::string format = "obj";
    std::string png;
    int threads = 0;
    int columns = 10;
    MeshWriteOptions mesh_options;
    ResourceOptions resources;
};

struct GalleryEntry {
    std::uint64_t seed = 0;
    MeshArrays mesh;
    int seed_vertices = 0;
    double time_ms = 0;
    FitnessOutcome fitness;
    std::string error;
};

std::string entry_name(int index, const std::string& extension) {
    char name[32];
    std::snprintf(name, sizeof name, "%04d.%s", index, extension.c_str());
    return name;
}

int run_gallery(const GalleryOptions& options) {
    const ExperimentConfig config = load_experiment_config(options.config);
    const GenomeGrower grower(config.network, config.growth);
    const int threads = resolve_threads(options.threads);
    check_resource_limits(config, grower.seed(),
                          Workload{.threads = threads, .writers = options.format != "none" ? double(threads) : 0.0,
                                   .kept_meshes = double(options.count)},
                          options.resources.limits(), config_source(options.config));
    const std::filesystem::path dir(options.out);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw IoError(options.out + ": cannot create directory: " + ec.message());

    std::vector<GalleryEntry> entries(options.count);
    std::vector<GrowthWorkspace> workspaces(static_cast<std::size_t>(threads));
    parallel_for(entries.size(), threads, [&](std::size_t i, int worker) {
        GrowthWorkspace& workspace = workspaces[static_cast<std::size_t>(worker)];
        GalleryEntry& entry = entries[i];
        entry.seed = options.seed + static_cast<std::uint64_t>(i);
        try {
            const auto start = std::chrono::steady_clock::now();
            const Genome genome = random_genome(grower.layers(), config.growth.mode, config.evolution.init_range, entry.seed);
            GrowthState state = grower.grow(genome.params, workspace);
            entry.time_ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            entry.fitness = config.fitness->evaluate(state.mesh.view());
            entry.mesh = {state.mesh.positions(), state.mesh.faces()};
            if (options.format != "none")
                write_mesh(entry.mesh.view(), (dir / entry_name(static_cast<int>(i), options.format)).string(),
                           options.mesh_options);
        } catch (const std::exception& e) {
            entry.error = e.what();
        }
    });

    const std::string summary_path = (dir / "summary.csv").string();
    std::ofstream summary(summary_path, std::ios::trunc);
    if (!summary) throw IoError(summary_path + ": cannot open for writing");
    summary << "index,seed,vertices,faces,height,width,grew,time_ms,fitness\n";
    int grew = 0, failed = 0;
    for (int i = 0; i < options.count; ++i) {
        const GalleryEntry& e = entries[i];
        if (!e.error.empty()) {
            std::fprintf(stderr, "morphogen: gallery entry %d (seed %llu) failed: %s\n", i,
                         static_cast<unsigned long long>(e.seed), e.error.c_str());
            ++failed;
            continue;
        }
        const MeshStats stats = mesh_stats(e.mesh.view());
        const bool did_grow = static_cast<int>(e.mesh.positions.size()) > grower.seed().mesh.num_vertices();
        grew += did_grow;
        char row[256];
        std::snprintf(row, sizeof row, "%d,%llu,%zu,%zu,%.17g,%.17g,%d,%.3f,", i,
                      static_cast<unsigned long long>(e.seed), e.mesh.positions.size(), e.mesh.faces.size(),
                      stats.height, stats.width, did_grow ? 1 : 0, e.time_ms);
        summary << row;
        if (e.fitness.valid) {
            std::snprintf(row, sizeof row, "%.17g", e.fitness.score);
            summary << row;
        }
        summary << '\n';
    }
    summary.close();
    if (!summary) throw IoError(summary_path + ": write failed");

    if (!options.png.empty()) {
        std::vector<MeshArrays> meshes;
        std::vector<std::string> captions;
        for (int i = 0; i < options.count; ++i) {
            if (!entries[i].error.empty()) continue;
            meshes.push_back(std::move(entries[i].mesh));
            captions.push_back(std::to_string(i));
        }
        RenderOptions render;
        render.columns = options.columns;
        render_contact_sheet(meshes, captions, options.png, render);
    }
    std::printf("%s: %d genomes, %d grew, %d failed\n", options.out.c_str(), options.count, grew, failed);
    return failed == 0 ? 0 : 1;
}

}  // namespace

void add_gallery_command(CLI::App& root, CommandRunner& selected) {
    auto options = std::make_shared<GalleryOptions>();
    CLI::App* cmd = root.add_subcommand("gallery", "Grow many random genomes in parallel and summarise them");
    add_config_option(cmd, options->config);
    cmd->add_option("--count", options->count, "Number of random genomes")->required()->check(CLI::Range(1, 1'000'000));
    cmd->add_option("--seed", options->seed, "Seed of the first genome (genome i uses seed + i)")->required();
    cmd->add_option("--out", options->out, "Output directory")->required();
    cmd->add_option("--format", options->format, "Mesh format of the entries (none: only summary.csv)")
        ->check(CLI::IsMember({"obj", "glb", "ply", "none"}));
    cmd->add_flag("--ply-double", options->mesh_options.ply_double,
                  "With --format ply: 64-bit coordinates and normals instead of float32");
    cmd->add_option("--png", options->png, "Also render a contact sheet of all entries to this PNG");
    cmd->add_option("--columns", options->columns, "Columns of the contact sheet")->check(CLI::Range(1, 100));
    cmd->add_option("--threads", options->threads, "Threads (0 = all cores)")->check(CLI::Range(0, 4096));
    add_resource_options(cmd, options->resources);
    select_on_pick(cmd, selected, options, run_gallery);
}

}  // namespace morphogen
