#include "evolution/emitters/gaussian_emitter.hpp"

namespace morphogen {

Individual GaussianEmitter::conceive(const EmitterSource& s, std::uint64_t birth) const {
    return conceive_birth(s.rules, s.blocks, s.dimension, s.seed, birth, s.pool.picker(selection()));
}

}  // namespace morphogen
