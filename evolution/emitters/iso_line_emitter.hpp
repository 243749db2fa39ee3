#pragma once
// The iso+line emitter (Vassiliades & Mouret 2018; docs/algorithm.md §9.8):
// parents x and y picked by its selection, then
//   child = x + sigma_iso * N(0, I) + sigma_line * N(0, 1) * (y - x).
// No state.
#include "evolution/emitters/emitters.hpp"

namespace morphogen {

struct IsoLineSettings {
    double sigma_iso = 0.05;  // the isotropic step
    double sigma_line = 0.2;  // the step along the line to the second parent
};

class IsoLineEmitter final : public Emitter {
public:
    explicit IsoLineEmitter(ParentSelection selection = ParentSelection::uniform, IsoLineSettings settings = {})
        : Emitter(selection), settings_(settings) {}
    std::unique_ptr<Emitter> clone() const override { return std::make_unique<IsoLineEmitter>(*this); }
    std::string_view kind() const override { return "iso_line"; }
    // Draws from RandomStream(seed, birth), in this order: parent x, parent
    // y, the line's N(0,1), then one N(0,1) per parameter. An empty pool
    // gives a random genome (as conceive_birth does).
    Individual conceive(const EmitterSource& source, std::uint64_t birth) const override;
    const IsoLineSettings& settings() const { return settings_; }

private:
    IsoLineSettings settings_;
};

}  // namespace morphogen
