// A run directory written before growth's signal switches were always
// resolved (format 2 as first written) resumes through the config migration
// (run/config/config_migration.hpp) with the same results as a whole run.
#include "run/persistence/checkpoint.hpp"
#include "tests/app/evolve_test_support.hpp"
#include "tests/support/temp_dir.hpp"

#include <catch2/catch.hpp>

using namespace morphogen;
using nlohmann::json;

TEST_CASE("a run directory written before the signal switches were resolved resumes, with the same results",
          "[app][config][migration][checkpoint]") {
    using namespace morphogen::test;
    TempDir tmp("signal-switches");
    json config = json::parse(tiny_config(1, 6, 3));
    config["growth"]["mode"] = "branching";
    config["network"]["outputs"] = 7;  // the branching mode's least
    write_text(tmp.path / "c.json", config.dump());
    const std::string evolve = "evolve " + q(tmp.path / "c.json") + " --no-report --out ";
    REQUIRE(run_morphogen(evolve + q(tmp.path / "run")).code == 0);
    REQUIRE(run_morphogen(evolve + q(tmp.path / "whole") + " --generations 2").code == 0);
    // The run directory as the build before wrote it: both switches left out.
    const fs::path config_file = tmp.path / "run" / "config.json", checkpoint = tmp.path / "run" / "checkpoint.json";
    json stored = json::parse(read_text(config_file));
    REQUIRE(stored["growth"]["exposure"] == false);
    stored["growth"].erase("exposure");
    stored["growth"].erase("signal_diffusion");
    write_text(config_file, stored.dump(2) + "\n");
    CheckpointParts parts = checkpoint_parts(read_text(checkpoint), "run");
    parts.content["config"]["growth"].erase("exposure");
    parts.content["config"]["growth"].erase("signal_diffusion");
    write_text(checkpoint, checkpoint_bytes(parts));

    const CliResult resumed = run_morphogen("resume " + q(tmp.path / "run") + " --no-report --generations 2");
    INFO(resumed.output);
    REQUIRE(resumed.code == 0);
    const json written = json::parse(read_text(config_file));
    CHECK(written["growth"]["exposure"] == false);
    CHECK(written["growth"]["signal_diffusion"] == 0);
    check_same_results(tmp.path / "run", tmp.path / "whole");
}
