#pragma once
// Births counted in generations of `population` births, for the GA and
// MAP-Elites alike (docs/algorithm.md §8.1). `Search` provides state().births and
// params().population.
#include <cstdint>

namespace morphogen {

template <class Search>
class GenerationCount {
public:
    // Generations completed so far (generation 0 included).
    std::uint64_t completed_generations() const { return births() / population(); }
    // True right after the last birth of a generation.
    bool at_generation_end() const { return births() > 0 && births() % population() == 0; }
    // Births needed to complete generation `generation`.
    std::uint64_t births_to_finish(std::uint64_t generation) const { return (generation + 1) * population(); }

protected:
    std::uint64_t population() const {
        return static_cast<std::uint64_t>(static_cast<const Search&>(*this).params().population);
    }

private:
    std::uint64_t births() const { return static_cast<const Search&>(*this).state().births; }
};

}  // namespace morphogen
