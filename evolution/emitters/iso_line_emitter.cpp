#include "evolution/emitters/iso_line_emitter.hpp"

namespace morphogen {

Individual IsoLineEmitter::conceive(const EmitterSource& s, std::uint64_t birth) const {
    if (s.pool.empty()) return conceive_birth(s.rules, s.blocks, s.dimension, s.seed, birth, ParentPicker{});
    RandomStream stream(s.seed, birth);
    const Individual& x = s.pool.pick(selection(), stream);
    const Individual& y = s.pool.pick(selection(), stream);
    Individual child;
    child.id = birth;
    child.parent1 = x.id;
    child.parent2 = y.id;
    const double along = settings_.sigma_line * stream.normal();
    child.params.resize(x.params.size());
    for (std::size_t i = 0; i < x.params.size(); ++i)
        child.params[i] = x.params[i] + settings_.sigma_iso * stream.normal() + along * (y.params[i] - x.params[i]);
    return child;
}

}  // namespace morphogen
