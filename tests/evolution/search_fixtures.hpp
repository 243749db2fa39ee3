#pragma once
// What the MAP-Elites and pipeline tests share: a plain emitter, an empty
// 8 x 8 archive, and the pipeline's do-nothing callbacks.
#include "evolution/emitters/emitters.hpp"
#include "evolution/emitters/gaussian_emitter.hpp"
#include "evolution/schedulers/map_elites.hpp"

#include <memory>
#include <string>

namespace morphogen::test {

inline EmitterSpec gaussian(double share = 1.0) { return {share, std::make_shared<GaussianEmitter>()}; }

inline MapElitesState empty_state() {
    return MapElitesState{0, Archive::grid({{"x", -2, 3, 8}, {"y", -2, 3, 8}}), {}, 0, 0};
}

// The pipeline's callbacks: an insertion nobody records, and a stop never asked for.
inline const auto ignore = [](const Individual&, const std::string&, const Inserted&, const std::string&) {};
inline const auto never = [] { return false; };

}  // namespace morphogen::test
