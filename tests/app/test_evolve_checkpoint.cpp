// Checkpoint files: exact round trip, and refusal of every truncation and
// every single changed byte, of other versions and formats, and of contents
// that contradict themselves or lineage.csv though their hash matches.
#include "core/base/errors.hpp"
#include "run/persistence/checkpoint.hpp"
#include "run/persistence/checkpoint_checks.hpp"
#include "core/base/fnv_hash.hpp"
#include "tests/app/evolve_test_support.hpp"
#include "tests/run/search_states.hpp"

#include <catch2/catch.hpp>

#include <functional>
#include <optional>
#include <utility>
#include <vector>

using namespace morphogen;
using namespace morphogen::test;

namespace {
using CheckpointEdits = std::vector<std::pair<std::function<void(nlohmann::json&)>, std::string>>;

// Each edit of `content`, written back with its hash right (checkpoint_text)
// so only the contradiction can refuse it, makes `resume` exit 5 naming
// `why`, leaving checkpoint.json, lineage.csv and history.csv as they were.
void check_edits_refused(const fs::path& run, const nlohmann::json& content, const CheckpointEdits& edits) {
    const std::string lineage = read_text(run / "lineage.csv"), history = read_text(run / "history.csv");
    for (std::size_t i = 0; i < edits.size(); ++i) {
        CAPTURE(i, edits[i].second);
        nlohmann::json changed = content;
        edits[i].first(changed);
        REQUIRE(changed != content);
        const std::string text = checkpoint_text(changed);
        write_text(run / "checkpoint.json", text);
        const CliResult r = run_morphogen("resume " + q(run) + " --generations 2");
        CHECK(r.code == 5);
        CHECK_THAT(r.output, Catch::Contains("checkpoint") && Catch::Contains(edits[i].second));
        CHECK(read_text(run / "checkpoint.json") == text);
        CHECK(read_text(run / "lineage.csv") == lineage);
        CHECK(read_text(run / "history.csv") == history);
    }
}
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
    CHECK(ga_of(state).births == 24);
    CHECK(ga_of(state).population.size() == 8);
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

