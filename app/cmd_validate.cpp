// `morphogen validate CONFIG...`: reports every problem of each config at
// once (with its key path), or "valid". Exit 0 if all are valid, else 2 for an
// invalid config, 3 for an unreadable file (the config or its seed mesh), 4 for
// a seed mesh that is not usable (the first of these wins over later ones, 2 over all).
#include "app/commands.hpp"
#include "app/resource_options.hpp"
#include "core/base/errors.hpp"
#include "core/growth/seeds/seeds.hpp"
#include "run/exit_codes.hpp"
#include "run/config/experiment_config.hpp"

#include <iostream>
#include <memory>

namespace morphogen {

namespace {
struct ValidateOptions {
    std::vector<std::string> configs;
    bool print_resolved = false;
    ResourceOptions resources;
};

int run_validate(const ValidateOptions& o) {
    int result = exit_code::ok;
    for (const std::string& path : o.configs) {
        try {
            const ExperimentConfig config = load_experiment_config(path);
            // The same exceptions (and exit codes) as evolve and grow give: a seed
            // file that cannot be read is 3, one that is not a usable mesh 4.
            Seed seed;
            try {
                seed = make_seed(config.growth);
            } catch (const IoError& e) {
                throw IoError(path + ": " + e.what());
            } catch (const MeshError& e) {
                throw MeshError(path + ": growth.seed_mesh: " + e.what());
            }
            // What `evolve` would need on this machine.
            const ResourceLimits limits = o.resources.limits();
            const ResourceEstimate estimate =
                check_resource_limits(config, seed, evolution_workload(config), limits, path);
            std::cout << path << ": valid (" << resource_summary(estimate, limits) << ")\n";
            if (o.print_resolved) std::cout << config.resolved.dump(2) << '\n';
        } catch (const ConfigError& e) {
            std::cerr << e.what() << '\n';
            result = exit_code::usage;
        } catch (const IoError& e) {
            std::cerr << e.what() << '\n';
            if (result == exit_code::ok) result = exit_code::io;
        } catch (const MeshError& e) {
            std::cerr << e.what() << '\n';
            if (result == exit_code::ok) result = exit_code::mesh;
        }
    }
    return result;
}
}  // namespace

void add_validate_command(CLI::App& root, CommandRunner& selected) {
    auto options = std::make_shared<ValidateOptions>();
    CLI::App* cmd = root.add_subcommand("validate", "Check experiment configs and report every problem at once");
    cmd->add_option("config", options->configs, "experiment config files (JSON)")->required();
    cmd->add_flag("--resolved", options->print_resolved, "also print each config with its defaults filled in");
    add_resource_options(cmd, options->resources);
    select_on_pick(cmd, selected, options, run_validate);
}

}  // namespace morphogen
