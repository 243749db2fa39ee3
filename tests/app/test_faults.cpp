
// Faults during a run: Ctrl-C/SIGTERM and kill -9 at random moments from
// the first millisecond, a full disk, a log that cannot be opened, a deleted
// best/, leftovers of a crash. Every stopped run must end, after `resume` (or
// `evolve` again where it stopped before its first checkpoint), with exactly
// the files of an uninterrupted run.
#include "core/base/atomic_file.hpp"
#include "run/persistence/checkpoint.hpp"
#include "tests/app/evolve_test_support.hpp"
#include "tests/support/sanitizers.hpp"

#include <catch2/catch.hpp>

#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <iostream>
#include <map>
#include <random>
#include <thread>
#include <vector>

using namespace morphogen;
using namespace morphogen::test;

namespace {

// A run of 4 generations of 6 with every best exported: ~20 ms on a RAM disk.
// The pipeline schedule, lag 3: a stop mostly lands with births in flight.
std::string fault_config() {
    auto config = nlohmann::json::parse(tiny_pipeline_config(3, 6, 3));
    config["growth"]["steps"] = 4;
    config["growth"]["max_vertices"] = 100;
    config["run"]["export_every"] = 1;
    config["run"]["threads"] = 1;
    return config.dump(1);
}

// On /dev/shm where there is one: fsync there costs nothing, so a run takes
// milliseconds and the random moments below cover all of it.
struct FastDir {
    fs::path path;
    explicit FastDir(const std::string& label) {
        static int counter = 0;
        std::error_code ec;
        const fs::path base = fs::is_directory("/dev/shm", ec) && ::access("/dev/shm", W_OK) == 0
                                  ? fs::path("/dev/shm")
                                  : fs::temp_directory_path();
        path = base / ("morphogen_" + label + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        fs::remove_all(path, ec);
        fs::create_directories(path);
    }
    ~FastDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    FastDir(const FastDir&) = delete;
    FastDir& operator=(const FastDir&) = delete;
};

// Temporary files (<name>.tmp) anywhere under `dir`.
std::vector<std::string> temporaries(const fs::path& dir) {
    std::vector<std::string> found;
    std::error_code ec;
    for (const auto& entry : fs::recursive_directory_iterator(dir, ec))
        if (entry.path().extension() == ".tmp") found.push_back(entry.path().string());
    return found;
}

// best/ as name -> bytes.
std::map<std::string, std::string> exports(const fs::path& dir) {
    std::map<std::string, std::string> files;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir / "best", ec))
        files[entry.path().filename().string()] = read_text(entry.path());
    return files;
}

// Same results as the uninterrupted run `whole`: rows, checkpoint, exports, no leftovers.
void check_same_run(const fs::path& whole, const fs::path& dir) {
    check_same_results(whole, dir);
    CHECK(exports(whole) == exports(dir));
    CHECK(temporaries(dir).empty());
}

// Continues a stopped run to the end: `resume` if it has a checkpoint,
// otherwise `evolve` into the same directory without --force.
void finish(const fs::path& config, const fs::path& dir) {
    const bool has_checkpoint = fs::exists(dir / "checkpoint.json");
    CAPTURE(has_checkpoint);
    const CliResult r = has_checkpoint ? run_morphogen("resume " + q(dir) + " --generations 3")
                                       : run_morphogen("evolve " + q(config) + " --out " + q(dir));
    INFO(r.output);
    REQUIRE(r.code == 0);
}

struct FaultRun {
    FastDir tmp;
    fs::path config, whole;
    double seconds = 0.0;  // how long the uninterrupted run took
    explicit FaultRun(const std::string& label) : tmp(label), config(tmp.path / "c.json"), whole(tmp.path / "whole") {
        write_text(config, fault_config());
        const auto start = std::chrono::steady_clock::now();
        REQUIRE(run_morphogen("evolve " + q(config) + " --out " + q(whole)).code == 0);
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
};

// <prefix><n> (appending, not "s" + string: GCC 12 warns falsely, -Wrestrict).
std::string numbered(const char* prefix, int n) {
    std::string name(prefix);
    name += std::to_string(n);
    return name;
}

void sleep_us(long us) { std::this_thread::sleep_for(std::chrono::microseconds(us)); }
}  // namespace

