#include "core/base/errors.hpp"
#include "core/growth/genome_io.hpp"
#include "core/growth/network/network.hpp"
#include "core/growth/network/network_kernel.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/test_genomes.hpp"

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace morphogen;
using namespace morphogen::testing;

TEST_CASE("genome layout: sizes and neuron blocks", "[network]") {
    const std::vector<int> layers = layer_sizes(15, std::vector<int>{30});
    CHECK(layers == std::vector<int>{45, 30, 15});
    CHECK(parameter_count(layers) == 1845);
    const auto blocks = neuron_blocks(layers);
    REQUIRE(blocks.size() == 45);
    CHECK(blocks[0] == std::pair<std::size_t, std::size_t>{0, 46});
    CHECK(blocks[30] == std::pair<std::size_t, std::size_t>{30 * 46, 31});
    CHECK(blocks.back().first + blocks.back().second == 1845);
    CHECK(parameter_count(std::vector<int>{9, 3}) == 30);
}

TEST_CASE("batched evaluation agrees with the paper's pseudocode to 1e-12", "[network]") {
    const std::vector<std::vector<int>> shapes{{45, 30, 15}, {9, 3}, {12, 7, 5, 4}, {30, 1, 10}};
    for (const auto& layers : shapes) {
        for (std::uint64_t seed = 1; seed <= 10; ++seed) {
            const Network network(random_test_genome(layers, seed, 3.0));
            RandomStream rng(seed, 99);
            const int V = 1 + static_cast<int>(rng.below(200));
            Eigen::MatrixXd inputs(layers.front(), V);
            for (Eigen::Index i = 0; i < inputs.size(); ++i) inputs.data()[i] = rng.uniform(-0.5, 1.5);
            Eigen::MatrixXd outputs(layers.back(), V);
            NetworkWorkspace workspace;
            network.evaluate({inputs.data(), static_cast<std::size_t>(inputs.size())},
                             {outputs.data(), static_cast<std::size_t>(outputs.size())}, workspace);
            for (int v = 0; v < V; ++v) {
                const std::vector<double> column(inputs.col(v).data(), inputs.col(v).data() + layers.front());
                const std::vector<double> expected = network.evaluate_reference(column);
                for (int j = 0; j < layers.back(); ++j) {
                    REQUIRE(std::abs(outputs(j, v) - expected[j]) <= 1e-12);
                    REQUIRE(outputs(j, v) > 0.0);
                    REQUIRE(outputs(j, v) < 1.0);
                }
            }
        }
    }
}

TEST_CASE("the reference evaluation is the pseudocode", "[network]") {
    // One neuron, two inputs: sigmoid(-t + (x0 - .5) w0 + (x1 - .5) w1).
    const Network network(Genome{{2, 1}, {0.7, -1.3, 0.25}});
    const double a = -0.25 + (0.9 - 0.5) * 0.7 + (0.1 - 0.5) * -1.3;
    const std::vector<double> out = network.evaluate_reference(std::vector<double>{0.9, 0.1});
    CHECK(out[0] == Approx(1.0 / (1.0 + std::exp(-a))).epsilon(1e-15));
}

TEST_CASE("the kernel's sigmoid is accurate to a few ulp over the whole range", "[network]") {
    // Against 1 / (1 + e^-a) in long double, on a step that is no round number.
    double worst_absolute = 0.0, worst_relative = 0.0;
    for (double a = -800.0; a <= 800.0; a += 0.0123456789) {
        const long double exact = 1.0L / (1.0L + std::exp(-static_cast<long double>(a)));
        const double error = std::abs(static_cast<double>(kernel::sigmoid_vectorizable(a) - exact));
        worst_absolute = std::max(worst_absolute, error);
        // Relative accuracy wherever the sigmoid exceeds 1e-30 (a > -69):
        // rounding b = -a log2(e) to a double costs up to half an ulp of
        // |b| <= 100 there (7e-15 absolute in b, 5e-15 relative here).
        if (a > -69.0) worst_relative = std::max(worst_relative, error / static_cast<double>(exact));
    }
    CHECK(worst_absolute <= 4e-16);  // measured 1.6e-16
    CHECK(worst_relative <= 1e-14);  // measured 5.9e-15 at a = -58.8
    // The clamps: far beyond +-700 the result is still exact to the last bit that matters.
    CHECK(kernel::sigmoid_vectorizable(1e6) == 1.0);
    CHECK(kernel::sigmoid_vectorizable(-1e6) >= 0.0);
    CHECK(kernel::sigmoid_vectorizable(-1e6) < 1e-300);
}

