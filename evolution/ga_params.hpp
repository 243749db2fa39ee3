#pragma once
// Parameters of the steady-state GA (docs/algorithm.md §8.8; the `evolution` config
// section). Defaults are the documented ones (docs/config.md, configs/schema.json).
namespace morphogen {

struct GaParams {
    int population = 100;        // individuals; a generation is this many births
    int tournament = 3;          // draws per tournament (uniform, with replacement)
    double crossover = 0.3;      // probability a child mixes neuron blocks of two parents
    double mutation_rate = 0.05; // per-parameter probability of a normal step
    double mutation_sigma = 0.3; // standard deviation of that step
    int batch = 32;              // births drawn from one population snapshot and evaluated in parallel
    double init_range = 2.0;     // initial parameters uniform in [-init_range, +init_range)
};

}  // namespace morphogen