TEST_CASE("SIGINT or SIGTERM at any moment: resumed or restarted to the same bytes", "[app][faults][signals]") {
    FaultRun t("faults-signal");
    std::mt19937 random(20261123);
    // Delays from 0 to a little past the run's end (the whole run is spawned, so measure generously).
    const long span_us = static_cast<long>(t.seconds * 1.5e6) + 2000;
    const int trials = morphogen::testing::whole_or_under_sanitizers(24, 8);
    for (int trial = 0; trial < trials; ++trial) {
        const int signal = trial % 2 == 0 ? SIGINT : SIGTERM;
        const bool blocked = trial % 4 < 2;  // half start with the signals blocked across exec
        const long delay = trial < 4 ? 0 : std::uniform_int_distribution<long>(0, span_us)(random);
        CAPTURE(trial, signal, blocked, delay);
        const auto dir = t.tmp.path / numbered("s", trial);
        const int pid = spawn_morphogen({"evolve", t.config.string(), "--out", dir.string()},
                                        t.tmp.path / "spawn.log", blocked);
        sleep_us(delay);
        ::kill(pid, signal);
        bool killed = false;
        const int code = wait_for(pid, &killed);
        const std::string output = read_text(t.tmp.path / "spawn.log");
        INFO(output);
        if (killed) {
            // Only before any morphogen code ran (the system loading it): nothing written.
            CHECK_FALSE(blocked);
            CHECK(code == 128 + signal);
            CHECK_FALSE(fs::exists(dir));
        } else {
            CHECK((code == 130 || code == 0));
        }
        CHECK(temporaries(t.tmp.path).empty());
        finish(t.config, dir);
        check_same_run(t.whole, dir);
    }
}

TEST_CASE("SIGTERM during resume's start-up exits 130 and changes nothing", "[app][faults][signals]") {
    FaultRun t("faults-resume-signal");
    const auto dir = t.tmp.path / "r";
    REQUIRE(run_morphogen("evolve " + q(t.config) + " --out " + q(dir) + " --generations 1").code == 0);
    const int pid = spawn_morphogen({"resume", dir.string(), "--generations", "3"}, t.tmp.path / "spawn.log", true);
    ::kill(pid, SIGTERM);  // pending until resume's handlers are in place: its very first moment
    CHECK(wait_for(pid) == 130);
    finish(t.config, dir);
    check_same_run(t.whole, dir);
}

TEST_CASE("kill -9 at any moment: resumed or restarted to the same bytes", "[app][faults][signals]") {
    FaultRun t("faults-kill");
    std::mt19937 random(9);
    const long span_us = static_cast<long>(t.seconds * 1.5e6) + 2000;
    for (int trial = 0; trial < 16; ++trial) {
        const long delay = trial < 2 ? 0 : std::uniform_int_distribution<long>(0, span_us)(random);
        CAPTURE(trial, delay);
        const auto dir = t.tmp.path / numbered("k", trial);
        const int pid =
            spawn_morphogen({"evolve", t.config.string(), "--out", dir.string()}, t.tmp.path / "spawn.log");
        sleep_us(delay);
        ::kill(pid, SIGKILL);
        const int code = wait_for(pid);
        CHECK((code == 128 + SIGKILL || code == 0));
        finish(t.config, dir);
        check_same_run(t.whole, dir);
    }
}

TEST_CASE("a run stopped before its first checkpoint can be started again without --force", "[app][faults]") {
    FaultRun t("faults-stopped-start");
    const auto dir = t.tmp.path / "start";
    // What a kill -9 during start-up leaves: the config, headers (one cut short), an empty log, the lock, a temp.
    fs::create_directories(dir / "best");
    fs::copy_file(t.whole / "config.json", dir / "config.json");
    write_text(dir / "history.csv", "generation,births,best,mean,median,worst,mean_vertices,invalid,births_per_s,elapsed_s\n");
    write_text(dir / "lineage.csv", "id,birth,pa");
    write_text(dir / "log.txt", "");
    write_text(dir / ".lock", "");
    write_text(dir / "checkpoint.json.tmp", "{\"content\":");

    const CliResult refused = run_morphogen("resume " + q(dir));
    CHECK(refused.code == 3);  // no checkpoint to read; nothing refused (5)
    CHECK_THAT(refused.output, Catch::Contains("before its first checkpoint") && Catch::Contains("evolve"));

    SECTION("evolve starts it again") {
        const CliResult r = run_morphogen("evolve " + q(t.config) + " --out " + q(dir));
        INFO(r.output);
        REQUIRE(r.code == 0);
        check_same_run(t.whole, dir);
    }
    SECTION("but not a directory holding anything else") {
        for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
                 {"notes.txt", "mine"}, {"lineage.csv", read_text(t.whole / "lineage.csv")}}) {
            CAPTURE(name);
            const std::string before = fs::exists(dir / name) ? read_text(dir / name) : std::string("(none)");
            write_text(dir / name, text);
            const CliResult r = run_morphogen("evolve " + q(t.config) + " --out " + q(dir));
            CHECK(r.code == 3);
            CHECK_THAT(r.output, Catch::Contains("not empty"));
            CHECK(read_text(dir / name) == text);
            if (before == "(none)") fs::remove(dir / name);
            else write_text(dir / name, before);
        }
        write_text(dir / "best" / "gen_0000.obj", "o\n");
        CHECK(run_morphogen("evolve " + q(t.config) + " --out " + q(dir)).code == 3);
    }
}

