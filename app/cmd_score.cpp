// `morphogen score`: the configured fitness and every metric of one mesh, read
// from a file or grown from a genome.
#include "app/commands.hpp"
#include "app/resource_options.hpp"
#include "core/base/config_reader.hpp"
#include "core/base/errors.hpp"
#include "fitness/architecture/architecture_json.hpp"
#include "fitness/fitness.hpp"
#include "core/growth/genome_grower.hpp"
#include "core/io/mesh_io.hpp"
#include "run/config/experiment_config.hpp"
#include "run/genome_source.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

namespace morphogen {

namespace {

struct ScoreOptions {
    std::string mesh;
    std::string genome;
    std::string config;
    std::string fitness;  // inline JSON replacing the config's fitness section
    bool json = false;
    ResourceOptions resources;
};

ExperimentConfig score_config(const ScoreOptions& options) {
    if (options.fitness.empty()) return load_experiment_config(options.config);
    nlohmann::json document = options.config.empty() ? nlohmann::json::object() : load_json_file(options.config);
    document["fitness"] = parse_json_text(options.fitness, "--fitness");
    const std::string source = options.config.empty() ? "--fitness" : options.config + " with --fitness";
    return read_experiment_config(document, source);
}

MeshArrays grow_genome(const ExperimentConfig& config, const std::string& path) {
    const GenomeGrower grower(config.network, config.growth);
    const GrowthState state = grower.grow(load_genome_for(grower.layers(), path).params);
    return {state.mesh.positions(), state.mesh.faces()};
}

std::string number_text(const nlohmann::json& value) {
    if (value.is_boolean()) return value.get<bool>() ? "yes" : "no";
    if (value.is_number_integer() || value.is_number_unsigned()) return value.dump();
    char text[64];
    std::snprintf(text, sizeof text, "%.10g", value.get<double>());
    return text;
}

// The fitness's parts, or none where computing them throws (the score is
// then invalid and says why).
FitnessFunction::Terms fitness_terms(const Fitness& fitness, MeshView mesh) {
    try {
        return fitness.function().terms(mesh);
    } catch (const std::exception&) {
        return {};
    }
}

// A mesh file that reads but holds nothing to score is an invalid mesh
// (exit 4), named like every other mesh error.
void require_scorable(const MeshArrays& mesh, const std::string& source) {
    if (mesh.positions.empty()) throw MeshError(source + ": the mesh has no vertices (nothing to score)");
    if (mesh.faces.empty()) throw MeshError(source + ": the mesh has no triangles (nothing to score)");
}

int run_score(const ScoreOptions& options) {
    const ExperimentConfig config = score_config(options);
    const std::string source = options.mesh.empty() ? options.genome + " (grown)" : options.mesh;
    if (options.mesh.empty())  // a grown mesh: bounded by the config
        check_resource_limits(config, Workload{.metrics = true}, options.resources.limits(),
                              config_source(options.config));
    const MeshArrays mesh = options.mesh.empty() ? grow_genome(config, options.genome) : read_mesh(options.mesh);
    require_scorable(mesh, source);
    const FitnessOutcome outcome = config.fitness->evaluate(mesh.view());
    nlohmann::json metrics;
    nlohmann::json architecture;
    try {
        metrics = mesh_metrics(mesh.view(), config.fitness->canopy_params());
        architecture = architecture_json(measure_architecture(mesh.view()));
    } catch (const std::logic_error& e) {  // what the measures refuse (e.g. a canopy grid too large)
        throw MeshError(source + ": " + e.what());
    }
    const std::string type = config.fitness->function().type();

    if (options.json) {
        nlohmann::json report = {{"source", options.mesh.empty() ? options.genome : options.mesh},
                                 {"fitness_type", type},
                                 {"fitness_valid", outcome.valid}};
        report["fitness"] = outcome.valid ? nlohmann::json(outcome.score) : nlohmann::json();  // null if invalid
        if (!outcome.valid) report["fitness_error"] = outcome.error;
        if (const FitnessFunction::Terms terms = fitness_terms(*config.fitness, mesh.view()); !terms.empty()) {
            nlohmann::json& parts = report["fitness_terms"] = nlohmann::json::object();
            for (const auto& [name, value] : terms) parts[name] = value;
        }
        report.update(metrics);
        report["architecture"] = architecture;
        std::printf("%s\n", report.dump(2).c_str());
        return 0;
    }
    std::printf("%s\n", (options.mesh.empty() ? "genome " + options.genome + " (grown)" : "mesh " + options.mesh).c_str());
    if (outcome.valid)
        std::printf("  %-18s %s (%s)\n", "fitness", number_text(outcome.score).c_str(), type.c_str());
    else
        std::printf("  %-18s invalid (%s): %s\n", "fitness", type.c_str(), outcome.error.c_str());
    for (const auto& [name, value] : fitness_terms(*config.fitness, mesh.view()))
        std::printf("  %-18s %s\n", ("  " + name).c_str(), number_text(value).c_str());
    for (const char* key : {"canopy", "height", "footprint", "area", "volume", "vertices", "faces", "self_intersecting"})
        std::printf("  %-18s %s\n", key, number_text(metrics.at(key)).c_str());
    std::printf("  %-18s tips %s, limbs %s, first fork at %s, Strahler %s, solidity %s\n", "architecture",
                number_text(architecture["tips"]).c_str(), number_text(architecture["limbs"]).c_str(),
                number_text(architecture["first_fork_height"]).c_str(), number_text(architecture["strahler"]).c_str(),
                architecture["solidity"].is_null() ? "none (open mesh)" : number_text(architecture["solidity"]).c_str());
    return 0;
}

}  // namespace

void add_score_command(CLI::App& root, CommandRunner& selected) {
    auto options = std::make_shared<ScoreOptions>();
    CLI::App* cmd = root.add_subcommand("score", "Print the configured fitness and every metric of a mesh");
    auto* mesh = cmd->add_option("--mesh", options->mesh, "Score this mesh file (" + mesh_extensions() + ")")
                     ->check(CLI::ExistingFile);
    auto* genome = cmd->add_option("--genome", options->genome, "Grow this genome (JSON) and score the mesh")
                       ->check(CLI::ExistingFile);
    mesh->excludes(genome);
    cmd->add_option("--config", options->config,
                    "Experiment config (JSON): its network/growth grow --genome, its fitness scores")
        ->check(CLI::ExistingFile);
    cmd->add_option("--fitness", options->fitness,
                    "Fitness section as inline JSON, replacing the config's, e.g. '{\"type\": \"light\"}'");
    cmd->add_flag("--json", options->json, "Print one JSON object instead of text");
    add_resource_options(cmd, options->resources);
    select_on_pick(cmd, selected, options, run_score, [mesh, genome] {
        if (mesh->count() + genome->count() != 1)
            throw CLI::RequiredError("score needs one of --mesh FILE or --genome FILE");
    });
}

}  // namespace morphogen
