#pragma once
// The search states a RunState holds, for tests that build or read one.
#include "run/searches/elites_search.hpp"
#include "run/searches/ga_search.hpp"
#include "run/loop/run_state.hpp"

#include <memory>
#include <stdexcept>

namespace morphogen::test {

// The GA's state; an empty one is put in first when the RunState holds none.
inline GaState& ga_of(RunState& state) {
    if (!state.search) state.search = std::make_unique<GaSearchState>();
    if (GaState* ga = ga_state(*state.search)) return *ga;
    throw std::logic_error("the run state holds another search's state, not the GA's");
}
inline const GaState& ga_of(const RunState& state) {
    if (const GaState* ga = state.search ? ga_state(*state.search) : nullptr) return *ga;
    throw std::logic_error("the run state holds no GA state");
}
inline const MapElitesState& elites_of(const RunState& state) {
    if (const MapElitesState* elites = state.search ? elites_state(*state.search) : nullptr) return *elites;
    throw std::logic_error("the run state holds no MAP-Elites state");
}

}  // namespace morphogen::test
