// `morphogen breed --resume` after the worst a user does: kill -9 in the
// middle of a choice, and two servers started on one session
// (docs/breed.md, "The session directory").
#include "core/base/json_text.hpp"
#include "tests/breed/breed_test_support.hpp"
#include "tests/breed/server_process.hpp"
#include "tests/support/temp_dir.hpp"

#include <catch2/catch.hpp>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include <signal.h>

#include <atomic>
#include <chrono>
#include <sys/wait.h>
#include <cstdio>
#include <map>
#include <set>
#include <thread>

using namespace morphogen;
using namespace morphogen::testing;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The API of a running server (own names: the breed tests share one unity build).
struct ResumeClient {
    httplib::Client client;
    httplib::Headers auth;
    explicit ResumeClient(const BreedProcess& server)
        : client("127.0.0.1", server.port()), auth{{"Authorization", "Bearer " + server.token()}} {
        client.set_read_timeout(60, 0);
    }
    json state() {
        auto r = client.Get("/api/state", auth);
        REQUIRE(r);
        REQUIRE(r->status == 200);
        return json::parse(r->body);
    }
    int post(const std::string& path, const json& body) {
        auto r = client.Post(path, auth, body.dump(), "application/json");
        return r ? r->status : -1;
    }
};

std::string plant_file_id(std::uint64_t number) {
    char id[32];
    std::snprintf(id, sizeof id, "p%06llu", static_cast<unsigned long long>(number));
    return id;
}

// The files under genomes/, meshes/ and thumbs/ that no plant of state.json owns.
std::vector<std::string> unowned_plant_files(const fs::path& dir) {
    std::set<std::string> ids;
    const json state = read_json_object(read_text(dir / "state.json"));
    for (const json& p : state.at("plants")) ids.insert(p.at("id").get<std::string>());
    std::vector<std::string> unowned;
    for (const auto& [folder, suffix] : std::map<std::string, std::string>{
             {"genomes", ".genome.json"}, {"meshes", ".glb"}, {"thumbs", ".png"}}) {
        for (const auto& entry : fs::directory_iterator(dir / folder)) {
            const std::string name = entry.path().filename().string();
            if (!(name.ends_with(suffix) && ids.contains(name.substr(0, name.size() - suffix.size()))))
                unowned.push_back(folder + "/" + name);
        }
    }
    std::sort(unowned.begin(), unowned.end());
    return unowned;
}

// The line of a resume's stderr that names the files it removed; "" if none.
std::string removal_line(const std::string& stderr_text) {
    std::size_t at = stderr_text.find("no recorded choice owns");
    if (at == std::string::npos) return "";
    const std::size_t start = stderr_text.rfind('\n', at);
    const std::size_t end = stderr_text.find('\n', at);
    return stderr_text.substr(start == std::string::npos ? 0 : start + 1,
                              (end == std::string::npos ? stderr_text.size() : end) - (start == std::string::npos ? 0 : start + 1));
}

std::string expected_removal_line(const std::vector<std::string>& files) {
    if (files.empty()) return "";
    std::string line = "morphogen breed: removed " + std::to_string(files.size()) +
                       " plant files that no recorded choice owns (a choice cut short):";
    for (const std::string& f : files) line += " " + f;
    return line;
}

// Where in a choice the server is killed.
enum class KillPoint { at_once, first_genome_written, last_thumb_written, after_5_ms, after_20_ms };

// Waits until the file appears or `answered` (the choice ended first), at most 30 s.
void wait_for(const fs::path& file, const std::atomic<bool>& answered) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!fs::exists(file) && !answered && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
}

// Processes started with start_breed_command: their exit statuses once
// ended; those still running at the end are killed and reaped.
struct Reaper {
    std::vector<pid_t> pids;
    std::vector<int> statuses;  // -1 while running
    void start(const std::vector<std::string>& args, const fs::path& out, const fs::path& err) {
        pids.push_back(start_breed_command(args, out, err));
        statuses.push_back(-1);
    }
    int status(std::size_t k) {
        if (statuses[k] < 0) statuses[k] = exit_status_if_ended(pids[k]);
        return statuses[k];
    }
    // Waits up to 60 s for process k to end: its exit status, or -1.
    int wait(std::size_t k) {
        for (int i = 0; i < 6000 && status(k) < 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
        return status(k);
    }
    ~Reaper() {
        for (std::size_t k = 0; k < pids.size(); ++k) {
            if (status(k) >= 0) continue;
            ::kill(pids[k], SIGKILL);
            int ignored = 0;
            ::waitpid(pids[k], &ignored, 0);
        }
    }
};

}  // namespace

