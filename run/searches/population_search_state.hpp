#pragma once
// What the population searches (the GA, NSLC) answer alike, as a run drives
// them (PopulationSearch) and as a run keeps them (PopulationSearchState).
//
// The states (the GA's, NSLC's) answer alike
// (search_state.hpp): `State` has births, population (valid or not, in slot
// order), best and invalid_in_generation; history rows summarise the
// population. `Derived` (CRTP) gives the key, the JSON, its own checks and
// its session, and `first_births`: whether in generation 0 slot i holds birth i.
#include "evolution/ga/population_stats.hpp"
#include "evolution/operators.hpp"
#include "run/searches/run_search.hpp"
#include "run/searches/search_state.hpp"

#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace morphogen {

template <class State, class Derived>
class PopulationSearchState : public SearchState {
public:
    explicit PopulationSearchState(State state = {}) : state(std::move(state)) {}
    State state;

    std::unique_ptr<SearchState> clone() const override {
        return std::make_unique<Derived>(static_cast<const Derived&>(*this));
    }
    std::uint64_t births() const override { return state.births; }
    const std::optional<Individual>& best() const override { return state.best; }
    SearchView view() const override {
        SearchView v;
        v.births = state.births;
        v.best = &state.best;
        for (const Individual& member : state.population) v.members.push_back(&member);
        v.members_name = std::string(key()) + ".population";
        v.members_source = "the population it holds";
        v.invalid_in_generation = state.invalid_in_generation;
        v.members_are_first_births = Derived::first_births;
        return v;
    }
    void fill(HistoryRow& row, const ExperimentConfig&) const override {
        fill_statistics(row, summarize(state.population));
    }
};

// The live search `Search` (SteadyStateGA, Nslc): its history rows summarise
// the population, it exports the member that ranks highest by fitness
// (top_ranked), and it saves its state as a `Saved`.
template <class Search, class Saved>
class PopulationSearch final : public SearchOver<Search> {
public:
    template <class... Args>
    explicit PopulationSearch(Args&&... args) : SearchOver<Search>(std::forward<Args>(args)...) {}

    void fill(HistoryRow& row, const Inserted&) const override {
        fill_statistics(row, summarize(this->search_.state().population));
    }
    const Individual* exported() const override { return top_ranked(this->search_.state().population); }
    std::unique_ptr<SearchState> save() const override { return std::make_unique<Saved>(this->search_.state()); }
};

}  // namespace morphogen
