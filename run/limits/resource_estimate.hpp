#pragma once
// Before anything runs: how much memory a config can need and how long one
// evaluation (grow one genome, score the mesh) can take, as upper bounds over
// every genome the config allows, and the limits of this machine they must
// stay within (docs/limits-resources.md, "Resource limits").
//
// Contract:
//  - estimate_resources() is a pure function of the config, the seed's size
//    and the workload; it allocates nothing that grows with the estimate, so
//    refusing an absurd config takes microseconds. Every number is a bound for
//    the worst genome: the vertex count can at most triple per step (a split
//    adds one vertex per face, F = 2V - 4) and never passes max_vertices; a
//    vertex moves at most min(speed / 2, budget) per step (its drive is at
//    most 0.5, and k * drive <= budget) and new vertices are born inside the
//    mesh, so a plant stays within the seed's box grown by that much per step.
//  - Memory is in bytes of this build's data structures (measured: see the
//    constants in resource_estimate.cpp); work is in seconds of one core at
//    the speed measured on the development machine (an AMD EPYC VM), so the
//    same config gets the same verdict on every machine with the same limits.
//  - resource_issues() turns every exceeded limit into a ConfigIssue whose
//    path names the config keys responsible and whose message gives the
//    estimate, how it is made up, the limit and how to raise it.
//  - Scoring is costed by the config's fitness itself
//    (FitnessFunction::add_cost): its memory, its time and the hard caps it
//    enforces while scoring (light_max_rays_per_sun, canopy_max_cells), with
//    the same numbers, so a config that passes never has a plant refused by
//    them; --no-limits skips the check (plants beyond a cap then score
//    invalid).
//  - The genomes the search holds are counted in one place,
//    search_genomes(): a MAP-Elites archive adds its cells there.
#include "core/base/config_reader.hpp"
#include "core/growth/seeds/seeds.hpp"
#include "fitness/cost.hpp"
#include "run/config/experiment_config.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace morphogen {

struct ResourceLimits {
    double max_memory_bytes = 0;    // --max-memory; default: default_memory_fraction of physical memory
    double max_eval_seconds = 300;  // --max-eval-time: one evaluation, worst genome, one core
    bool enabled = true;            // false with --no-limits: nothing is refused
};

inline constexpr double default_memory_fraction = 0.5;
inline constexpr double default_max_eval_seconds = 300;

// This machine's physical memory (sysconf); 0 if it cannot be read.
double physical_memory_bytes();
// default_memory_fraction of it (16 GiB if it cannot be read), and the
// default time limit.
ResourceLimits default_resource_limits();
// "8G", "512MiB", "1.5T", "4096" (bytes): K, M, G, T are powers of 1024,
// optionally followed by "B" or "iB". Nothing for anything else or <= 0.
std::optional<double> parse_byte_size(const std::string& text);
// "12.3 GiB", "512 MiB", "800 B".
std::string format_bytes(double bytes);

// What the estimate needs of the seed mesh.
struct SeedExtent {
    double vertices = 0;
    Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  // bounding box
};
SeedExtent seed_extent(const Seed& seed);

// What a command does with a config.
struct Workload {
    bool evolution = false;  // evolve/resume: population, checkpoints, best-mesh exports
    int threads = 1;         // threads growing at once
    bool scores = true;      // scores each mesh with the config's fitness
    bool metrics = false;    // also every metric of the mesh (score)
    double writers = 0;      // grown meshes being written to files at once
    double kept_meshes = 0;  // grown meshes kept in memory (gallery's contact sheet)
};

// What evolve and resume do with a config on this machine (run.threads
// resolved; threads beyond the births in flight evaluate nothing).
Workload evolution_workload(const ExperimentConfig& config);

// One contribution to an estimate, with the keys that decide it, and a bound
// the fitness code enforces itself while scoring: the fitness's own types,
// since every fitness type states its cost (fitness/cost.hpp).
using EstimatePart = CostPart;
using HardCap = CostCap;

// The genomes of the search, the one place an archive of elites would add
// its cells (both in memory and in the checkpoint).
struct SearchGenomes {
    double held = 0;          // in memory at once: population, its copy in the saved state, the births in flight, the best
    double checkpointed = 0;  // in each checkpoint: population and best
};
SearchGenomes search_genomes(const ExperimentConfig& config);

struct ResourceEstimate {
    std::uint64_t parameters = 0;   // genome size
    SearchGenomes genomes;          // of the search (evolution only)
    double checkpoint_bytes = 0;    // the largest checkpoint.json of the run (evolution only)
    double max_vertices = 0;        // the most vertices a plant can have
    double vertex_steps = 0;        // vertices thinking, summed over the steps
    double max_width = 0;           // diagonal of the box a plant stays in
    std::vector<EstimatePart> memory;  // bytes at the peak
    std::vector<EstimatePart> work;    // seconds of one evaluation
    std::vector<HardCap> caps;

    double memory_bytes() const;
    double eval_seconds() const;
};

ResourceEstimate estimate_resources(const ExperimentConfig& config, const SeedExtent& seed, const Workload& workload);

// Every limit `estimate` exceeds (none when limits.enabled is false).
std::vector<ConfigIssue> resource_issues(const ResourceEstimate& estimate, const ResourceLimits& limits);

// For commands: builds the config's seed, estimates, and throws one
// ConfigError "<source>: <keys>: ..." listing every exceeded limit.
void check_resource_limits(const ExperimentConfig& config, const Workload& workload, const ResourceLimits& limits,
                           const std::string& source);
// The same with the seed already built; also when limits are lifted, the
// estimate is returned.
ResourceEstimate check_resource_limits(const ExperimentConfig& config, const Seed& seed, const Workload& workload,
                                       const ResourceLimits& limits, const std::string& source);
// "estimated at most 91 MiB of memory and 0.48 s of one core per evaluation,
// ...; limits 11.8 GiB and 5.0 min" for `validate`.
std::string resource_summary(const ResourceEstimate& estimate, const ResourceLimits& limits);

}  // namespace morphogen
