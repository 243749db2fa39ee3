// Checkpoint files: exact round trip, and refusal of every truncation and
// every single changed byte, of other versions and formats.
#include "app/evolve_test_support.hpp"
#include "checkpoint.hpp"
#include "errors.hpp"

#include <catch2/catch.hpp>

using namespace morphogen;
using namespace morphogen::test;

namespace {
std::string run_and_read(const TempDir& tmp);
// A real checkpoint from a tiny run (2 generations of 8 individuals).
std::string tiny_checkpoint(const TempDir& tmp) {
    write_text(tmp.path / "tiny.json", tiny_config(2, 8, 3));
    return run_and_read(tmp);
}
// A smaller one (3 individuals of 30 parameters), so every byte can be changed quickly.
std::string small_checkpoint(const TempDir& tmp) {
    auto config = nlohmann::json::parse(tiny_config(1, 3, 2));
    config["network"] = {{"outputs", 3}, {"hidden", nlohmann::json::array()}};
    write_text(tmp.path / "tiny.json", config.dump());
    return run_and_read(tmp);
}
std::string run_and_read(const TempDir& tmp) {
    const auto run = tmp.path / "run";
    const CliResult r = run_morphogen("evolve '" + (tmp.path / "tiny.json").string() + "' --out '" + run.string() + "'");
    REQUIRE(r.code == 0);
    return read_text(run / "checkpoint.json");
}
}  // namespace

TEST_CASE("a checkpoint round-trips exactly", "[app][checkpoint]") {
    TempDir tmp("checkpoint-roundtrip");
    const std::string text = tiny_checkpoint(tmp);
    const RunState state = load_checkpoint(tmp.path / "run" / "checkpoint.json");
    CHECK(state.ga.births == 24);
    CHECK(state.ga.population.size() == 8);
    CHECK(state.history.size() == 3);
    CHECK(state.seed == 7);
    save_checkpoint(tmp.path / "copy.json", state);
    CHECK(read_text(tmp.path / "copy.json") == text);  // bit-exact doubles, same bytes
    CHECK_FALSE(fs::exists(tmp.path / "copy.json.tmp"));
}

TEST_CASE("every truncation and every single changed byte is refused", "[app][checkpoint]") {
    TempDir tmp("checkpoint-corrupt");
    const std::string text = small_checkpoint(tmp);
    REQUIRE_NOTHROW(checkpoint_content(text, "good"));
    std::size_t refused = 0, tried = 0;
    for (std::size_t length = 0; length < text.size(); length += 7) {
        ++tried;
        try {
            checkpoint_content(text.substr(0, length), "cut");
        } catch (const CheckpointError&) {
            ++refused;
        }
    }
    for (std::size_t i = 0; i < text.size(); ++i) {
        // Every byte with its lowest bit flipped; every 11th also as ' ' and '0'.
        for (char change : {char(text[i] ^ 0x01), ' ', '0'}) {
            if (change == text[i] || (change != char(text[i] ^ 0x01) && i % 11 != 0)) continue;
            std::string bad = text;
            bad[i] = change;
            ++tried;
            try {
                checkpoint_content(bad, "bad");
            } catch (const CheckpointError& e) {
                ++refused;
                if (refused % 997 == 0) CHECK_THAT(e.what(), Catch::Contains("checkpoint"));
            }
        }
    }
    CHECK(refused == tried);

    SECTION("the file itself is never touched by a refusal") {
        const auto path = tmp.path / "run" / "checkpoint.json";
        std::string bad = text;
        bad[text.size() / 3] ^= 0x04;
        write_text(path, bad);
        CHECK_THROWS_AS(load_checkpoint(path), CheckpointError);
        CHECK(read_text(path) == bad);
    }
}

TEST_CASE("other versions and formats and unfitting contents are refused with a reason", "[app][checkpoint]") {
    TempDir tmp("checkpoint-mismatch");
    const std::string text = tiny_checkpoint(tmp);
    nlohmann::json content = checkpoint_content(text, "good");

    nlohmann::json document = nlohmann::json::parse(text);
    document["version"] = 2;
    CHECK_THROWS_WITH(checkpoint_content(document.dump() + "\n", "v2"), Catch::Contains("version 2"));
    document["version"] = 1;
    document["format"] = "something-else";
    CHECK_THROWS_WITH(checkpoint_content(document.dump() + "\n", "f"), Catch::Contains("not a morphogen checkpoint"));

    // Well-formed envelopes around contents that do not fit their own config.
    auto refused = [&](nlohmann::json changed, const std::string& why) {
        write_text(tmp.path / "c.json", checkpoint_text(changed));
        CHECK_THROWS_WITH(load_checkpoint(tmp.path / "c.json"), Catch::Contains("checkpoint") && Catch::Contains(why));
    };
    auto c = content;
    c["config"]["network"]["outputs"] = 5;  // genomes no longer fit the network
    refused(c, "parameters");
    c = content;
    c["config"]["evolution"]["population"] = 9;
    refused(c, "members");
    c = content;
    c["seed"] = 8;
    refused(c, "seed");
    c = content;
    c["config"]["evolution"]["batch"] = 0;
    refused(c, "config is not valid");
    c = content;
    c["history"].erase(1);
    refused(c, "history");
}
