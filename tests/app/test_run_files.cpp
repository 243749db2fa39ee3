// A run directory's files where something else stands: a FIFO, a directory
// or a device in place of checkpoint.json, lineage.csv, config.json or a
// best/ GLB, files larger than their reader's bound, a file-size limit, and
// command-line numbers out of range. Each is refused naming the file (or the
// option), with the documented exit code, without waiting and without
// touching the run.
#include "core/base/atomic_file.hpp"
#include "core/base/errors.hpp"
#include "tests/app/evolve_test_support.hpp"
#include "tests/support/sanitizers.hpp"

#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <map>

using namespace morphogen;
using namespace morphogen::test;

namespace {

// `prefix morphogen args` through the shell, stopped after 60 s (a reader
// that waits on a FIFO ends as exit 124, not as a hung test).
CliResult run_limited(const std::string& prefix, const std::string& args) {
    const fs::path out = fs::temp_directory_path() / ("morphogen-files-out-" + std::to_string(::getpid()));
    const std::string command = prefix + " timeout -s KILL 60 " + std::string(MORPHOGEN_EXE) + " " + args + " > " +
                                q(out) + " 2>&1 < /dev/null";
    CliResult result;
    const int status = std::system(("bash -c " + q(command)).c_str());
    result.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    result.output = read_text(out);
    fs::remove(out);
    return result;
}

// Every regular file under `dir` (not report/), as name -> bytes.
std::map<std::string, std::string> files_of(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        const std::string name = fs::relative(entry.path(), dir).string();
        if (name.rfind("report", 0) != 0 && entry.is_regular_file()) files[name] = read_text(entry.path());
    }
    return files;
}

// A finished MAP-Elites run of 3 generations with every best exported.
struct FinishedRun {
    TempDir tmp{"run-files"};
    fs::path run = tmp.path / "run";
    FinishedRun() {
        const CliResult made = run_morphogen("evolve " + q(fs::path(MORPHOGEN_SOURCE_DIR) / "tests/app/fixtures/engine_elites.json") +
                                             " --out " + q(run) + " --no-report");
        INFO(made.output);
        REQUIRE(made.code == 0);
    }
    // A copy of the run with `name` replaced by what `make` puts there.
    template <class Make>
    fs::path with(const std::string& label, const std::string& name, Make make) const {
        const fs::path copy = tmp.path / label;
        fs::copy(run, copy, fs::copy_options::recursive);
        fs::remove(copy / name);
        make(copy / name);
        return copy;
    }
};

void make_fifo(const fs::path& path) { REQUIRE(::mkfifo(path.c_str(), 0644) == 0); }
void make_dir(const fs::path& path) { fs::create_directory(path); }
void link_zero(const fs::path& path) { fs::create_symlink("/dev/zero", path); }
// A sparse file of `bytes` NUL bytes (no disk space used).
void sparse(const fs::path& path, std::uintmax_t bytes) {
    write_text(path, "");
    fs::resize_file(path, bytes);
}

}  // namespace

TEST_CASE("a FIFO, a directory or a device in place of a run's file is not a regular file, exit 3", "[app][files]") {
    const FinishedRun made;
    const std::pair<const char*, void (*)(const fs::path&)> kinds[] = {
        {"FIFO", make_fifo}, {"directory", make_dir}, {"character device", link_zero}};
    for (const char* name : {"checkpoint.json", "lineage.csv", "config.json"})
        for (const auto& [kind, make] : kinds) {
            const fs::path dir = made.with(std::string("r_") + name + "_" + (kind[0] == 'F' ? "f" : kind[0] == 'd' ? "d" : "c"),
                                           name, make);
            const auto before = files_of(dir);
            const CliResult resume = run_limited("", "resume " + q(dir) + " --generations 4 --no-report");
            CAPTURE(name, kind, resume.output);
            CHECK(resume.code == 3);
            CHECK_THAT(resume.output, Catch::Contains(name) && Catch::Contains("is not a regular file (it is a " +
                                                                                std::string(kind) + ")"));
            CHECK(files_of(dir) == before);
            if (std::string(name) == "checkpoint.json")
                for (const char* command : {"archive", "report"}) {
                    const CliResult other = run_limited("", std::string(command) + " " + q(dir));
                    CAPTURE(command, other.output);
                    CHECK(other.code == 3);
                    CHECK_THAT(other.output, Catch::Contains("is not a regular file"));
                }
        }
}

