#pragma once
// What a run has done so far: the search's state, the history rows, how far
// lineage.csv goes. Saved and read back by checkpoint.hpp, checked by
// checkpoint_checks.hpp.
#include "evolution/map_elites.hpp"
#include "evolution/steady_state.hpp"
#include "run/run_records.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace morphogen {

struct RunState {
    nlohmann::json config;  // the resolved config
    std::uint64_t seed = 0; // == config.run.seed; stored on its own for readers
    GaState ga;                          // steady_state runs ("ga" in the content)
    std::optional<MapElitesState> elites; // map_elites runs ("map_elites" in the content, instead of "ga")
    // Births conceived from a state before this one and not yet inserted
    // (evolution/schedule.hpp: kept_begin..kept_end), in birth order, not
    // evaluated; "pending" in the content, absent when empty.
    std::vector<Individual> pending;
    std::vector<HistoryRow> history;
    std::uint64_t lineage_bytes = 0;  // lineage.csv length at checkpoint time
    std::string lineage_hash;         // FNV-1a 64 (hex) of those bytes
    double elapsed_s = 0.0;           // run time so far, over all sessions

    std::uint64_t births() const { return elites ? elites->births : ga.births; }
};

}  // namespace morphogen
