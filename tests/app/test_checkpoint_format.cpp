// Checkpoint format 2 (run/persistence/checkpoint.hpp): genomes as exact little-endian
// doubles after the JSON header line. Exact bits, format-1 files still loading
// and resuming, refusal of every damaged byte of the binary part and of
// contradicting genome references (the states from
// tests/run/checkpoint_states.hpp; their size: tests/run/, their timings:
// tests/bench/).
#include "core/base/atomic_file.hpp"
#include "core/base/errors.hpp"
#include "evolution/ga/ga_state_json.hpp"
#include "evolution/schedulers/map_elites_state_json.hpp"
#include "core/growth/network/network.hpp"
#include "run/persistence/checkpoint.hpp"
#include "run/config/experiment_config.hpp"
#include "run/loop/run_records.hpp"
#include "tests/app/evolve_test_support.hpp"
#include "tests/run/checkpoint_states.hpp"
#include "tests/run/search_states.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>
#include <iostream>
#include <limits>
#include <random>

using namespace morphogen;
using namespace morphogen::test;

namespace {
// A tiny run's checkpoint (3 individuals of 30 parameters), its run directory at tmp/run.
std::string small_run(const TempDir& tmp, int generations = 1) {
    auto config = nlohmann::json::parse(tiny_config(generations, 3, 2));
    config["network"] = {{"outputs", 3}, {"hidden", nlohmann::json::array()}};
    write_text(tmp.path / "small.json", config.dump());
    REQUIRE(run_morphogen("evolve " + q(tmp.path / "small.json") + " --out " + q(tmp.path / "run") +
                          " --generations " + std::to_string(generations))
                .code == 0);
    return read_text(tmp.path / "run" / "checkpoint.json");
}

}  // namespace

TEST_CASE("format 2 keeps every genome's exact bits, -0.0, denormals and 1e308 included", "[app][checkpoint]") {
    TempDir tmp("ckpt2-bits");
    const std::string bytes = small_run(tmp);
    const fs::path path = tmp.path / "run" / "checkpoint.json";
    RunState state = load_checkpoint(path);
    REQUIRE(ga_of(state).population.size() == 3);
    const std::vector<double> special{-0.0,
                                      0.0,
                                      std::numeric_limits<double>::denorm_min(),
                                      -std::numeric_limits<double>::denorm_min(),
                                      2.2250738585072009e-308,  // the largest denormal
                                      std::numeric_limits<double>::min(),
                                      1e308,
                                      -1e308,
                                      std::numeric_limits<double>::max(),
                                      0.1,
                                      1.0 / 3.0,
                                      std::nextafter(1.0, 2.0)};
    std::size_t member = 0;  // one that is not the best (the best must equal its copy in the population)
    while (ga_of(state).population[member].id == ga_of(state).best->id) ++member;
    std::vector<double>& params = ga_of(state).population[member].params;
    REQUIRE(params.size() == 30);
    std::copy(special.begin(), special.end(), params.begin());
    save_checkpoint(path, state);
    const std::string saved = read_text(path);

    const RunState loaded = load_checkpoint(path);
    CHECK(same_bits(ga_of(loaded).population[member].params, params));
    CHECK(std::signbit(ga_of(loaded).population[member].params[0]));
    for (std::size_t i = 0; i < ga_of(state).population.size(); ++i)
        CHECK(same_bits(ga_of(loaded).population[i].params, ga_of(state).population[i].params));
    CHECK(same_bits(ga_of(loaded).best->params, ga_of(state).best->params));
    CHECK(checkpoint_bytes(loaded) == saved);  // the same bytes again

    // The layout: a JSON header line, then count x dimension x 8 bytes, the genomes in order.
    const auto header = nlohmann::json::parse(saved.substr(0, header_end(saved)));
    CHECK(header["version"] == checkpoint_version);
    CHECK(header["genomes"] == nlohmann::json{{"count", 4}, {"dimension", 30}, {"encoding", "f64le"}});
    CHECK(saved.size() - header_end(saved) - 1 == 4 * 30 * 8);
    const std::uint64_t k = header["content"]["ga"]["population"][member]["genome"].get<std::uint64_t>();
    std::uint64_t first = 0;
    std::memcpy(&first, saved.data() + header_end(saved) + 1 + k * 30 * 8, 8);
    if constexpr (std::endian::native == std::endian::little) CHECK(first == std::bit_cast<std::uint64_t>(-0.0));
    CHECK_FALSE(saved.substr(0, header_end(saved)).find("\"params\"") != std::string::npos);
    // The tools' view has them inline again, bit-exact through JSON's shortest round-trip form.
    const nlohmann::json inline_content = checkpoint_content(saved, "t");
    std::vector<double> from_json = inline_content["ga"]["population"][member]["params"];
    CHECK(same_bits(from_json, params));
}