TEST_CASE("report names a FIFO or a directory for what it is, not missing, and NUL bytes are not empty", "[app][files]") {
    const FinishedRun made;
    struct Case {
        const char* label;
        const char* name;
        void (*make)(const fs::path&);
        int code;
        const char* says;
        const char* never;
    };
    const Case cases[] = {
        {"lineage_fifo", "lineage.csv", make_fifo, 3, "lineage.csv: is not a regular file (it is a FIFO)", "missing"},
        {"history_dir", "history.csv", make_dir, 3, "history.csv: is not a regular file (it is a directory)", "missing"},
        {"lineage_nul", "lineage.csv", [](const fs::path& p) { sparse(p, 1 << 20); }, 3,
         "no header line (1048576 bytes without an end of line)", "empty"},
        // A FIFO in best/: that generation is skipped with a note, the report is written.
        {"glb_fifo", "best/gen_0001.glb", make_fifo, 0, "gen_0001.glb: is not a regular file (it is a FIFO)", "missing"},
    };
    for (const Case& c : cases) {
        const CliResult r = run_limited("", "report " + q(made.with(c.label, c.name, c.make)));
        CAPTURE(c.label, r.output);
        CHECK(r.code == c.code);
        CHECK_THAT(r.output, Catch::Contains(c.says) && !Catch::Contains(c.never));
    }
}