TEST_CASE("a network refuses a genome that does not fit its layers", "[network]") {
    CHECK_THROWS_AS(Network(Genome{{45, 30, 15}, std::vector<double>(100, 0.0)}), ConfigError);
    Genome nan = random_test_genome({9, 3}, 1);
    nan.params[4] = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(Network(nan), Catch::Contains("parameter 4"));
    CHECK_THROWS_AS(Network(Genome{{9}, {}}), ConfigError);
    // Finite, but the folded bias (and the kernel's scaling) overflow.
    Genome huge = random_test_genome({9, 3}, 1);
    huge.params[10] = huge.params[11] = 1.5e308;  // neuron 1 of layer 1: its first two weights
    CHECK_THROWS_WITH(Network(huge), Catch::Contains("neuron 1 of layer 1"));
}

TEST_CASE("genome files round-trip exactly", "[network][io]") {
    const TempDir tmp("genome");
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        Genome genome = random_test_genome({45, 30, 15}, seed, 1e3);
        genome.params[0] = 1e-310;  // subnormal
        genome.params[1] = -0.1;
        genome.params[2] = 1.0 / 3.0;
        const std::string path = tmp.file("genome-" + std::to_string(seed) + ".json");
        save_genome(genome, path);
        const Genome back = load_genome(path);
        CHECK(back.layers == genome.layers);
        REQUIRE(back.params.size() == genome.params.size());
        for (std::size_t i = 0; i < genome.params.size(); ++i) REQUIRE(back.params[i] == genome.params[i]);
    }
}

TEST_CASE("bad genome files are refused with the file and the reason", "[network][io]") {
    const TempDir tmp("genome");
    const std::string path = tmp.file("bad-genome.json");
    auto refused = [&](const std::string& text, const std::string& reason) {
        write_text(path, text);
        CHECK_THROWS_WITH(load_genome(path), Catch::Contains(path) && Catch::Contains(reason));
    };
    refused("{\"format\": \"morphogen-genome\", \"version\": 1, \"layers\": [2,1], \"params\": [1,2]}", "need 3");
    refused("{\"format\": \"other\", \"version\": 1, \"layers\": [2,1], \"params\": [1,2,3]}", "format");
    refused("{\"format\": \"morphogen-genome\", \"version\": 7, \"layers\": [2,1], \"params\": [1,2,3]}", "version 7");
    refused("{\"format\": \"morphogen-genome\", \"version\": 1, \"layers\": [2,1], \"params\": [1,null,3]}",
            "params[1]");
    refused("{\"format\": \"morphogen-genome\", \"version\": 1, \"layers\": [2,0], \"params\": []}", "layer size 0");
    refused("{\"format\": \"morphogen-genome\", \"version\": 1,\n \"layers\": [2,1] \"params\": [1,2,3]}", "line 2");
    refused("[]", "object");
    CHECK_THROWS_WITH(load_genome(tmp.file("does-not-exist.json")), Catch::Contains("cannot open"));
}

TEST_CASE("genome files: malformed JSON and overflowing parameters name the file", "[json][genome]") {
    TempDir dir("json-genome");
    const std::string head = R"({"format": "morphogen-genome", "version": 1, "layers": [3, 1], )";
    const std::string good = head + R"("params": [0.5, -0.25, 0.125, 0]})";
    const std::string open = good.substr(0, good.size() - 1);  // without the closing brace
    CHECK(load_genome(dir.write("good.json", good)).params.size() == 4);
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"deep.json", open + ", \"x\": " + std::string(100'000, '[') + std::string(100'000, ']') + "}"},
        {"inf.json", head + R"("params": [1e999, 0, 0, 0]})"},
        {"nul.json", good + std::string(1, '\0') + "junk"},
        {"null.json", "null"},
        {"dup.json", open + ", \"layers\": [3, 1]}"},
        // Finite, but the network's folding (0.5 * the sum of a neuron's weights) overflows.
        {"overflow.json", head + R"("params": [1e308, 1e308, 0, 0]})"},
    };
    for (const auto& [name, text] : bad) {
        INFO(name);
        try {
            (void)load_genome(dir.write(name, text));
            FAIL("accepted");
        } catch (const IoError& e) {
            const std::string what = e.what();
            CHECK(what.rfind(dir.file(name) + ": not a valid genome file: ", 0) == 0);
            CHECK(what.find_first_of("\r\n") == std::string::npos);  // one line
        }
    }
    CHECK_THROWS_WITH(load_genome(dir.file("overflow.json")), Catch::Contains("params[0..3]"));
    CHECK_THROWS_WITH(load_genome(dir.file("inf.json")),
                      Catch::Contains("line 1, column ") && Catch::Contains("params[0]"));
}