TEST_CASE("a format-1 checkpoint (previous builds) loads and resumes; the next save writes the current format",
          "[app][checkpoint][resume]") {
    TempDir tmp("ckpt2-v1");
    const std::string v2 = small_run(tmp, 1);
    const fs::path run = tmp.path / "run", path = run / "checkpoint.json";
    const RunState state = load_checkpoint(path);
    const std::string v1 = format1_text(state);
    REQUIRE(v1 == checkpoint_text(checkpoint_content(v2, "t")));  // the same content, format 1
    REQUIRE(v1.find("\"version\":1") != std::string::npos);
    REQUIRE(v1.find("\"params\":[") != std::string::npos);
    write_text(path, v1);
    const RunState from_v1 = load_checkpoint(path);
    CHECK(checkpoint_bytes(from_v1) == v2);  // same state as the format-2 file holds
    CHECK(checkpoint_content(v1, "t") == checkpoint_content(v2, "t"));

    // Resumed from format 1 to the end: the same results as a run never stopped, saved in the current format.
    REQUIRE(run_morphogen("resume " + q(run) + " --generations 3").code == 0);
    const std::string after = read_text(path);
    CHECK(nlohmann::json::parse(after.substr(0, header_end(after)))["version"] == checkpoint_version);
    write_text(tmp.path / "whole.json", read_text(tmp.path / "small.json"));
    REQUIRE(run_morphogen("evolve " + q(tmp.path / "whole.json") + " --out " + q(tmp.path / "whole") +
                          " --generations 3")
                .code == 0);
    check_same_results(tmp.path / "whole", run);
    CHECK_FALSE(fs::exists(run / "checkpoint.json.tmp"));
}

TEST_CASE("every truncation and changed byte of the binary part is refused; the file is left as it was",
          "[app][checkpoint]") {
    TempDir tmp("ckpt2-damage");
    const std::string good = small_run(tmp);
    const std::size_t start = header_end(good) + 1;
    REQUIRE(good.size() - start == 4 * 30 * 8);
    auto refused = [](const std::string& bytes) {
        try {
            checkpoint_content(bytes, "bad");
        } catch (const CheckpointError&) {
            return true;
        }
        return false;
    };
    std::size_t accepted = 0;
    for (std::size_t length = start - 1; length < good.size(); ++length) accepted += !refused(good.substr(0, length));
    for (std::size_t i = start - 1; i < good.size(); ++i)
        for (unsigned char bit : {0x01, 0x80}) {
            std::string bad = good;
            bad[i] = static_cast<char>(bad[i] ^ bit);
            accepted += !refused(bad);
        }
    accepted += !refused(good + '\0');  // a byte too many
    accepted += !refused(good + std::string(240, '\0'));  // a whole genome too many
    CHECK(accepted == 0);

    // Through resume: exit 5, one line with the reason, the file byte-identical.
    const fs::path path = tmp.path / "run" / "checkpoint.json";
    for (const auto& [bytes, why] : std::vector<std::pair<std::string, std::string>>{
             {good.substr(0, good.size() - 3), "truncated"},
             {good.substr(0, start), "truncated"},
             {good.substr(0, start - 1), "truncated"},
             {good.substr(0, start + 100) + char(good[start + 100] ^ 0x10) + good.substr(start + 101), "hash"}}) {
        write_text(path, bytes);
        const CliResult r = run_morphogen("resume " + q(tmp.path / "run") + " --generations 2");
        INFO(r.output);
        CHECK(r.code == 5);
        CHECK_THAT(r.output, Catch::Contains("checkpoint " + path.string() + " refused") && Catch::Contains(why));
        CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
        CHECK(read_text(path) == bytes);
    }
    write_text(path, good);
    CHECK(run_morphogen("resume " + q(tmp.path / "run") + " --generations 2").code == 0);
}

