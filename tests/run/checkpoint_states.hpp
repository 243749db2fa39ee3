#pragma once
// Large run states for the checkpoint tests and their timings: generation 0
// of a GA or of MAP-Elites with many genomes, and the text format 1 held.
#include "run/loop/run_state.hpp"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace morphogen::test {

// A valid run state of generation 0 for `config_text`: `members` random
// genomes born so far (ids 0.., no parents), the population one more than
// that so no generation has ended. MAP-Elites: one elite per cell of a
// 100 x 100 grid (members = 10,000). Genomes of the config's network.
RunState generation0_state(const std::string& config_text, std::uint64_t members);

// The default network (1845 parameters), MAP-Elites on a 100 x 100 grid.
std::string archive_config(std::uint64_t population);
std::string ga_config(std::uint64_t population);

// The end of a checkpoint's JSON header line (its binary part follows).
inline std::size_t header_end(const std::string& bytes) { return bytes.find('\n'); }
// Equal to the bit (-0.0 and 0.0 differ; so would two NaNs' payloads).
inline bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// The content format 1 held (genomes inline), as the previous build's save wrote it.
std::string format1_text(const RunState& s);

}  // namespace morphogen::test
