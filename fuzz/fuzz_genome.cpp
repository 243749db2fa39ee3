// Fuzz target "genome": the bytes as a genome file (core/growth/genome_io.hpp), read
// the way load_genome reads one, but from memory.
#include "core/base/config_reader.hpp"
#include "fuzz/fuzz_target.hpp"
#include "core/growth/genome_io.hpp"

#include <bit>
#include <cstdint>

namespace morphogen::fuzz {
std::string input_from_file(const std::string&, std::string bytes) { return bytes; }
}  // namespace morphogen::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace morphogen;
    using namespace morphogen::fuzz;
    const std::string text(as_text(data, size));
    Genome genome;
    if (!accepts([&] { genome = genome_from_json(parse_json_text(text, "fuzz.genome.json"), "fuzz.genome.json"); }))
        return 0;
    // genome_io.hpp promises an exact round trip: write it as save_genome does
    // and read it back, bit for bit.
    const std::string written = genome_to_json(genome).dump();
    Genome back;
    if (!accepts([&] { back = genome_from_json(parse_json_text(written, "written genome"), "written genome"); }))
        finding("a genome that was read is refused after writing it: " + written.substr(0, 200));
    bool same = back.layers == genome.layers && back.params.size() == genome.params.size();
    for (std::size_t i = 0; same && i < back.params.size(); ++i)
        same = std::bit_cast<std::uint64_t>(back.params[i]) == std::bit_cast<std::uint64_t>(genome.params[i]);
    if (!same) finding("a genome changes when written and read back: " + written.substr(0, 200));
    return 0;
}