TEST_CASE("files larger than their reader's bound are refused naming the file and the bound", "[app][files]") {
    const FinishedRun made;
    // config.json: 16 MiB at most.
    const fs::path config = made.with("big_config", "config.json", [](const fs::path& p) { sparse(p, (16u << 20) + 1); });
    const CliResult resume = run_limited("", "resume " + q(config) + " --generations 4 --no-report");
    INFO(resume.output);
    CHECK(resume.code == 3);
    CHECK_THAT(resume.output, Catch::Contains("config.json: 16777217 bytes, more than the limit of 16777216 bytes "
                                              "for config files"));
    // A 3 GB best/ GLB under a 4 GB address space: skipped naming the bound,
    // no std::bad_alloc (ASan's shadow memory needs more address space than that).
    const fs::path glb = made.with("big_glb", "best/gen_0001.glb", [](const fs::path& p) { sparse(p, 3'000'000'000); });
    const CliResult report =
        run_limited(morphogen::testing::kBuiltWithSanitizers ? "" : "ulimit -v 4000000;", "report " + q(glb));
    INFO(report.output);
    CHECK(report.code == 0);
    CHECK_THAT(report.output, Catch::Contains("gen_0001.glb: 3000000000 bytes, more than the limit of 2147483648 "
                                              "bytes for mesh files"));
    CHECK_THAT(report.output, !Catch::Contains("bad_alloc"));
}

TEST_CASE("read_file_bytes: bounds, kinds and heads", "[app][files]") {
    TempDir tmp("read-bounds");
    const std::string path = tmp.write("ten.txt", "0123456789");
    CHECK(read_file_bytes(path, {10, "tests"}) == "0123456789");
    CHECK_THROWS_WITH(read_file_bytes(path, {9, "tests"}),
                      Catch::Contains("ten.txt: 10 bytes, more than the limit of 9 bytes for tests"));
    CHECK(read_file_head(path, 4) == "0123");
    CHECK(read_file_head(path, 40) == "0123456789");
    CHECK_THROWS_WITH(read_file_bytes("/dev/zero", {1 << 20, "tests"}),
                      Catch::Contains("/dev/zero: is not a regular file (it is a character device)"));
    CHECK_THROWS_AS(read_file_head(tmp.path, 1), IoError);
}

TEST_CASE("a file-size limit is reported as such, not as an input/output error", "[app][files]") {
    const FinishedRun made;
    // A three.js of 200 kB, copied into the report past a 100 kB limit.
    const fs::path three = made.tmp.path / "three";
    fs::create_directories(three / "examples/js/loaders");
    fs::create_directories(three / "examples/js/controls");
    write_text(three / "three.min.js", std::string(200'000, 'x'));
    write_text(three / "examples/js/loaders/GLTFLoader.js", "x");
    write_text(three / "examples/js/controls/OrbitControls.js", "x");
    const CliResult r = run_limited("ulimit -f 100; MORPHOGEN_THREE_DIR=" + q(three), "report " + q(made.run));
    INFO(r.output);
    CHECK(r.code == 3);
    CHECK_THAT(r.output, Catch::Contains("three.min.js: cannot write: File too large"));
    CHECK_THAT(r.output, !Catch::Contains("Input/output error"));
}

TEST_CASE("command-line numbers out of range are blamed on the option, not on the config", "[app][files][cli]") {
    const FinishedRun made;
    const std::string config = q(fs::path(MORPHOGEN_SOURCE_DIR) / "tests/app/fixtures/engine_elites.json");
    const std::pair<std::string, std::string> cases[] = {
        {"evolve " + config + " --out " + q(made.tmp.path / "a") + " --threads -5", "--threads: -5 is out of range"},
        {"evolve " + config + " --out " + q(made.tmp.path / "b") + " --threads 99999", "--threads: 99999 is out of range"},
        {"resume " + q(made.run) + " --threads 99999", "--threads: 99999 is out of range"},
        {"evolve " + config + " --out " + q(made.tmp.path / "c") + " --generations 18446744073709551616",
         "--generations: expected a whole number up to 18446744073709551615, got '18446744073709551616'"},
        {"resume " + q(made.run) + " --generations 18446744073709551616", "--generations: expected a whole number"},
        {"evolve " + config + " --out " + q(made.tmp.path / "d") + " --generations 2000000000",
         "--generations: 2000000000 is out of range [0, 1000000000] (it replaces run.generations)"},
    };
    for (const auto& [args, expected] : cases) {
        const CliResult r = run_morphogen(args);
        CAPTURE(args, r.output);
        CHECK(r.code == 2);
        CHECK_THAT(r.output, Catch::Contains(expected));
        CHECK_THAT(r.output, !Catch::Contains(": run.threads:") && !Catch::Contains(": run.generations:"));
    }
}

TEST_CASE("heights below 1 mm (--height) are refused in grow, packs and configs", "[app][files][engine]") {
    const FinishedRun made;
    const CliResult grow = run_morphogen("grow --random 3 --steps 20 -o " + q(made.tmp.path / "h.glb") + " --height 1e-300");
    INFO(grow.output);
    CHECK(grow.code == 2);
    CHECK_THAT(grow.output, Catch::Contains("--height 1e-300: must be a number of metres in [0.001, 10000]"));
    CHECK_FALSE(fs::exists(made.tmp.path / "h.glb"));
    const CliResult pack = run_morphogen("archive " + q(made.run) + " --pack " + q(made.tmp.path / "p") + " --height 1e-300");
    INFO(pack.output);
    CHECK(pack.code == 2);
    CHECK_FALSE(fs::exists(made.tmp.path / "p"));
    write_text(made.tmp.path / "c.json", R"({"run": {"export_glb": {"height": 1e-300}}})");
    const CliResult config = run_morphogen("validate " + q(made.tmp.path / "c.json"));
    INFO(config.output);
    CHECK(config.code == 2);
    CHECK_THAT(config.output, Catch::Contains("run.export_glb.height") && Catch::Contains("0.001 (1 mm)"));
    CHECK(run_morphogen("grow --random 3 --steps 20 -o " + q(made.tmp.path / "mm.glb") + " --height 0.001").code == 0);
}

namespace {
// A MAP-Elites run from a tetrahedron grown 2 steps: elites of 4 to ~40 triangles.
std::string tiny_elites_config() {
    return R"({"network": {"outputs": 4, "hidden": [5]},
 "growth": {"steps": 2, "max_vertices": 300, "seed_mesh": "tetrahedron"},
 "fitness": {"type": "canopy", "height": 1, "cell": 0.1},
 "evolution": {"algorithm": "map_elites", "population": 12, "batch": 4, "mutation_rate": 0.2},
 "descriptors": [{"measure": "height", "min": 0, "max": 3, "bins": 6},
                 {"measure": "footprint", "min": 0, "max": 10, "bins": 5}],
 "archive": {"type": "grid"},
 "run": {"name": "tiny", "seed": 3, "generations": 1}})";
}
}  // namespace

TEST_CASE("archive --pack --lods 3 gives an elite under 32 triangles the levels it can have", "[app][files][engine]") {
    TempDir tmp("tiny-pack");
    write_text(tmp.path / "tiny.json", tiny_elites_config());
    REQUIRE(run_morphogen("evolve " + q(tmp.path / "tiny.json") + " --out " + q(tmp.path / "run") + " --no-report").code == 0);
    const CliResult r = run_morphogen("archive " + q(tmp.path / "run") + " --pack " + q(tmp.path / "pack") + " --lods 3");
    INFO(r.output);
    REQUIRE(r.code == 0);
    const nlohmann::json manifest = nlohmann::json::parse(read_text(tmp.path / "pack" / "manifest.json"));
    const std::string archive = read_text(tmp.path / "run" / "archive.csv");
    const auto elites = static_cast<std::size_t>(std::count(archive.begin(), archive.end(), '\n') - 1);
    CHECK(manifest["species"].size() == elites);  // every elite packed
    std::size_t small = 0;
    for (const nlohmann::json& species : manifest["species"]) {
        CAPTURE(species.dump());
        const auto lod0 = species["triangles"][0].get<std::size_t>();
        CHECK(fs::exists(tmp.path / "pack" / species["file"].get<std::string>()));
        if (lod0 >= 32) continue;
        ++small;
        REQUIRE(species.contains("lods_written"));
        CHECK(species["lods_written"].get<std::size_t>() < 3);
        CHECK(species["triangles"].size() == species["lods_written"].get<std::size_t>());
    }
    CHECK(small > 0);
    CHECK_THAT(r.output, Catch::Contains("could not be made (the plant has"));
}

TEST_CASE("archive stops on SIGTERM with exit 130 and leaves no pack, and names an incomplete pack", "[app][files][faults]") {
    const FinishedRun made;
    // Sent while SIGTERM is blocked across exec: it arrives the moment
    // archive's handlers are in place, before its first plant.
    const fs::path pack = made.tmp.path / "pack";
    const int pid = spawn_morphogen({"archive", made.run.string(), "--pack", pack.string(), "--lods", "2"},
                                    made.tmp.path / "archive.log", true);
    ::kill(pid, SIGTERM);
    bool killed = false;
    const int code = wait_for(pid, &killed);
    INFO(read_text(made.tmp.path / "archive.log"));
    CHECK_FALSE(killed);
    CHECK(code == 130);
    CHECK_THAT(read_text(made.tmp.path / "archive.log"), Catch::Contains("stopped by signal 15"));
    CHECK_FALSE(fs::exists(pack));
    // The same for the elites' export: stopped before its first elite.
    const int elites_pid = spawn_morphogen({"archive", made.run.string(), "--out", (made.tmp.path / "el").string()},
                                           made.tmp.path / "elites.log", true);
    ::kill(elites_pid, SIGTERM);
    CHECK(wait_for(elites_pid) == 130);
    CHECK_FALSE(fs::exists(made.tmp.path / "el" / "species.csv"));

    // What a kill -9 mid-pack leaves: plant files, no manifest.
    fs::create_directories(pack);
    write_text(pack / "plant_7.glb", "glTF");
    const CliResult again = run_morphogen("archive " + q(made.run) + " --pack " + q(pack));
    INFO(again.output);
    CHECK(again.code == 3);
    CHECK_THAT(again.output, Catch::Contains("holds an incomplete species pack") &&
                                 Catch::Contains("remove the directory and run the same command again"));
    CHECK(read_text(pack / "plant_7.glb") == "glTF");
    const CliResult whole = run_morphogen("archive " + q(made.run) + " --pack " + q(made.tmp.path / "whole"));
    CHECK(whole.code == 0);
    CHECK(fs::exists(made.tmp.path / "whole" / "manifest.json"));
}

TEST_CASE("render draws GLB files: grow's and an engine export's LOD0", "[app][files][render]") {
    TempDir tmp("render-glb");
    REQUIRE(run_morphogen("grow --random 4 --steps 120 -o " + q(tmp.path / "plain.glb")).code == 0);
    REQUIRE(run_morphogen("grow --random 4 --steps 120 -o " + q(tmp.path / "plain.obj")).code == 0);
    REQUIRE(run_morphogen("grow --random 4 --steps 120 -o " + q(tmp.path / "lods.glb") + " --lods 3 --wind").code == 0);
    const CliResult r = run_morphogen("render " + q(tmp.path / "plain.glb") + " " + q(tmp.path / "lods.glb") + " -o " +
                                      q(tmp.path / "sheet.png"));
    INFO(r.output);
    CHECK(r.code == 0);
    CHECK(fs::file_size(tmp.path / "sheet.png") > 0);
    // The GLB's body is the same mesh as the OBJ beside it: the same picture.
    REQUIRE(run_morphogen("render " + q(tmp.path / "plain.obj") + " -o " + q(tmp.path / "obj.png")).code == 0);
    REQUIRE(run_morphogen("render " + q(tmp.path / "plain.glb") + " -o " + q(tmp.path / "glb.png")).code == 0);
    CHECK(read_text(tmp.path / "obj.png") == read_text(tmp.path / "glb.png"));
}