TEST_CASE("kill -9 finds at most one finished generation past the checkpoint", "[app][faults][signals]") {
    // On a real disk (fsync costs there) with 2-generation-long checkpoints
    // that used to queue behind each other: history.csv and lineage.csv may
    // hold the generation being finished, never more.
    TempDir tmp("faults-lag");
    auto config = nlohmann::json::parse(fault_config());
    config["run"]["generations"] = 30;
    config["run"]["export_every"] = 0;
    config["evolution"]["population"] = 4;
    const fs::path config_path = tmp.path / "c.json";
    write_text(config_path, config.dump());
    std::mt19937 random(39);
    for (int trial = 0; trial < 20; ++trial) {
        const long delay = std::uniform_int_distribution<long>(20000, 120000)(random);
        CAPTURE(trial, delay);
        const auto dir = tmp.path / numbered("k", trial);
        const int pid = spawn_morphogen({"evolve", config_path.string(), "--out", dir.string()}, tmp.path / "spawn.log");
        sleep_us(delay);
        ::kill(pid, SIGKILL);
        wait_for(pid);
        if (!fs::exists(dir / "checkpoint.json")) continue;
        const nlohmann::json content = checkpoint_content(read_text(dir / "checkpoint.json"), "test");
        const std::uint64_t done = content["ga"]["births"].get<std::uint64_t>() / 4;  // finished generations
        const auto lines = [](const fs::path& file) {
            std::uint64_t n = 0;
            for (char c : read_text(file)) n += c == '\n';
            return n - 1;  // the header
        };
        const std::uint64_t reported = lines(dir / "history.csv"), born = lines(dir / "lineage.csv");
        CAPTURE(done, reported, born);
        CHECK(reported <= done + 1);
        CHECK(born <= (done + 1) * 4);
    }
}

TEST_CASE("resume removes what a crash left after the checkpoint and recreates best/", "[app][faults]") {
    FaultRun t("faults-leftovers");
    const auto dir = t.tmp.path / "r";
    REQUIRE(run_morphogen("evolve " + q(t.config) + " --out " + q(dir) + " --generations 1").code == 0);
    SECTION("temporaries and later exports") {
        write_text(dir / "checkpoint.json.tmp", "{\"con");
        write_text(dir / "best" / "gen_0001.glb.tmp", "glTF");
        write_text(dir / "best" / "gen_0003.obj", "v 0 0 0\n");  // a generation after the checkpoint
        write_text(dir / "best" / "gen_0009.genome.json", "{}");
        finish(t.config, dir);
        check_same_run(t.whole, dir);
    }
    SECTION("a deleted best/") {
        fs::remove_all(dir / "best");
        finish(t.config, dir);
        check_same_results(t.whole, dir);
        auto expected = exports(t.whole);
        for (const char* gone : {"gen_0000.glb", "gen_0000.obj", "gen_0000.genome.json", "gen_0001.glb",
                                 "gen_0001.obj", "gen_0001.genome.json"})
            expected.erase(gone);
        CHECK(exports(dir) == expected);
    }
}

