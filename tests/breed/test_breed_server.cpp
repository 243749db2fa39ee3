// The API of `morphogen breed` against the real process (docs/breed.md):
// every refusal, many requests at once, two clients on one session,
// Ctrl-C, kill -9 then resume, and --replay.
#include "core/base/json_text.hpp"
#include "tests/breed/breed_test_support.hpp"
#include "tests/breed/server_process.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/sanitizers.hpp"

#include <catch2/catch.hpp>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include <signal.h>

#include <atomic>
#include <chrono>
#include <random>
#include <thread>

using namespace morphogen;
using namespace morphogen::testing;
using nlohmann::json;

namespace {

struct Api {
    httplib::Client client;
    std::string token;
    Api(const BreedProcess& p) : client("127.0.0.1", p.port()), token(p.token()) {
        client.set_read_timeout(60, 0);
    }
    httplib::Headers auth() const { return {{"Authorization", "Bearer " + token}}; }
    httplib::Result get(const std::string& path) { return client.Get(path, auth()); }
    httplib::Result post(const std::string& path, const json& body) {
        return client.Post(path, auth(), body.dump(), "application/json");
    }
    json state() {
        auto r = get("/api/state");
        REQUIRE(r);
        REQUIRE(r->status == 200);
        return json::parse(r->body);
    }
};

// The status of a reply, after checking that an error has its JSON body.
int status(const httplib::Result& r) {
    REQUIRE(r);
    if (r->status >= 400) {
        INFO(r->status << " " << r->body);
        const json body = json::parse(r->body, nullptr, false);
        CHECK(body.is_object());
        CHECK(body.contains("error"));
        CHECK(body.value("error", "").size() > 10);
        CHECK(r->get_header_value("Content-Type") == "application/json");
    }
    return r->status;
}

std::string config_file(const TempDir& tmp) { return tmp.write("tiny.json", kTinyBreedConfig); }

}  // namespace

