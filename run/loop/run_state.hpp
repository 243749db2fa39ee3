#pragma once
// What a run has done so far: the search's state, the history rows, how far
// lineage.csv goes. Saved and read back by checkpoint.hpp, checked by
// checkpoint_checks.hpp.
#include "evolution/individual.hpp"
#include "run/loop/run_records.hpp"
#include "run/searches/search_state.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace morphogen {

struct RunState {
    nlohmann::json config;  // the resolved config
    std::uint64_t seed = 0; // == config.run.seed; stored on its own for readers
    // The search's state (run_search.hpp), under its key in the content
    // ("ga", "map_elites"); empty only before a run's first state is made.
    HeldSearchState search;
    // Births conceived from a state before this one and not yet inserted
    // (evolution/execution/schedule.hpp: kept_begin..kept_end), in birth order, not
    // evaluated; "pending" in the content, absent when empty.
    std::vector<Individual> pending;
    std::vector<HistoryRow> history;
    std::uint64_t lineage_bytes = 0;  // lineage.csv length at checkpoint time
    std::string lineage_hash;         // FNV-1a 64 (hex) of those bytes
    double elapsed_s = 0.0;           // run time so far, over all sessions

    std::uint64_t births() const { return search ? search->births() : 0; }
};

}  // namespace morphogen