TEST_CASE("a kill -9 during a choice leaves nothing behind: resume removes what no choice owns, replay is the session",
          "[breed][server]") {
    TempDir tmp("breed_resume");
    const std::string dir = tmp.file("s");
    {
        BreedProcess first({tmp.write("tiny.json", kTinyBreedConfig), "--out", dir});
        first.signal(SIGKILL);
        first.wait();
    }
    std::size_t unowned_seen = 0;
    // The last kill leaves a whole choice's files with no state that owns them.
    for (KillPoint point : {KillPoint::first_genome_written, KillPoint::at_once, KillPoint::after_5_ms,
                            KillPoint::first_genome_written, KillPoint::after_20_ms, KillPoint::last_thumb_written}) {
        const std::vector<std::string> unowned = unowned_plant_files(dir);
        unowned_seen += unowned.size();
        BreedProcess server({"--resume", dir}, tmp.path / "resume.err");
        INFO("killed at point " << static_cast<int>(point) << " next; the last kill left " << unowned.size()
                                << " unowned files");
        CHECK(removal_line(read_text(tmp.path / "resume.err")) == expected_removal_line(unowned));
        CHECK(unowned_plant_files(dir).empty());
        ResumeClient api(server);
        REQUIRE(api.post("/api/breed", {{"parents", {grid_ids(api.state())[1]}}, {"strength", 0.6}}) == 200);
        // The choice in flight: 11 children, plants next_plant .. next_plant + 10.
        const std::uint64_t next = read_json_object(read_text(fs::path(dir) / "state.json")).at("next_plant");
        const std::string parent = grid_ids(api.state())[2];
        std::atomic<bool> answered{false};
        std::thread in_flight([&] {
            ResumeClient late(server);
            late.post("/api/breed", {{"parents", {parent}}});
            answered = true;
        });
        switch (point) {
            case KillPoint::at_once: break;
            case KillPoint::first_genome_written:
                wait_for(fs::path(dir) / "genomes" / (plant_file_id(next) + ".genome.json"), answered);
                break;
            case KillPoint::last_thumb_written:
                wait_for(fs::path(dir) / "thumbs" / (plant_file_id(next + 10) + ".png"), answered);
                break;
            case KillPoint::after_5_ms: std::this_thread::sleep_for(std::chrono::milliseconds(5)); break;
            case KillPoint::after_20_ms: std::this_thread::sleep_for(std::chrono::milliseconds(20)); break;
        }
        server.signal(SIGKILL);
        in_flight.join();
        CHECK(server.wait() == 128 + SIGKILL);
    }
    // Kills in the middle of writing a choice's plants left files behind.
    const std::vector<std::string> unowned = unowned_plant_files(dir);
    unowned_seen += unowned.size();
    CHECK(unowned_seen > 0);
    {
        // Resumed, an undo (no plant takes the ids of the files left), then Ctrl-C.
        BreedProcess last({"--resume", dir}, tmp.path / "resume.err");
        CHECK(removal_line(read_text(tmp.path / "resume.err")) == expected_removal_line(unowned));
        ResumeClient api(last);
        REQUIRE(api.post("/api/undo", json::object()) == 200);
        last.signal(SIGINT);
        CHECK(last.wait() == 0);
    }
    CHECK(replay_difference(dir, tmp.path / "r") == "");
}

TEST_CASE("two servers started at once on one session: one is refused, the session untouched", "[breed][server]") {
    TempDir tmp("breed_resume");
    const std::string dir = tmp.file("s");
    json before;
    {
        BreedProcess first({tmp.write("tiny.json", kTinyBreedConfig), "--out", dir});
        ResumeClient api(first);
        REQUIRE(api.post("/api/breed", {{"parents", {grid_ids(api.state())[0]}}}) == 200);
        before = api.state();
        first.signal(SIGTERM);
        REQUIRE(first.wait() == 0);
    }
    const std::vector<std::string> files = session_files(dir);
    std::map<std::string, std::string> bytes;
    for (const std::string& f : files) bytes[f] = read_text(fs::path(dir) / f);
    auto unchanged = [&] {
        CHECK(session_files(dir) == files);
        for (const std::string& f : files) CHECK(read_text(fs::path(dir) / f) == bytes[f]);
    };

    Reaper reaper;
    const std::vector<std::string> args = {"--resume", dir, "--no-browser", "--port", "0"};
    for (const char* name : {"a", "b"})
        reaper.start(args, tmp.path / (std::string(name) + ".out"), tmp.path / (std::string(name) + ".err"));
    // One of the two ends, refused; the other serves.
    int ended = -1;
    for (int i = 0; i < 6000 && ended < 0; ++i) {
        for (int k = 0; k < 2 && ended < 0; ++k)
            if (reaper.status(k) >= 0) ended = k;
        if (ended < 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    REQUIRE(ended >= 0);
    const std::size_t winner = ended == 0 ? 1 : 0;
    const std::string loser_name = ended == 0 ? "a" : "b", winner_name = ended == 0 ? "b" : "a";
    CHECK(reaper.status(ended) == 3);
    const std::string refusal = read_text(tmp.path / (loser_name + ".err"));
    CHECK(refusal.find("breeding session " + dir + " is in use by another morphogen process") != std::string::npos);
    for (int i = 0; i < 6000 && read_text(tmp.path / (winner_name + ".out")).find('\n') == std::string::npos; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    CHECK(read_text(tmp.path / (winner_name + ".out")).starts_with("http://127.0.0.1:"));
    CHECK(reaper.status(winner) == -1);
    unchanged();
    // A third, 1.5 s later while the winner serves: refused the same way.
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    CHECK(run_breed_command(args) == 3);
    unchanged();
    ::kill(reaper.pids[winner], SIGTERM);
    CHECK(reaper.wait(winner) == 0);
    unchanged();
    // The session opens normally afterwards, as it was.
    BreedProcess again({"--resume", dir});
    CHECK(ResumeClient(again).state() == before);
}