TEST_CASE("the server prints its address, serves the page and API, and refuses what it must", "[breed][server]") {
    TempDir tmp("breed_server");
    BreedProcess server({config_file(tmp), "--out", tmp.file("s")});
    CHECK(server.token().size() == 32);
    CHECK(server.token().find_first_not_of("0123456789abcdef") == std::string::npos);
    Api api(server);
    httplib::Client& c = api.client;
    const std::string t = "?token=" + server.token();

    // The token, by query or by header.
    CHECK(status(c.Get("/api/state")) == 401);
    CHECK(status(c.Get("/api/state?token=0123456789abcdef0123456789abcdef")) == 401);
    CHECK(status(c.Get("/api/state", {{"Authorization", "Bearer wrong"}})) == 401);
    CHECK(status(c.Get("/api/state", {{"Authorization", "Basic " + server.token()}})) == 401);
    CHECK(status(c.Get("/" )) == 401);
    CHECK(status(c.Get("/api/mesh/p000000.glb")) == 401);
    CHECK(status(c.Get("/api/state" + t)) == 200);
    CHECK(status(api.get("/api/state")) == 200);

    // The page and its assets.
    auto page = c.Get("/" + t);
    REQUIRE(page);
    CHECK(page->status == 200);
    CHECK(page->get_header_value("Content-Type").starts_with("text/html"));
    CHECK(status(c.Get("/index.html" + t)) == 200);
    if (std::filesystem::exists("/usr/share/javascript/three/build/three.min.js")) {
        auto three = c.Get("/assets/three/build/three.min.js" + t);
        REQUIRE(three);
        CHECK(three->status == 200);
        CHECK(three->body.size() > 100000);
    }
    CHECK(status(c.Get("/assets/three/../../../../etc/passwd" + t)) == 404);
    CHECK(status(c.Get("/assets/three/%2e%2e/%2e%2e/%2e%2e/etc/passwd" + t)) == 404);
    CHECK(status(c.Get("/assets/nothing.js" + t)) == 404);
    CHECK(status(c.Get("/nowhere" + t)) == 404);

    // DNS rebinding: a Host or an Origin that is not the server's own.
    CHECK(status(c.Get("/api/state" + t, {{"Host", "evil.example:" + std::to_string(server.port())}})) == 403);
    CHECK(status(c.Get("/api/state" + t, {{"Host", "127.0.0.1:1"}})) == 403);
    CHECK(status(c.Get("/api/state" + t, {{"Host", "localhost:" + std::to_string(server.port())}})) == 200);
    CHECK(status(c.Get("/api/state" + t, {{"Origin", "http://evil.example"}})) == 403);
    CHECK(status(c.Get("/api/state" + t, {{"Origin", "http://localhost:" + std::to_string(server.port())}})) == 200);
    CHECK(status(c.Post("/api/undo" + t, {{"Origin", "http://127.0.0.1:1"}}, "{}", "application/json")) == 403);

    // Bodies: too large, not JSON, missing or wrong fields.
    const std::string big(70 * 1024, ' ');
    CHECK(status(c.Post("/api/breed", api.auth(), "{\"parents\": []}" + big, "application/json")) == 413);
    CHECK(status(api.client.Post("/api/breed", api.auth(), "{not json", "application/json")) == 400);
    CHECK(status(api.client.Post("/api/breed", api.auth(), "[1, 2]", "application/json")) == 400);
    CHECK(status(api.client.Post("/api/breed", api.auth(), "{\"a\": 1, \"a\": 2}", "application/json")) == 400);
    CHECK(status(api.post("/api/breed", json::object())) == 400);
    CHECK(status(api.post("/api/breed", {{"parents", "p000000"}})) == 400);
    CHECK(status(api.post("/api/breed", {{"parents", {1, 2}}})) == 400);
    CHECK(status(api.post("/api/breed", {{"parents", {"p000000"}}, {"strength", "strong"}})) == 400);
    CHECK(status(api.post("/api/breed", {{"parents", {"p000000"}}, {"strength", 2}})) == 400);
    CHECK(status(api.post("/api/breed", {{"parents", {"p000000"}}, {"colour", "red"}})) == 400);
    CHECK(status(api.post("/api/export", {{"height", 3}})) == 400);
    CHECK(status(api.post("/api/export", {{"id", "p000000"}, {"lods", 99}})) == 400);
    CHECK(status(api.post("/api/export", {{"id", "p000000"}, {"height", -2}})) == 400);
    CHECK(status(api.post("/api/explore", {{"parents", {"p000000"}}, {"births", 0}})) == 400);
    CHECK(status(api.post("/api/explore", {{"parents", {"p000000"}}, {"along", "sideways"}})) == 400);
    CHECK(status(api.post("/api/explore", {{"parents", {"p000000"}}, {"along", 1}})) == 400);

    // Unknown ids.
    CHECK(status(api.post("/api/breed", {{"parents", {"p999999"}}})) == 404);
    CHECK(status(api.post("/api/export", {{"id", "p999999"}})) == 404);
    CHECK(status(api.get("/api/mesh/p999999.glb")) == 404);
    CHECK(status(api.get("/api/thumb/p999999.png")) == 404);
    CHECK(status(api.get("/api/mesh/p000000.png")) == 404);

    // Wrong methods on known paths.
    CHECK(status(api.get("/api/breed")) == 405);
    CHECK(status(c.Delete("/api/state", api.auth())) == 405);
    CHECK(status(c.Put("/api/undo", api.auth(), "{}", "application/json")) == 405);
    CHECK(status(api.post("/api/state", json::object())) == 405);

    // Nothing to undo or redo; no search to stop.
    CHECK(status(api.post("/api/undo", json::object())) == 409);
    CHECK(status(api.post("/api/redo", json::object())) == 409);
    CHECK(status(api.post("/api/explore/stop", json::object())) == 409);

    // After all that, the session is as it started, and works.
    const json state = api.state();
    CHECK(state.at("generation") == 0);
    const std::vector<std::string> ids = grid_ids(state);
    auto mesh = api.get("/api/mesh/" + ids[0] + ".glb");
    REQUIRE(mesh);
    CHECK(mesh->status == 200);
    CHECK(mesh->get_header_value("Content-Type") == "model/gltf-binary");
    CHECK(mesh->body.substr(0, 4) == "glTF");
    auto thumb = c.Get("/api/thumb/" + ids[0] + ".png" + t);
    REQUIRE(thumb);
    CHECK(thumb->get_header_value("Content-Type") == "image/png");
    CHECK(thumb->body.substr(1, 3) == "PNG");
    auto bred = api.post("/api/breed", {{"parents", {ids[1], ids[2]}}, {"strength", 0.7}});
    REQUIRE(status(bred) == 200);
    CHECK(json::parse(bred->body).at("grid")[0].at("id") == ids[1]);
    CHECK(json::parse(bred->body).at("generation") == 1);
    auto exported = api.post("/api/export", {{"id", ids[1]}, {"height", 4.0}, {"lods", 2}, {"wind", true}});
    REQUIRE(status(exported) == 200);
    CHECK(json::parse(exported->body) == json({{"genome", "exports/" + ids[1] + ".genome.json"},
                                               {"mesh", "exports/" + ids[1] + ".glb"}}));
    CHECK(std::filesystem::exists(tmp.path / "s" / "exports" / (ids[1] + ".glb")));
    // Wind presets as grow's --wind-preset: written into the GLB; refused
    // without wind or by a name that is not a preset, writing nothing.
    auto presets = api.post("/api/export", {{"id", ids[1]}, {"wind", true}, {"wind_presets", {"uv"}}});
    REQUIRE(status(presets) == 200);
    const std::filesystem::path glb = tmp.path / "s" / "exports" / (ids[1] + ".glb");
    const std::string bytes = read_text(glb);
    CHECK(bytes.find("\"TEXCOORD_1\"") != std::string::npos);
    CHECK(bytes.find("\"COLOR_0\"") == std::string::npos);
    CHECK(status(api.post("/api/export", {{"id", ids[1]}, {"wind_presets", {"uv"}}})) == 400);
    CHECK(status(api.post("/api/export", {{"id", ids[1]}, {"wind", true}, {"wind_presets", {"unity"}}})) == 400);
    CHECK(status(api.post("/api/export", {{"id", ids[1]}, {"wind", true}, {"wind_presets", "uv"}})) == 400);
    CHECK(read_text(glb) == bytes);
    auto lineage = api.get("/api/lineage");
    REQUIRE(status(lineage) == 200);
    CHECK(json::parse(lineage->body).at("nodes").size() == 2);
    CHECK(status(api.post("/api/undo", json::object())) == 200);
    CHECK(status(api.post("/api/redo", json::object())) == 200);

    // The search: 202, progress, then a new grid.
    auto explore = api.post("/api/explore", {{"parents", {ids[1]}}, {"births", 40}});
    REQUIRE(explore);
    if (explore->status == 202) {
        CHECK(json::parse(explore->body).at("search").at("total") == 40);
        json s = api.state();
        for (int i = 0; i < 600 && s.at("search").at("running") == true; ++i) {
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            s = api.state();
        }
        CHECK(s.at("search").at("running") == false);
        CHECK(s.at("generation") == 2);
    } else {
        // The parent could not seed a search (no valid fitness or descriptors).
        CHECK(status(explore) == 400);
    }

    server.signal(SIGINT);
    CHECK(server.wait() == 0);
}