    // The header line alone (format 2 puts the genomes after it).
    nlohmann::json document = nlohmann::json::parse(text.substr(0, text.find('\n')));
    document["version"] = checkpoint_version + 1;
    CHECK_THROWS_WITH(checkpoint_content(document.dump() + "\n", "next"),
                      Catch::Contains("version " + std::to_string(checkpoint_version + 1) +
                                      " was written by a newer morphogen"));
    document["version"] = 0;
    CHECK_THROWS_WITH(checkpoint_content(document.dump() + "\n", "v0"), Catch::Contains("version 0 is not supported"));
    document["version"] = checkpoint_version;
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

TEST_CASE("a checkpoint that contradicts itself or lineage.csv is refused and left as it was",
          "[app][checkpoint][resume]") {
    TempDir tmp("checkpoint-contradictions");
    write_text(tmp.path / "tiny.json", tiny_config(2, 8, 3));
    const auto run = tmp.path / "run";
    const CliResult made =
        run_morphogen("evolve '" + (tmp.path / "tiny.json").string() + "' --out '" + run.string() + "' --generations 1");
    REQUIRE(made.code == 0);
    const std::string good = read_text(run / "checkpoint.json"), lineage = read_text(run / "lineage.csv");
    const nlohmann::json content = checkpoint_content(good, "good");
    REQUIRE(content["ga"]["births"] == 16);
    const double best = content["ga"]["best"]["fitness"].get<double>();
    std::size_t child = 0;  // a member born after generation 0 (it has parents), not the best
    while (content["ga"]["population"][child]["parent1"].is_null() ||
           content["ga"]["population"][child]["id"] == content["ga"]["best"]["id"])
        ++child;
    // lineage.csv without its last row, and that prefix's hash.
    const std::string shorter = lineage.substr(0, lineage.rfind('\n', lineage.size() - 2) + 1);

    check_edits_refused(run, content, {
        {[](nlohmann::json& c) { c["ga"]["births"] = 19, c["config"]["run"]["generations"] = 2; }, "lineage.csv records 16 births"},
        {[](nlohmann::json& c) { c["ga"]["population"][0]["size"] = -1; }, "not a vertex count"},
        {[](nlohmann::json& c) { c["ga"]["population"][1]["size"] = 2.5; }, "not a vertex count"},
        {[](nlohmann::json& c) { c["ga"]["best"]["size"] = -3; }, "ga.best.size"},
        {[](nlohmann::json& c) { c["elapsed_s"] = -1; }, "elapsed_s is -1"},
        {[](nlohmann::json& c) { c["history"][1]["births"] = 15; }, "history[1].births"},
        {[](nlohmann::json& c) { c["history"][0]["elapsed_s"] = c["elapsed_s"].get<double>() + 1; }, "elapsed_s"},
        {[](nlohmann::json& c) { c["history"][0]["births_per_s"] = -1; }, "births_per_s"},
        {[](nlohmann::json& c) { c["history"][1]["invalid"] = c["history"][1]["invalid"].get<int>() + 1; }, "invalid"},
        {[](nlohmann::json& c) { c["history"][1]["invalid"] = 9; }, "more than the 8 births"},
        {[&](nlohmann::json& c) { c["history"][0]["best"] = best + 1; }, "better than the best individual ever born"},
        {[](nlohmann::json& c) { c["history"][0]["worst"] = c["history"][0]["best"].get<double>() + 1e-3; }, "not in order"},
        {[](nlohmann::json& c) { c["history"][0]["mean"] = nullptr; }, "statistics are missing"},
        {[&](nlohmann::json& c) { c["ga"]["best"]["fitness"] = best + 1; }, "ga.best"},
        {[](nlohmann::json& c) { c["ga"]["best"] = nullptr; }, "ga.best is null"},
        {[](nlohmann::json& c) { c["ga"]["population"][2]["fitness"] = c["ga"]["population"][2]["fitness"].get<double>() - 0.25; },
         "but the population it holds gives"},
        {[](nlohmann::json& c) { c["ga"]["population"][1]["zzz"] = 1; }, "unknown key ga.population[1].zzz"},
        {[](nlohmann::json& c) { c["ga"]["zzz"] = 1; }, "unknown key ga.zzz"},
        {[](nlohmann::json& c) { c["history"][1]["zzz"] = 1; }, "unknown key history[1].zzz"},
        {[](nlohmann::json& c) { c["history"][0]["mean"] = c["history"][0]["mean"].get<double>() + 1e-9; },
         "history[0].mean is"},
        {[&](nlohmann::json& c) { c["ga"]["population"][child]["parent2"] = nullptr, c["ga"]["population"][child]["parent1"] = nullptr; },
         "differs from its lineage.csv row"},
        {[&](nlohmann::json& c) { c["lineage"] = {{"bytes", shorter.size()}, {"hash", fnv1a64_hex(shorter)}}; },
         "lineage.csv records 15 births"},
        {[](nlohmann::json& c) { c["lineage"]["hash"] = "ABCDEF0123456789"; }, "hex"},
        {[](nlohmann::json& c) { c["lineage"]["bytes"] = 3; }, "header"},
        {[](nlohmann::json& c) { c["config"]["run"]["generations"] = 0; }, "beyond"},
    });
    write_text(run / "checkpoint.json", good);  // the untouched checkpoint still resumes
    CHECK(run_morphogen("resume '" + run.string() + "' --generations 2").code == 0);
}

TEST_CASE("a pipeline checkpoint keeps its births in flight; damaged ones are refused", "[app][checkpoint][pipeline]") {
    TempDir tmp("checkpoint-pending");
    write_text(tmp.path / "pipe.json", tiny_pipeline_config(2, 8, 5));
    const auto run = tmp.path / "run";
    REQUIRE(run_morphogen("evolve " + q(tmp.path / "pipe.json") + " --out " + q(run) + " --generations 1").code == 0);
    const std::string good = read_text(run / "checkpoint.json");
    const nlohmann::json content = checkpoint_content(good, "good");
    // After 16 births with lag 5, births 16..19 were conceived from earlier states.
    REQUIRE(content["pending"].size() == 4);
    CHECK(content["pending"][0]["id"] == 16);
    CHECK(content["pending"][3]["id"] == 19);
    CHECK(content["pending"][0]["fitness"].is_null());

    check_edits_refused(run, content, {
        {[](nlohmann::json& c) { c["pending"].erase(3); }, "pending holds 3 births"},
        {[](nlohmann::json& c) { c.erase("pending"); }, "pending holds 0 births"},
        {[](nlohmann::json& c) { c["pending"] = nlohmann::json::array(); }, "pending births"},
        {[](nlohmann::json& c) { c["pending"][1]["id"] = 21; }, "pending[1] is birth 21"},
        {[](nlohmann::json& c) { c["pending"][2]["fitness"] = 1.5; }, "before its evaluation"},
        {[](nlohmann::json& c) { c["pending"][0]["parent1"] = 13; }, "conceived from"},
        {[](nlohmann::json& c) { c["pending"][0]["params"].erase(0); }, "parameters"},
        {[](nlohmann::json& c) { c["pending"][0]["zzz"] = 1; }, "unknown key pending[0].zzz"},
    });
    // The untouched checkpoint resumes to the uninterrupted run's bytes.
    write_text(run / "checkpoint.json", good);
    REQUIRE(run_morphogen("resume " + q(run) + " --generations 2").code == 0);
    REQUIRE(run_morphogen("evolve " + q(tmp.path / "pipe.json") + " --out " + q(tmp.path / "whole")).code == 0);
    check_same_results(tmp.path / "whole", run);
}

TEST_CASE("forged parents of pending births are refused: re-drawn from the population lineage.csv replays",
          "[app][checkpoint][pipeline]") {
    TempDir tmp("checkpoint-pending-parents");
    auto config = nlohmann::json::parse(tiny_pipeline_config(3, 8, 5));
    config["evolution"]["crossover"] = 0.7;  // most children have two parents
    write_text(tmp.path / "pipe.json", config.dump());
    const auto run = tmp.path / "run";
    REQUIRE(run_morphogen("evolve " + q(tmp.path / "pipe.json") + " --out " + q(run) + " --generations 2").code == 0);
    const std::string good = read_text(run / "checkpoint.json");
    const nlohmann::json content = checkpoint_content(good, "good");
    const nlohmann::json& pending = content["pending"];
    REQUIRE(pending.size() == 4);
    std::optional<std::size_t> crossed;
    for (std::size_t i = 0; i < pending.size(); ++i)
        if (!crossed && !pending[i]["parent2"].is_null() && pending[i]["parent1"] != pending[i]["parent2"]) crossed = i;
    REQUIRE(crossed);
    std::optional<std::size_t> other;  // a birth whose parents differ from pending[crossed]'s
    for (std::size_t i = 0; i < pending.size(); ++i)
        if (i != *crossed && (pending[i]["parent1"] != pending[*crossed]["parent1"] ||
                              pending[i]["parent2"] != pending[*crossed]["parent2"]))
            other = i;
    REQUIRE(other);
    const std::size_t k = *crossed, m = *other;
    const std::uint64_t gone = pending[0]["parent1"] == 0 ? 1 : 0;
    check_edits_refused(run, content, {
        {[](nlohmann::json& c) {
             c["pending"][0]["parent1"] = nullptr;
             c["pending"][0]["parent2"] = nullptr;
         }, "has parents null, null"},
        {[gone](nlohmann::json& c) { c["pending"][0]["parent1"] = gone; }, "has parents " + std::to_string(gone)},
        {[k](nlohmann::json& c) { std::swap(c["pending"][k]["parent1"], c["pending"][k]["parent2"]); }, "has parents"},
        {[k, m](nlohmann::json& c) {
             std::swap(c["pending"][k]["parent1"], c["pending"][m]["parent1"]);
             std::swap(c["pending"][k]["parent2"], c["pending"][m]["parent2"]);
         }, "the population lineage.csv records"},
    });
    write_text(run / "checkpoint.json", good);
    REQUIRE(run_morphogen("resume " + q(run) + " --generations 3").code == 0);
    REQUIRE(run_morphogen("evolve " + q(tmp.path / "pipe.json") + " --out " + q(tmp.path / "whole")).code == 0);
    check_same_results(tmp.path / "whole", run);
}

namespace {
// A MAP-Elites run of population 10 with `keys` added to its config, stopped
// at generation `stop` of `total`, and its checkpoint.
struct StoppedElitesRun {
    TempDir tmp{"me-pending"};
    fs::path run = tmp.path / "run";
    std::uint64_t total;
    std::string good;
    nlohmann::json content;
    StoppedElitesRun(const std::string& keys, std::uint64_t stop, std::uint64_t total_generations)
        : total(total_generations) {
        write_text(tmp.path / "me.json", R"({"network": {"outputs": 4, "hidden": [5]},
            "growth": {"steps": 12, "max_vertices": 300}, "fitness": {"type": "canopy", "height": 1, "cell": 0.1},
            "descriptors": [{"measure": "height", "min": 0, "max": 3, "bins": 6},
                            {"measure": "footprint", "min": 0, "max": 10, "bins": 5}],
            "archive": {"type": "grid"}, )" + keys + "}");
        REQUIRE(run_morphogen("evolve " + q(tmp.path / "me.json") + " --out " + q(run) + " --generations " +
                              std::to_string(stop) + " --no-report")
                    .code == 0);
        good = read_text(run / "checkpoint.json");
        content = checkpoint_content(good, "good");
        REQUIRE(content["pending"].size() >= 2);
    }
    // The genuine checkpoint back, resumed to the end: the uninterrupted run's lineage.csv.
    void finish() const {
        write_text(run / "checkpoint.json", good);
        REQUIRE(run_morphogen("resume " + q(run) + " --generations " + std::to_string(total) + " --no-report").code == 0);
        REQUIRE(run_morphogen("evolve " + q(tmp.path / "me.json") + " --out " + q(tmp.path / "whole") +
                              " --generations " + std::to_string(total) + " --no-report")
                    .code == 0);
        CHECK(read_text(run / "lineage.csv") == read_text(tmp.path / "whole" / "lineage.csv"));
    }
};
}  // namespace

