#pragma once
// The command-line options that set the resource limits
// (resource_estimate.hpp), shared by every command that builds from a config:
//   --max-memory SIZE       memory a command may plan to use (default: half of this machine's)
//   --max-eval-time SECONDS one evaluation's worst case, one core (default 300)
//   --no-limits             refuse nothing
// A machine's size is not part of the experiment, so these are options and not
// config keys (resolved configs and checkpoints do not record them).
#include "run/limits/resource_estimate.hpp"

#include <CLI/CLI.hpp>

#include <memory>

namespace morphogen {

struct ResourceOptions {
    std::string max_memory;  // as typed; empty = default
    double max_eval_seconds = default_max_eval_seconds;
    bool no_limits = false;
    ResourceLimits limits() const;
};

// Adds the three options to `command`; their values land in `options`.
void add_resource_options(CLI::App* command, ResourceOptions& options);

}  // namespace morphogen