TEST_CASE("many requests at once: nothing crashes, nothing is lost", "[breed][server]") {
    TempDir tmp("breed_server");
    BreedProcess server({config_file(tmp), "--out", tmp.file("s")});
    constexpr int kThreads = 8, kRequests = whole_or_under_sanitizers(50, 20);
    std::atomic<int> breeds{0}, failures{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) {
        threads.emplace_back([&, t] {
            Api api(server);
            for (int i = 0; i < kRequests; ++i) {
                auto request = [&]() -> httplib::Result {
                    switch ((i + t) % 5) {
                        case 0: return api.get("/api/state");
                        case 1: return api.get("/api/lineage");
                        case 2: return api.get("/api/mesh/p000000.glb");
                        case 3: return api.get("/api/thumb/p000001.png");
                        default: {
                            // The first cell is the last grid's parent: always in the grid.
                            auto s = api.get("/api/state");
                            if (!s || s->status != 200) return s;
                            const std::string parent = json::parse(s->body).at("grid")[0].at("id");
                            auto r = api.post("/api/breed", {{"parents", {parent}}, {"strength", 0.3}});
                            if (r && r->status == 200) ++breeds;
                            return r;
                        }
                    }
                };
                const httplib::Result r = request();
                if (!r || r->status != 200) ++failures;
            }
        });
    }
    for (std::thread& t : threads) t.join();
    CHECK(failures == 0);
    CHECK(breeds == kThreads * kRequests / 5);
    Api api(server);
    const json state = api.state();
    CHECK(state.at("generation") == breeds.load());
    const std::string log = read_text(tmp.path / "s" / "choices.jsonl");
    CHECK(std::count(log.begin(), log.end(), '\n') == 1 + breeds.load());
    server.signal(SIGTERM);
    CHECK(server.wait() == 0);
    // Resumed, the same state.
    BreedProcess again({"--resume", tmp.file("s")});
    Api api2(again);
    CHECK(api2.state() == state);
}

