// Hostile JSON through the real executable: configs (exit 2), genome files
// (exit 3), checkpoints (exit 5, left byte-identical). Every refusal is one
// line naming the file. Also replays every file of tests/corpus/{config,
// genome,checkpoint}: each must be refused with its documented exit code.
#include "core/base/errors.hpp"
#include "run/persistence/checkpoint.hpp"
#include "tests/app/evolve_test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace morphogen;
using namespace morphogen::test;

namespace {
const fs::path corpus = fs::path(MORPHOGEN_SOURCE_DIR) / "tests" / "corpus";

std::string shell_quoted(const fs::path& path) { return "'" + path.string() + "'"; }

// The output is exactly one line (ending in a newline) and names `file`.
void check_one_line_naming(const CliResult& r, const std::string& file) {
    INFO(r.output);
    CHECK(!r.output.empty());
    CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
    CHECK(r.output.back() == '\n');
    CHECK(r.output.find(file) != std::string::npos);
}

std::string deep_nesting(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

// The hostile files of a corpus folder: every file but the fuzzers' valid
// seeds (named valid-*) and READMEs.
std::vector<fs::path> corpus_files(const std::string& kind) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(corpus / kind)) {
        const std::string name = entry.path().filename().string();
        if (entry.is_regular_file() && name.rfind("valid-", 0) != 0 && name.rfind("README", 0) != 0)
            files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

// A small network (9 inputs, 3 outputs, 30 parameters) for the genome tests and the corpus.
const std::string small_network = R"({"network": {"outputs": 3, "hidden": []}})";
// A genome file for it; `first` replaces the first parameters, `extra` adds keys.
std::string genome_with(const std::string& first, const std::string& extra = "") {
    std::string params = first;
    const int given = first.empty() ? 0 : static_cast<int>(std::count(first.begin(), first.end(), ',')) + 1;
    for (int i = given; i < 30; ++i) params += (i ? ", " : "") + std::string("0.25");
    return R"({"format": "morphogen-genome", "version": 1, "layers": [9, 3], "params": [)" + params + "]" + extra + "}";
}
}  // namespace

TEST_CASE("validate refuses hostile configs in one line, exit 2", "[app][json]") {
    TempDir dir("hostile-config");
    const std::vector<std::pair<std::string, std::string>> cases = {
        // ~100,000 nested brackets used to overflow the stack (SIGSEGV).
        {"deep.json", R"({"network":)" + deep_nesting(100'000) + "}"},
        {"overflow.json", R"({"growth": {"speed": 1e309}})"},
        {"nul.json", std::string(R"({"growth": {"steps": 5}})") + '\0' + "junk"},
        {"null.json", "null"},
        {"duplicate.json", R"({"growth":{"steps":5},"growth":{"steps":7}})"},
    };
    for (const auto& [name, text] : cases) {
        const std::string path = dir.write(name, text);
        for (const std::string& command : {std::string("validate "), "evolve --out " + dir.file("run") + " "}) {
            const CliResult r = run_morphogen(command + shell_quoted(path));
            INFO(command << name << ": " << r.output);
            CHECK(r.code == 2);
            check_one_line_naming(r, path);
            CHECK(r.output.find("invalid JSON at line 1, column ") != std::string::npos);
            CHECK_FALSE(fs::exists(dir.path / "run"));
        }
    }
    CHECK(run_morphogen("validate " + dir.file("overflow.json")).output.find("in growth.speed") != std::string::npos);
    CHECK(run_morphogen("validate " + dir.file("duplicate.json")).output.find("duplicate key \"growth\"") !=
          std::string::npos);
    CHECK(run_morphogen("validate " + dir.file("null.json")).output.find("not a JSON object") != std::string::npos);
    CHECK(run_morphogen("validate " + dir.file("nul.json")).output.find("NUL") != std::string::npos);
}

TEST_CASE("run.seed 9e15 is an integer, 1e16 asks for plain digits", "[app][json]") {
    TempDir dir("hostile-seed");
    const CliResult ok = run_morphogen("validate --resolved " + dir.write("s.json", R"({"run": {"seed": 9e15}})"));
    INFO(ok.output);
    CHECK(ok.code == 0);
    CHECK(ok.output.find("\"seed\": 9000000000000000") != std::string::npos);
    const CliResult big = run_morphogen("validate " + dir.write("b.json", R"({"run": {"seed": 1e16}})"));
    CHECK(big.code == 2);
    check_one_line_naming(big, "run.seed");
}

TEST_CASE("a missing seed mesh is exit 3 naming growth.seed_mesh in validate, evolve and grow", "[app][json]") {
    TempDir dir("hostile-seed-mesh");
    const std::string missing = dir.file("no-such-seed.obj");
    const std::string config = dir.write("c.json", R"({"growth": {"seed_mesh": ")" + missing + R"("}})");
    for (const std::string& command : {"validate " + config, "evolve " + config + " --out " + dir.file("run"),
                                      "grow --config " + config + " --random 1 -o " + dir.file("x.obj")}) {
        const CliResult r = run_morphogen(command);
        INFO(command << ": " << r.output);
        CHECK(r.code == 3);
        check_one_line_naming(r, "growth.seed_mesh: " + missing);
        CHECK(r.output.find("No such file") != std::string::npos);
    }
    CHECK_FALSE(fs::exists(dir.path / "run"));
}

TEST_CASE("grow refuses hostile genome files in one line naming the file, exit 3", "[app][json]") {
    TempDir dir("hostile-genome");
    const std::string grow =
        "grow --config " + dir.write("c.json", small_network) + " --steps 3 -o " + dir.file("x.obj");
    const std::string good = dir.write("good.json", genome_with(""));
    REQUIRE(run_morphogen(grow + " --genome " + good).code == 0);
    fs::remove(dir.path / "x.obj");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"deep.json", genome_with("", ", \"x\": " + deep_nesting(100'000))},
        {"inf.json", genome_with("1e999")},
        {"nul.json", genome_with("") + '\0' + "junk"},
        {"null.json", "null"},
        {"duplicate.json", genome_with("", R"(, "layers": [45, 15])")},
    };
    for (const auto& [name, text] : cases) {
        const std::string path = dir.write(name, text);
        const CliResult r = run_morphogen(grow + " --genome " + path);
        INFO(name << ": " << r.output);
        CHECK(r.code == 3);
        check_one_line_naming(r, path + ": not a valid genome file: invalid JSON at line 1, column ");
    }
    // Two parameters of 1e308 are finite, but the network's folding of them
    // overflows: a bad genome file (exit 3, named), not a "config error".
    const std::string overflow = dir.write("overflow.json", genome_with("1e308, 1e308"));
    for (const std::string& command : {grow + " --genome " + overflow,
                                       "score --config " + dir.file("c.json") + " --genome " + overflow}) {
        const CliResult r = run_morphogen(command);
        INFO(r.output);
        CHECK(r.code == 3);
        check_one_line_naming(r, overflow + ": not a valid genome file: neuron 0 of layer 1");
        CHECK(r.output.find("config error") == std::string::npos);
    }
    CHECK_FALSE(fs::exists(dir.path / "x.obj"));
}

TEST_CASE("resume refuses hostile checkpoints with exit 5 and leaves them byte-identical", "[app][json]") {
    TempDir dir("hostile-checkpoint");
    write_text(dir.path / "tiny.json", tiny_config(1, 3, 2));
    const fs::path run = dir.path / "run";
    REQUIRE(run_morphogen("evolve " + dir.file("tiny.json") + " --out " + shell_quoted(run)).code == 0);
    const std::string good = read_text(run / "checkpoint.json");
    const std::string key = "\"elapsed_s\":";
    const std::size_t start = good.find(key) + key.size();
    const std::size_t end = good.find_first_of(",}", start);
    REQUIRE(end != std::string::npos);
    auto with_elapsed = [&](const std::string& value) { return good.substr(0, start) + value + good.substr(end); };
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"deep", with_elapsed(deep_nesting(100'000))},
        {"1e999", with_elapsed("1e999")},
        {"nul", good.substr(0, good.find('\n')) + '\0' + "junk" + good.substr(good.find('\n'))},  // in the header line
        {"duplicate", R"({"format":"morphogen-checkpoint",)" + good.substr(1)},
    };
    const fs::path checkpoint = run / "checkpoint.json";
    for (const auto& [name, text] : cases) {
        write_text(checkpoint, text);
        const CliResult r = run_morphogen("resume " + shell_quoted(run));
        INFO(name << ": " << r.output);
        CHECK(r.code == 5);
        check_one_line_naming(r, "checkpoint " + checkpoint.string() + " refused: invalid JSON");
        CHECK(read_text(checkpoint) == text);
    }
    // The untouched checkpoint still resumes: the refusals were about the text.
    write_text(checkpoint, good);
    CHECK(run_morphogen("resume " + shell_quoted(run)).code == 0);
}

TEST_CASE("corpus: every hostile config is refused by validate", "[app][json][corpus]") {
    for (const fs::path& file : corpus_files("config")) {
        const CliResult r = run_morphogen("validate " + shell_quoted(file));
        INFO(file.filename().string() << ": " << r.output);
        CHECK(r.code == 2);
        check_one_line_naming(r, file.string());
    }
}

TEST_CASE("corpus: every hostile genome file is refused by grow", "[app][json][corpus]") {
    TempDir dir("corpus-genome");
    const std::string config = dir.write("c.json", small_network);
    for (const fs::path& file : corpus_files("genome")) {
        const CliResult r = run_morphogen("grow --config " + config + " --genome " + shell_quoted(file) +
                                          " --steps 3 -o " + dir.file("x.obj"));
        INFO(file.filename().string() << ": " << r.output);
        CHECK(r.code == 3);
        check_one_line_naming(r, file.string() + ": not a valid genome file: ");
    }
}

TEST_CASE("corpus: every hostile checkpoint is refused, by the reader and by resume", "[app][json][corpus]") {
    TempDir dir("corpus-checkpoint");
    write_text(dir.path / "tiny.json", tiny_config(1, 3, 2));
    const fs::path run = dir.path / "run";
    REQUIRE(run_morphogen("evolve " + dir.file("tiny.json") + " --out " + shell_quoted(run)).code == 0);
    for (const fs::path& file : corpus_files("checkpoint")) {
        INFO(file.filename().string());
        const std::string text = read_text(file);
        CHECK_THROWS_AS(checkpoint_content(text, file.string()), CheckpointError);
        write_text(run / "checkpoint.json", text);
        const CliResult r = run_morphogen("resume " + shell_quoted(run));
        INFO(r.output);
        CHECK(r.code == 5);
        check_one_line_naming(r, (run / "checkpoint.json").string());
        CHECK(read_text(run / "checkpoint.json") == text);
    }
}
