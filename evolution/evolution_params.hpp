#pragma once
// The `evolution` config section (docs/config.md): which search runs and the
// parameters of the steady-state GA, read beside their struct with the
// ObjectReader every section uses (core/base/config_reader.hpp).
#include "core/base/config_reader.hpp"
#include "evolution/ga/ga_params.hpp"
#include "evolution/novelty/novelty_params.hpp"

namespace morphogen {

// evolution.algorithm: the steady-state GA (docs/algorithm.md §8),
// MAP-Elites (§9) or novelty search with local competition (§14).
enum class Algorithm { steady_state, map_elites, nslc };

// Reads the section (problems go to reader.issues(), defaults fill gaps, every
// value used is recorded in reader.resolved()) and calls reader.finish().
// `algorithm` (if not null) receives evolution.algorithm. The schedule is
// "batch" by default when the section sets `batch` (a config written for the
// batch schedule keeps it) and "pipeline" otherwise; of `lag` and `batch` only
// the one the schedule uses is resolved, and giving the other is an issue.
// The novelty_* keys are read (into `novelty`, if not null) and resolved only
// for "nslc"; giving one for another algorithm is an issue.
GaParams read_evolution_params(ObjectReader& reader, Algorithm* algorithm = nullptr, NoveltyParams* novelty = nullptr);

}  // namespace morphogen