TEST_CASE("forged parents of MAP-Elites' pending births are refused: a CMA emitter's children share its origin",
          "[app][checkpoint][map_elites]") {
    // The default emitters (two cma_me), stopped at generation 10.
    const StoppedElitesRun made(R"("evolution": {"algorithm": "map_elites", "population": 10}, "run": {"seed": 3})",
                                10, 20);
    const nlohmann::json& pending = made.content["pending"];
    // pending[0] and the first child of the other emitter: parents that
    // both came before both sources, so only their emitters' states tell.
    std::size_t other = 1;
    while (other < pending.size() && pending[other]["parent1"] == pending[0]["parent1"]) ++other;
    REQUIRE(other < pending.size());
    check_edits_refused(made.run, made.content, {
        {[](nlohmann::json& c) { c["pending"][0]["parent1"] = nullptr; }, "conceived from the same state of that emitter"},
        {[](nlohmann::json& c) { c["pending"][0]["parent1"] = 0; }, "has parent"},
        {[other](nlohmann::json& c) { std::swap(c["pending"][0]["parent1"], c["pending"][other]["parent1"]); },
         "conceived from the same state of that emitter"},
        {[](nlohmann::json& c) { c["pending"][0]["parent2"] = c["pending"][0]["parent1"]; }, "one parent, its origin"},
    });
    made.finish();
}

