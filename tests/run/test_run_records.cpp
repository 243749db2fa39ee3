// history.csv / lineage.csv rows and the append-only files behind them.
#include "core/base/errors.hpp"
#include "core/base/append_file.hpp"
#include "run/growth_problem.hpp"
#include "run/loop/run_records.hpp"
#include "tests/run/tiny_configs.hpp"
#include "tests/support/temp_dir.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <random>

using namespace morphogen;
using namespace morphogen::test;
using morphogen::testing::read_text;
using morphogen::testing::TempDir;
using morphogen::testing::write_text;
namespace fs = std::filesystem;

TEST_CASE("numbers are written in shortest round-trip form", "[run][records]") {
    for (double v : {0.1, 1.0 / 3.0, 2.0, -0.0, 1e-300, 123456789.123456789, std::nextafter(1.0, 2.0)}) {
        const std::string text = format_number(v);
        CHECK(std::strtod(text.c_str(), nullptr) == v);
    }
    CHECK(format_number(2.0) == "2");
    CHECK(format_number(0.1) == "0.1");
}

TEST_CASE("lineage rows: parents empty when absent and fitness empty when invalid", "[run][records]") {
    Individual initial{3, {}, {}, {}, 0.25};
    CHECK(format_lineage_row(initial) == "3,3,,,0.25\n");
    Individual copied{10, 4, {}, {}, 1.5};
    CHECK(format_lineage_row(copied) == "10,10,4,,1.5\n");
    Individual crossed{11, 4, 7, {}, invalid_fitness};
    CHECK(format_lineage_row(crossed) == "11,11,4,7,\n");
}

TEST_CASE("lineage rows and header with descriptor columns", "[run][records]") {
    CHECK(lineage_header_for({}) == lineage_header);
    CHECK(lineage_header_for({"height", "footprint"}) == "id,birth,parent1,parent2,fitness,height,footprint\n");
    Individual measured{5, 1, {}, {}, 2.5};
    measured.descriptors = {0.1, 12.0};
    CHECK(format_lineage_row(measured, 2) == "5,5,1,,2.5,0.1,12\n");
    CHECK(format_lineage_row(measured) == "5,5,1,,2.5\n");  // no columns asked for: as before
    Individual invalid{6, 1, 2, {}, invalid_fitness};
    CHECK(format_lineage_row(invalid, 2) == "6,6,1,2,,,\n");
    // a valid birth whose measures could not be taken (a GA's), or a count that does not match: empty cells
    Individual unmeasured{7, {}, {}, {}, 1.0};
    CHECK(format_lineage_row(unmeasured, 2) == "7,7,,,1,,\n");
    measured.descriptors = {0.1};
    CHECK(format_lineage_row(measured, 2) == "5,5,1,,2.5,,\n");
}

TEST_CASE("history rows round-trip through the checkpoint's JSON", "[run][records]") {
    HistoryRow row{2, 300, 1.5, 1.25, 1.0, 0.5, 123.5, 4, 12.5, 60.25};
    CHECK(format_history_row(history_row_from_json(history_row_to_json(row))) == format_history_row(row));
    HistoryRow empty{0, 100, {}, {}, {}, {}, {}, 100, 1, 2};
    CHECK(format_history_row(empty) == "0,100,,,,,,100,1,2\n");
    CHECK(format_history_row(history_row_from_json(history_row_to_json(empty))) == format_history_row(empty));
}

TEST_CASE("an append file resumes at a recorded length and refuses a changed prefix", "[run][records]") {
    TempDir tmp("append-file");
    const auto path = tmp.path / "rows.csv";
    std::uint64_t length = 0;
    std::string hash;
    {
        AppendFile file = AppendFile::create(path, "a,b\n");
        file.write("1,2\n");
        length = file.size();
        hash = file.hash_hex();
        file.write("3,4\n5,");  // written after the "checkpoint"
    }
    {
        AppendFile file = AppendFile::resume(path, length, hash);
        CHECK(read_text(path) == "a,b\n1,2\n");
        file.write("7,8\n");
    }
    CHECK(read_text(path) == "a,b\n1,2\n7,8\n");
    write_text(path, "a,b\n1,3\n7,8\n");
    CHECK_THROWS_AS(AppendFile::resume(path, length, hash), CheckpointError);
    CHECK(read_text(path) == "a,b\n1,3\n7,8\n");  // untouched
    write_text(path, "a,b\n");
    CHECK_THROWS_WITH(AppendFile::resume(path, length, hash), Catch::Contains("bytes"));
}

TEST_CASE("a mesh kept from its evaluation exports the bytes of one grown again", "[run][records][export]") {
    TempDir tmp("kept-export");
    auto exporting = nlohmann::json::parse(tiny_config(2));
    exporting["run"]["export_every"] = 1;
    const ExperimentConfig config = read_experiment_config(exporting, "tiny");
    GrowthProblem problem(config);
    problem.prepare(1);
    // A run that exports nothing keeps nothing.
    GrowthProblem silent(read_experiment_config(nlohmann::json::parse(tiny_config(2)), "tiny"));
    silent.prepare(1);
    std::mt19937_64 random(5);
    std::normal_distribution<double> normal(0.0, 1.0);
    int compared = 0;
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<double> genome(problem.dimension());
        for (double& p : genome) p = normal(random);
        const Evaluation plain = problem.evaluate(genome, 0);
        CHECK(plain.kept.empty());
        const Evaluation kept = problem.evaluate_keeping(genome, 0, -std::numeric_limits<double>::infinity());
        CHECK(kept.score == plain.score);
        if (!kept.valid) continue;
        REQUIRE_FALSE(kept.kept.empty());
        CHECK(silent.evaluate_keeping(genome, 0, -std::numeric_limits<double>::infinity()).kept.empty());
        // A threshold above the score keeps nothing.
        CHECK(problem.evaluate_keeping(genome, 0, kept.score + 1).kept.empty());
        const fs::path a = tmp.path / ("kept" + std::to_string(trial)), b = tmp.path / ("grown" + std::to_string(trial));
        problem.export_kept(kept.kept, genome, a);
        problem.export_genome(genome, b);
        for (const char* extension : {".glb", ".obj", ".genome.json"}) {
            CAPTURE(extension);
            CHECK(read_text(a.string() + extension) == read_text(b.string() + extension));
        }
        ++compared;
    }
    CHECK(compared > 5);
    CHECK_THROWS_AS(problem.export_kept("short", {}, tmp.path / "x"), std::invalid_argument);
}
