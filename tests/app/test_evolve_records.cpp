// history.csv / lineage.csv rows and the append-only files behind them.
#include "core/errors.hpp"
#include "run/append_file.hpp"
#include "run/run_records.hpp"
#include "tests/app/evolve_test_support.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>

using namespace morphogen;
using namespace morphogen::test;

TEST_CASE("numbers are written in shortest round-trip form", "[app][records]") {
    for (double v : {0.1, 1.0 / 3.0, 2.0, -0.0, 1e-300, 123456789.123456789, std::nextafter(1.0, 2.0)}) {
        const std::string text = format_number(v);
        CHECK(std::strtod(text.c_str(), nullptr) == v);
    }
    CHECK(format_number(2.0) == "2");
    CHECK(format_number(0.1) == "0.1");
}

TEST_CASE("lineage rows: parents empty when absent and fitness empty when invalid", "[app][records]") {
    Individual initial{3, {}, {}, {}, 0.25};
    CHECK(format_lineage_row(initial) == "3,3,,,0.25\n");
    Individual copied{10, 4, {}, {}, 1.5};
    CHECK(format_lineage_row(copied) == "10,10,4,,1.5\n");
    Individual crossed{11, 4, 7, {}, invalid_fitness};
    CHECK(format_lineage_row(crossed) == "11,11,4,7,\n");
}

TEST_CASE("lineage rows and header with descriptor columns", "[app][records]") {
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

TEST_CASE("history rows round-trip through the checkpoint's JSON", "[app][records]") {
    HistoryRow row{2, 300, 1.5, 1.25, 1.0, 0.5, 123.5, 4, 12.5, 60.25};
    CHECK(format_history_row(history_row_from_json(history_row_to_json(row))) == format_history_row(row));
    HistoryRow empty{0, 100, {}, {}, {}, {}, {}, 100, 1, 2};
    CHECK(format_history_row(empty) == "0,100,,,,,,100,1,2\n");
    CHECK(format_history_row(history_row_from_json(history_row_to_json(empty))) == format_history_row(empty));
}

TEST_CASE("an append file resumes at a recorded length and refuses a changed prefix", "[app][records]") {
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