TEST_CASE("forged parents of pending gaussian and iso-line births are refused: re-drawn from the replayed archive",
          "[app][checkpoint][map_elites]") {
    const StoppedElitesRun made(R"("evolution": {"algorithm": "map_elites", "population": 10, "crossover": 0.5},
        "emitters": [{"kind": "gaussian", "selection": "fitness_proportional"}, {"kind": "iso_line"}],
        "run": {"seed": 5})", 6, 12);
    const nlohmann::json& pending = made.content["pending"];
    std::size_t other = 1;  // a birth with other parents than pending[0]'s
    while (other < pending.size() && pending[other]["parent1"] == pending[0]["parent1"] &&
           pending[other]["parent2"] == pending[0]["parent2"])
        ++other;
    REQUIRE(other < pending.size());
    const std::string redrawn = "the archive lineage.csv records at its source state gives";
    check_edits_refused(made.run, made.content, {
        {[](nlohmann::json& c) { c["pending"][0]["parent1"] = nullptr; c["pending"][0]["parent2"] = nullptr; }, redrawn},
        {[other](nlohmann::json& c) {
             std::swap(c["pending"][0]["parent1"], c["pending"][other]["parent1"]);
             std::swap(c["pending"][0]["parent2"], c["pending"][other]["parent2"]);
         }, "pending["},
    });
    made.finish();
}