TEST_CASE("two clients on one session see each other's choices", "[breed][server]") {
    TempDir tmp("breed_server");
    BreedProcess server({config_file(tmp), "--out", tmp.file("s")});
    Api a(server), b(server);
    const std::vector<std::string> ids = grid_ids(a.state());
    CHECK(grid_ids(b.state()) == ids);
    REQUIRE(status(a.post("/api/breed", {{"parents", {ids[4]}}})) == 200);
    const json seen = b.state();
    CHECK(seen.at("generation") == 1);
    CHECK(seen.at("grid")[0].at("id") == ids[4]);
    REQUIRE(status(b.post("/api/undo", json::object())) == 200);
    CHECK(grid_ids(a.state()) == ids);
    // A choice made on a grid the other client has replaced is refused, not misapplied.
    REQUIRE(status(a.post("/api/breed", {{"parents", {ids[0]}}})) == 200);
    const std::vector<std::string> second = grid_ids(a.state());
    CHECK(status(b.post("/api/breed", {{"parents", {ids[3]}}})) == 400);
    CHECK(grid_ids(b.state()) == second);
}

TEST_CASE("kill -9 at any moment, then resume, loses at most the last choice", "[breed][server]") {
    TempDir tmp("breed_server");
    const std::string config = config_file(tmp);
    const std::string dir = tmp.file("s");
    std::mt19937 random(12345);
    int made = 0;  // choices the server answered
    {
        BreedProcess first({config, "--out", dir});
        Api api(first);
        REQUIRE(status(api.post("/api/breed", {{"parents", {grid_ids(api.state())[0]}}})) == 200);
        made = 1;
        first.signal(SIGKILL);
        first.wait();
    }
    for (int round = 0; round < 6; ++round) {
        BreedProcess server({"--resume", dir});
        Api api(server);
        const json resumed = api.state();
        const int generation = resumed.at("generation");
        INFO("round " << round << ": " << made << " choices answered, generation " << generation);
        // Every answered choice survived; the one in flight at the kill may not have.
        CHECK(generation >= made);
        CHECK(generation <= made + 1);
        made = generation;
        const std::string log = read_text(tmp.path / "s" / "choices.jsonl");
        CHECK(std::count(log.begin(), log.end(), '\n') == 1 + generation);
        // Answered choices, then one in flight, killed after a random delay.
        for (int i = 0; i < 2; ++i) {
            const std::string parent = grid_ids(api.state())[0];
            REQUIRE(status(api.post("/api/breed", {{"parents", {parent}}, {"strength", 0.4}})) == 200);
            ++made;
        }
        const std::string parent = grid_ids(api.state())[0];
        std::thread in_flight([&] {
            Api late(server);
            late.post("/api/breed", {{"parents", {parent}}});
        });
        std::this_thread::sleep_for(std::chrono::microseconds(std::uniform_int_distribution<int>(0, 80000)(random)));
        server.signal(SIGKILL);
        in_flight.join();
        CHECK(server.wait() == 128 + SIGKILL);
    }
    // The session that survived, resumed (which removes what the last kill
    // left) and stopped, replays to the same bytes.
    BreedProcess last({"--resume", dir});
    last.signal(SIGTERM);
    CHECK(last.wait() == 0);
    CHECK(replay_difference(dir, tmp.path / "r") == "");
}

