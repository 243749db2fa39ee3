#pragma once
// The gaussian emitter (docs/algorithm.md §9.8): the GA's birth
// (operators.hpp conceive_birth: crossover of two parents' blocks, then a
// normal step per parameter with the evolution section's rate and sigma),
// its parents picked from the archive by its selection. No state.
#include "evolution/emitters/emitters.hpp"

namespace morphogen {

class GaussianEmitter final : public Emitter {
public:
    explicit GaussianEmitter(ParentSelection selection = ParentSelection::uniform) : Emitter(selection) {}
    std::unique_ptr<Emitter> clone() const override { return std::make_unique<GaussianEmitter>(*this); }
    std::string_view kind() const override { return "gaussian"; }
    // conceive_birth with the pool's picks (a random genome from an empty pool).
    Individual conceive(const EmitterSource& source, std::uint64_t birth) const override;
};

}  // namespace morphogen
