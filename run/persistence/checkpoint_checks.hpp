#pragma once
// What a checkpoint must agree with besides its hash: itself and the run's
// lineage.csv. A checkpoint whose hash was recomputed after an edit passes
// the envelope check (checkpoint.hpp), so every field is checked against the
// others here. Each check throws std::invalid_argument saying which field
// contradicts what; callers turn that into a refused checkpoint (exit 5).
#include "evolution/ga/population_stats.hpp"
#include "run/config/experiment_config.hpp"
#include "run/loop/run_records.hpp"
#include "run/loop/run_state.hpp"

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace morphogen {

// The content against itself and its own config: births within the run's
// target, the population of generation 0, the best individual against the
// population and the history, history rows (births per generation, invalid
// counts, stats in order, timings finite, non-negative and in order, none
// after elapsed_s), sizes that are vertex counts, the lineage record's form.
void check_checkpoint_content(const RunState& state, const ExperimentConfig& config);

// The content against `lineage`, lineage.csv's first state.lineage_bytes
// bytes (whose hash was already checked): `header` (lineage_header_for the
// config's descriptors) and exactly one row per birth in id order, with its
// cells; every population member and the best individual as their rows
// record them (id to fitness; the descriptors too where the state holds
// them, as MAP-Elites elites do); the best the first of the highest fitness;
// the invalid births of every generation (history) and of the current one.
// The search's own checks (SearchState::check_history). With
// `pending_parents`, also the parents of every pending birth
// (SearchState::check_pending_parents).
void check_checkpoint_against_lineage(const RunState& state, std::string_view lineage, std::uint64_t population,
                                      std::string_view header = lineage_header,
                                      const BirthReplay* pending_parents = nullptr);

// What re-drawing a birth's parents needs, for `config`'s run.
BirthReplay birth_replay(const ExperimentConfig& config);

// Every parent of a pending birth is a valid birth lineage.csv records
// before the birth's source state (a search whose parents are members it
// kept: MAP-Elites, NSLC); throws std::invalid_argument naming the first that is not.
void check_parents_recorded_valid(std::span<const Individual> pending, std::span<const RecordedBirth> recorded,
                                  const BirthSchedule& schedule);

// A history row's fitness columns (and, with `sizes`, its mean vertices)
// against the statistics of the members they summarise, which `source`
// names ("the population it holds"); for the searches' own checks.
void check_row_stats(const HistoryRow& row, std::size_t generation, const PopulationStats& stats, bool sizes,
                     const std::string& source);

}  // namespace morphogen
