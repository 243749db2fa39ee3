// Fuzz target "config": the bytes as an experiment config, read the way
// `morphogen validate` reads one (core/base/config_reader.hpp parse_json_text, then
// run/config/experiment_config.hpp read_experiment_config, then the seed check).
#include "core/base/config_reader.hpp"
#include "fuzz/fuzz_target.hpp"
#include "core/growth/seeds/seeds.hpp"
#include "run/config/experiment_config.hpp"

namespace morphogen::fuzz {
std::string input_from_file(const std::string&, std::string bytes) { return bytes; }
}  // namespace morphogen::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace morphogen;
    using namespace morphogen::fuzz;
    const std::string text(as_text(data, size));
    ExperimentConfig config;
    const bool valid = accepts([&] {
        config = read_experiment_config(parse_json_text(text, "fuzz.json"), "fuzz.json");
        // validate also builds the seed. Only a built-in one here: a seed file
        // path would make the fuzzer read arbitrary files (/dev/zero never ends).
        if (is_builtin_seed(config.growth.seed_mesh))
            (void)make_seed(config.growth);
    });
    if (!valid) return 0;
    // A checkpoint stores the resolved config and refuses one that does not
    // read back to itself, so every valid config must resolve to a fixed point.
    ExperimentConfig again;
    if (!accepts([&] { again = read_experiment_config(config.resolved, "resolved config"); }))
        finding("the resolved form of a valid config is refused: " + config.resolved.dump());
    if (again.resolved != config.resolved)
        finding("reading a resolved config changes it: " + config.resolved.dump() + " -> " + again.resolved.dump());
    return 0;
}