TEST_CASE("log.txt that cannot be opened exits 3 naming it, and the run stays resumable", "[app][faults]") {
    FaultRun t("faults-log");
    const auto dir = t.tmp.path / "r";
    SECTION("evolve") {
        fs::create_directories(dir / "log.txt" / "inside");
        const CliResult r = run_morphogen("evolve " + q(t.config) + " --out " + q(dir) + " --force");
        CHECK(r.code == 3);
        CHECK_THAT(r.output, Catch::Contains("log.txt") && Catch::Contains("Is a directory"));
        fs::remove_all(dir / "log.txt");
        finish(t.config, dir);
        check_same_run(t.whole, dir);
    }
    SECTION("resume") {
        REQUIRE(run_morphogen("evolve " + q(t.config) + " --out " + q(dir) + " --generations 1").code == 0);
        const std::string checkpoint = read_text(dir / "checkpoint.json"), lineage = read_text(dir / "lineage.csv");
        fs::remove(dir / "log.txt");
        fs::create_directories(dir / "log.txt" / "inside");
        const CliResult r = run_morphogen("resume " + q(dir) + " --generations 3");
        CHECK(r.code == 3);
        CHECK_THAT(r.output, Catch::Contains("log.txt") && Catch::Contains("Is a directory"));
        CHECK(read_text(dir / "checkpoint.json") == checkpoint);
        CHECK(read_text(dir / "lineage.csv") == lineage);
        fs::remove_all(dir / "log.txt");
        finish(t.config, dir);
        check_same_run(t.whole, dir);
    }
}

TEST_CASE("a full disk: exit 3 with the reason, nothing partial, the checkpoint intact, then resumable",
          "[app][faults][disk-full]") {
    FaultRun t("faults-disk-full");
    const fs::path mount_point = t.tmp.path / "small";
    fs::create_directories(mount_point);
    if (::mount("tmpfs", mount_point.c_str(), "tmpfs", 0, "size=8k") != 0) {
        std::cout << "skipped the disk-full test: cannot mount a tmpfs here (" << std::strerror(errno) << ")\n";
        return;
    }
    struct Unmount {
        fs::path path;
        ~Unmount() { ::umount2(path.c_str(), MNT_DETACH); }
    } unmount{mount_point};

    int full = 0;
    // 8 KB to 120 KB: full at start-up, in the rows, the log, an export, a checkpoint, or not at all.
    for (int kb = 8; kb <= 120; kb += 8) {
        CAPTURE(kb);
        REQUIRE(::mount("tmpfs", mount_point.c_str(), "tmpfs", MS_REMOUNT, ("size=" + std::to_string(kb) + "k").c_str()) == 0);
        const auto dir = mount_point / numbered("r", kb);
        const CliResult r = run_morphogen("evolve " + q(t.config) + " --out " + q(dir));
        INFO(r.output);
        CHECK(temporaries(mount_point).empty());
        if (r.code == 3) {
            ++full;
            CHECK_THAT(r.output, Catch::Contains("No space left on device") && Catch::Contains(dir.string()));
            if (fs::exists(dir / "checkpoint.json")) {
                CHECK_NOTHROW(load_checkpoint(dir / "checkpoint.json"));
                CHECK_THAT(r.output, Catch::Contains("morphogen resume"));
            }
        } else {
            CHECK(r.code == 0);
        }
        // Free space, continue, compare; then make room for the next size.
        REQUIRE(::mount("tmpfs", mount_point.c_str(), "tmpfs", MS_REMOUNT, "size=4m") == 0);
        finish(t.config, dir);
        check_same_run(t.whole, dir);
        fs::remove_all(dir);
    }
    CHECK(full >= 5);
}

TEST_CASE("an atomic write that fails names the file and the reason and leaves nothing behind", "[app][faults]") {
    TempDir tmp("faults-atomic");
    const fs::path missing = tmp.path / "no-such-dir" / "f.json";
    CHECK_THROWS_WITH(write_file_atomically(missing, "x"),
                      Catch::Contains(missing.string()) && Catch::Contains("No such file or directory"));
    // The target is a non-empty directory: the rename fails after the temporary was written.
    fs::create_directories(tmp.path / "d.json" / "inside");
    CHECK_THROWS_WITH(write_file_atomically(tmp.path / "d.json", "x"),
                      Catch::Contains("d.json") && Catch::Contains("cannot replace"));
    CHECK(temporaries(tmp.path).empty());
    // A success replaces the old contents whole.
    write_text(tmp.path / "f.json", "old contents, longer than the new");
    write_file_atomically(tmp.path / "f.json", "new");
    CHECK(read_text(tmp.path / "f.json") == "new");
    CHECK(temporaries(tmp.path).empty());
}

TEST_CASE("an atomic write to a device writes into it instead of replacing it", "[app][faults]") {
    write_file_atomically("/dev/null", "bytes");  // as root, a rename would replace /dev/null itself
    struct stat info {};
    REQUIRE(::stat("/dev/null", &info) == 0);
    CHECK(S_ISCHR(info.st_mode));
    CHECK_FALSE(fs::exists("/dev/null.tmp"));
}