TEST_CASE("invalid births and the best are checked against lineage.csv", "[app][checkpoint]") {
    // Two generations of two: births 1 and 3 invalid, birth 2 the best.
    auto born = [](std::uint64_t id, std::optional<std::uint64_t> parent, double fitness) {
        Individual ind;
        ind.id = id;
        ind.parent1 = parent;
        ind.fitness = fitness;
        ind.size = 12;
        ind.params = {0.5};
        return ind;
    };
    const std::vector<Individual> births{born(0, {}, 1.0), born(1, {}, invalid_fitness), born(2, 0, 2.0),
                                         born(3, 2, invalid_fitness)};
    std::string lineage = lineage_header;
    for (const Individual& ind : births) lineage += format_lineage_row(ind);
    RunState state;
    ga_of(state).births = 4;
    ga_of(state).population = {births[2], births[0]};
    ga_of(state).best = births[2];
    for (std::uint64_t g = 0; g < 2; ++g) {
        HistoryRow row;
        row.generation = g;
        row.births = 2 * (g + 1);
        row.invalid = 1;
        // what the population held at the generation's end: {1} then {1, 2}
        row.best = g == 0 ? 1.0 : 2.0;
        row.mean = row.median = g == 0 ? 1.0 : 1.5;
        row.worst = 1.0;
        state.history.push_back(row);
    }
    REQUIRE_NOTHROW(check_checkpoint_against_lineage(state, lineage, 2));

    RunState bad = state;
    bad.history[0].invalid = 0;
    CHECK_THROWS_WITH(check_checkpoint_against_lineage(bad, lineage, 2),
                      Catch::Contains("history[0].invalid is 0, lineage.csv records 1"));
    bad = state;
    ga_of(bad).best = births[0];
    CHECK_THROWS_WITH(check_checkpoint_against_lineage(bad, lineage, 2), Catch::Contains("not the first birth"));
    bad = state;
    ga_of(bad).best.reset();
    CHECK_THROWS_WITH(check_checkpoint_against_lineage(bad, lineage, 2), Catch::Contains("ga.best is null"));
    CHECK_THROWS_WITH(check_checkpoint_against_lineage(state, lineage + "4,4,2,,2\n", 2),
                      Catch::Contains("records 5 births"));
    // A later birth as good as the best does not replace it (earliest on ties).
    RunState later = state;
    ga_of(later).births = 5;
    CHECK_NOTHROW(check_checkpoint_against_lineage(later, lineage + format_lineage_row(born(4, 2, 2.0)), 2));
    ga_of(later).invalid_in_generation = 1;
    CHECK_THROWS_WITH(check_checkpoint_against_lineage(later, lineage + format_lineage_row(born(4, 2, 2.0)), 2),
                      Catch::Contains("invalid_in_generation"));
}

TEST_CASE("lineage.csv with descriptor columns is checked against the checkpoint", "[app][checkpoint]") {
    auto born = [](std::uint64_t id, double fitness, std::vector<double> descriptors) {
        Individual ind;
        ind.id = id;
        ind.fitness = fitness;
        ind.size = 12;
        ind.params = {0.5};
        ind.descriptors = std::move(descriptors);
        return ind;
    };
    const std::vector<Individual> births{born(0, 1.0, {1.5, 2}), born(1, invalid_fitness, {}), born(2, 2.0, {3, 0.25})};
    const std::string header = lineage_header_for({"height", "footprint"});
    std::string lineage = header;
    for (const Individual& ind : births) lineage += format_lineage_row(ind, 2);
    // a GA's state keeps no descriptors: its members are compared up to the fitness
    RunState state;
    ga_of(state).births = 3;
    ga_of(state).population = {births[2], births[0], births[1]};
    for (Individual& member : ga_of(state).population) member.descriptors.clear();
    ga_of(state).best = ga_of(state).population[0];
    ga_of(state).invalid_in_generation = 1;
    REQUIRE_NOTHROW(check_checkpoint_against_lineage(state, lineage, 3, header));
    // the header must be the config's
    CHECK_THROWS_WITH(check_checkpoint_against_lineage(state, lineage, 3), Catch::Contains("does not start with its header"));
    CHECK_THROWS_WITH(check_checkpoint_against_lineage(state, lineage, 3, lineage_header_for({"height"})),
                      Catch::Contains("does not start with its header"));
    // every row has the header's cells
    std::string short_row = lineage;
    short_row.replace(short_row.find(",3,0.25\n"), 7, ",3\n");
    CHECK_THROWS_WITH(check_checkpoint_against_lineage(state, short_row, 3, header),
                      Catch::Contains("lineage.csv row 3 does not have 7 cells"));
    // the fitness is the fifth cell, not the last
    RunState worse = state;
    ga_of(worse).population[0].fitness = 0.25;
    ga_of(worse).best = ga_of(worse).population[0];
    CHECK_THROWS_WITH(check_checkpoint_against_lineage(worse, lineage, 3, header),
                      Catch::Contains("differs from its lineage.csv row"));
    // a member that keeps its descriptors (a MAP-Elites elite) is compared with them
    RunState kept = state;
    ga_of(kept).population[1].descriptors = {1.5, 2};
    CHECK_NOTHROW(check_checkpoint_against_lineage(kept, lineage, 3, header));
    ga_of(kept).population[1].descriptors = {1.5, 2.5};
    CHECK_THROWS_WITH(check_checkpoint_against_lineage(kept, lineage, 3, header),
                      Catch::Contains("ga.population[1] (id 0) differs from its lineage.csv row"));
}
