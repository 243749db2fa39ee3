// The size of a large checkpoint (run/persistence/checkpoint.hpp): 10,000
// elites of the default network, written and read back whole.
#include "core/base/atomic_file.hpp"
#include "run/persistence/checkpoint.hpp"
#include "tests/run/checkpoint_states.hpp"
#include "tests/run/search_states.hpp"
#include "tests/support/temp_dir.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace morphogen;
using namespace morphogen::test;
using morphogen::testing::TempDir;

TEST_CASE("an archive of 10,000 elites of the default network checkpoints in under 200 MB", "[run][checkpoint][limits]") {
    const RunState state = generation0_state(archive_config(20000), 10000);
    REQUIRE(elites_of(state).archive.occupied() == 10000);
    const std::size_t D = elites_of(state).best->params.size();
    REQUIRE(D == 1845);  // 18.45 M parameters in the archive
    const std::string bytes = checkpoint_bytes(state);
    const std::size_t header = header_end(bytes) + 1;
    CHECK(bytes.size() - header == 10001 * D * 8);  // the elites and the best ever, 8 bytes per parameter
    CHECK(header < 4'000'000);                      // ids, cells, descriptors, fitness: < 400 bytes per elite
    CHECK(bytes.size() < 200'000'000);
    // It is a checkpoint load_checkpoint accepts, holding the same state.
    TempDir tmp("ckpt2-size");
    write_file_atomically(tmp.path / "checkpoint.json", bytes);
    const RunState loaded = load_checkpoint(tmp.path / "checkpoint.json");
    CHECK(elites_of(loaded).archive.occupied() == 10000);
    CHECK(same_bits(elites_of(loaded).archive.elites().rbegin()->second.params,
                    elites_of(state).archive.elites().rbegin()->second.params));
    CHECK(checkpoint_bytes(loaded) == bytes);
}