TEST_CASE("Ctrl-C saves and stops; --replay refuses what it cannot replay", "[breed][server]") {
    TempDir tmp("breed_server");
    json before;
    {
        BreedProcess server({config_file(tmp), "--out", tmp.file("s"), "--seed", "99"});
        Api api(server);
        REQUIRE(status(api.post("/api/breed", {{"parents", {grid_ids(api.state())[5]}}})) == 200);
        before = api.state();
        server.signal(SIGINT);
        CHECK(server.wait() == 0);
    }
    CHECK(read_json_object(read_text(tmp.path / "s" / "config.json")).at("run").at("seed") == 99);
    BreedProcess again({"--resume", tmp.file("s")});
    Api api(again);
    CHECK(api.state() == before);
    CHECK(again.token() != "");
    CHECK(replay_difference(tmp.path / "s", tmp.path / "r") == "");
    CHECK(run_breed_command({"--replay", tmp.file("s"), "--out", tmp.file("r")}) != 0);  // r holds files
    CHECK(run_breed_command({"--replay", tmp.file("s")}) == 2);                           // no --out
    CHECK(run_breed_command({"--resume", tmp.file("s"), "--seed", "3"}) == 2);
}

TEST_CASE("Ctrl-C during a search keeps what it found as the next grid", "[breed][server]") {
    TempDir tmp("breed_server");
    json started;
    {
        BreedProcess server({config_file(tmp), "--out", tmp.file("s")});
        Api api(server);
        std::string parent;
        const json state = api.state();
        for (const json& p : state.at("grid"))
            if (parent.empty() && p.at("fitness").is_number() && p.at("measures").contains("spread"))
                parent = p.at("id").get<std::string>();
        REQUIRE(!parent.empty());
        auto r = api.post("/api/explore", {{"parents", {parent}}, {"births", 100000}});
        REQUIRE(status(r) == 202);
        json s = api.state();
        for (int i = 0; i < 400 && s.at("search").at("done").get<int>() < 3; ++i) {
            std::this_thread::sleep_for(std::chrono::milliseconds(25));
            s = api.state();
        }
        CHECK(s.at("search").at("running") == true);
        CHECK(s.at("can_undo") == false);
        CHECK(status(api.post("/api/undo", json::object())) == 409);
        server.signal(SIGINT);
        CHECK(server.wait() == 0);
    }
    BreedProcess again({"--resume", tmp.file("s")});
    Api api(again);
    const json resumed = api.state();
    CHECK(resumed.at("generation") == 1);
    CHECK(resumed.at("grid").size() == 12);
    const std::string log = read_text(tmp.path / "s" / "choices.jsonl");
    CHECK(log.find("\"choice\":\"explore\"") != std::string::npos);
    CHECK(replay_difference(tmp.path / "s", tmp.path / "r") == "");
}