TEST_CASE("format 2's genome references and binary part must fit; contradictions are refused with the reason",
          "[app][checkpoint]") {
    TempDir tmp("ckpt2-refs");
    const std::string good = small_run(tmp);
    const CheckpointParts parts = checkpoint_parts(good, "good");
    REQUIRE(checkpoint_bytes(parts) == good);
    REQUIRE(parts.count == 4);
    REQUIRE(parts.dimension == 30);
    const fs::path path = tmp.path / "run" / "checkpoint.json";
    auto refused = [&](const std::string& bytes, const std::string& why) {
        write_text(path, bytes);
        CHECK_THROWS_WITH(load_checkpoint(path), Catch::Contains("checkpoint") && Catch::Contains(why));
        const CliResult r = run_morphogen("resume " + q(tmp.path / "run") + " --generations 2");
        CHECK(r.code == 5);
        CHECK_THAT(r.output, Catch::Contains(why));
        CHECK(read_text(path) == bytes);
    };
    auto sealed = [&](const std::function<void(CheckpointParts&)>& edit) {
        CheckpointParts changed = parts;
        edit(changed);
        return checkpoint_bytes(changed);
    };
    auto population = [](CheckpointParts& p) -> nlohmann::json& { return p.content["ga"]["population"]; };
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    auto put = [](CheckpointParts& p, std::size_t at, double value) { std::memcpy(p.genomes.data() + at, &value, 8); };

    refused(sealed([&](CheckpointParts& p) { population(p)[1]["genome"] = population(p)[0]["genome"]; }), "used twice");
    refused(sealed([&](CheckpointParts& p) { population(p)[0]["genome"] = 4; }), "genome 4 does not exist");
    refused(sealed([&](CheckpointParts& p) { population(p)[0]["genome"] = -1; }), "ga.population[0].genome");
    refused(sealed([&](CheckpointParts& p) { population(p)[0]["params"] = nlohmann::json::array({1.0}); }),
            "binary part");
    refused(sealed([&](CheckpointParts& p) {
                p.genomes += std::string(30 * 8, '\0');
                p.count = 5;
            }),
            "1 of its 5 genomes belong to no individual");
    refused(sealed([&](CheckpointParts& p) { put(p, 8 * 31, nan); }), "not finite");
    refused(sealed([&](CheckpointParts& p) { put(p, 8 * 119, -inf); }), "not finite");
    refused(sealed([&](CheckpointParts& p) {
                p.genomes.resize(4 * 29 * 8);
                p.dimension = 29;
            }),
            "its genomes have 29 parameters, its network 30");
    refused(sealed([&](CheckpointParts& p) { p.count = 3; }), "the header announces 3 genomes");
    std::string encoding = good;
    encoding.replace(encoding.find("\"f64le\""), 7, "\"f32le\"");
    refused(encoding, "\"genomes\" is not");
    std::string zero = sealed([&](CheckpointParts& p) {
        p.content["ga"]["population"] = nlohmann::json::array();
        p.content["ga"]["best"] = nullptr;
        p.genomes.clear();
        p.count = 0;
        p.dimension = 0;
    });
    zero.replace(zero.find("\"dimension\":0"), 13, "\"dimension\":7");  // no genome, yet a dimension
    refused(zero, "truncated or corrupt");

    write_text(path, good);
    CHECK(run_morphogen("resume " + q(tmp.path / "run") + " --generations 2").code == 0);
}
