// The breeding session (breed/session.hpp): grids, breeding, undo/redo,
// lineage, the session directory, resume and replay to the same bytes.
#include "breed/breed_errors.hpp"
#include "breed/session.hpp"
#include "tests/breed/breed_test_support.hpp"
#include "tests/support/temp_dir.hpp"
#include "core/base/json_text.hpp"

#include <cmath>
#include <functional>
#include <map>

#include <catch2/catch.hpp>

#include <set>

using namespace morphogen;
using namespace morphogen::testing;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

int status_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const BreedRequestError& e) {
        return e.status;
    }
    return 0;
}

std::size_t files_in(const fs::path& dir) {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

std::size_t lines(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

// A few choices every determinism test makes.
void make_choices(BreedSession& s) {
    std::vector<std::string> g = grid_ids(s.state_json());
    s.breed({g[3], g[5]}, 0.5);
    g = grid_ids(s.state_json());
    s.breed({g[7]}, 1.0);
    s.undo();
    g = grid_ids(s.state_json());
    s.breed({g[2]}, 0.2);
    s.undo();
    s.redo();
}

}  // namespace

TEST_CASE("a new session shows a grid of plants and writes its directory", "[breed]") {
    TempDir tmp("breed");
    const auto session = BreedSession::create(tmp.path / "s", tiny_breed_config(), {});
    const json state = session->state_json();
    CHECK(state.at("session") == "s");
    CHECK(state.at("generation") == 0);
    REQUIRE(state.at("grid").size() == kBreedGridSize);
    CHECK(state.at("chosen").empty());
    CHECK(state.at("can_undo") == false);
    CHECK(state.at("can_redo") == false);
    CHECK(state.at("search").at("running") == false);
    std::set<std::string> ids;
    for (const json& p : state.at("grid")) {
        ids.insert(p.at("id").get<std::string>());
        CHECK(p.at("parents").empty());
        CHECK(p.at("mesh") == "/api/mesh/" + p.at("id").get<std::string>() + ".glb");
        CHECK(p.at("measures").at("vertices").get<double>() > 3);
        CHECK((p.at("fitness").is_null() || p.at("fitness").is_number()));
        CHECK(std::filesystem::exists(tmp.path / "s" / "genomes" / (p.at("id").get<std::string>() + ".genome.json")));
        CHECK(session->mesh_glb(p.at("id")).substr(0, 4) == "glTF");
        CHECK(session->thumb_png(p.at("id")).substr(1, 3) == "PNG");
    }
    CHECK(ids.size() == kBreedGridSize);
    for (const char* f : {"config.json", "state.json", "choices.jsonl", "lineage.csv"})
        CHECK(std::filesystem::exists(tmp.path / "s" / f));
    CHECK(lines(read_text(tmp.path / "s" / "lineage.csv")) == 1 + kBreedGridSize);
    CHECK(read_text(tmp.path / "s" / "choices.jsonl") == "{\"choice\":\"start\",\"from\":[]}\n");
    // A directory with files is refused: nothing is lost.
    CHECK_THROWS_WITH(BreedSession::create(tmp.path / "s", tiny_breed_config(), {}),
                      Catch::Contains("not an empty directory") && Catch::Contains("--resume"));
}

TEST_CASE("breeding keeps the parents and gives their children; undo and redo walk the grids", "[breed]") {
    TempDir tmp("breed");
    const auto session = BreedSession::create(tmp.path / "s", tiny_breed_config(), {});
    const std::vector<std::string> first = grid_ids(session->state_json());
    session->breed({first[2], first[9]}, 0.5);
    const json bred = session->state_json();
    const std::vector<std::string> second = grid_ids(bred);
    REQUIRE(second.size() == kBreedGridSize);
    CHECK(second[0] == first[2]);
    CHECK(second[1] == first[9]);
    CHECK(bred.at("generation") == 1);
    CHECK(bred.at("chosen") == json({first[2], first[9]}));
    for (std::size_t i = 2; i < second.size(); ++i) {
        CHECK(bred.at("grid")[i].at("parents") == json({first[2], first[9]}));
        CHECK(bred.at("grid")[i].at("generation") == 1);
        CHECK(std::find(first.begin(), first.end(), second[i]) == first.end());
    }
    CHECK(bred.at("can_undo") == true);

    session->undo();
    CHECK(grid_ids(session->state_json()) == first);
    CHECK(session->state_json().at("can_redo") == true);
    session->redo();
    CHECK(grid_ids(session->state_json()) == second);
    CHECK(status_of([&] { session->redo(); }) == 409);

    // A new choice after an undo drops the undone grid from redo.
    session->undo();
    session->breed({first[0]}, 1.0);
    const json third = session->state_json();
    CHECK(third.at("can_redo") == false);
    CHECK(third.at("grid")[0].at("id") == first[0]);
    CHECK(third.at("grid")[1].at("parents") == json({first[0]}));
    session->undo();
    CHECK(status_of([&] { session->undo(); }) == 409);

    // The refusals, each leaving the session as it was.
    const std::string before = read_text(tmp.path / "s" / "state.json");
    CHECK(status_of([&] { session->breed({}, 0.5); }) == 400);
    CHECK(status_of([&] { session->breed({first[0], first[1], first[2]}, 0.5); }) == 400);
    CHECK(status_of([&] { session->breed({first[0], first[0]}, 0.5); }) == 400);
    CHECK(status_of([&] { session->breed({first[0]}, 0.0); }) == 400);
    CHECK(status_of([&] { session->breed({first[0]}, 1.5); }) == 400);
    CHECK(status_of([&] { session->breed({first[0]}, std::nan("")); }) == 400);
    CHECK(status_of([&] { session->breed({"p999999"}, 0.5); }) == 404);
    CHECK(status_of([&] { session->breed({second[5]}, 0.5); }) == 400);  // known, not in this grid
    CHECK(status_of([&] { session->mesh_glb("nope"); }) == 404);
    CHECK(status_of([&] { session->thumb_png("p999999"); }) == 404);
    CHECK(read_text(tmp.path / "s" / "state.json") == before);
}

TEST_CASE("stronger breeding moves the children further from their parent", "[breed]") {
    TempDir tmp("breed");
    const auto session = BreedSession::create(tmp.path / "s", tiny_breed_config(), {});
    const std::string parent = grid_ids(session->state_json())[0];
    auto mean_distance = [&](double strength) {
        session->breed({parent}, strength);
        const json state = session->state_json();
        const std::vector<double> p =
            read_json_object(read_text(tmp.path / "s" / "genomes" / (parent + ".genome.json"))).at("params");
        double total = 0.0;
        for (std::size_t i = 1; i < kBreedGridSize; ++i) {
            const std::string id = state.at("grid")[i].at("id");
            const std::vector<double> c =
                read_json_object(read_text(tmp.path / "s" / "genomes" / (id + ".genome.json"))).at("params");
            REQUIRE(c.size() == p.size());
            CHECK(c != p);  // never a clone
            for (std::size_t k = 0; k < c.size(); ++k) total += std::abs(c[k] - p[k]);
        }
        session->undo();
        return total;
    };
    CHECK(mean_distance(1.0) > 2.0 * mean_distance(0.1));
}

TEST_CASE("the lineage holds every chosen plant and its ancestors; lineage.csv every plant shown", "[breed]") {
    TempDir tmp("breed");
    const auto session = BreedSession::create(tmp.path / "s", tiny_breed_config(), {});
    CHECK(session->lineage_json().at("nodes").empty());
    const std::vector<std::string> g0 = grid_ids(session->state_json());
    session->breed({g0[1], g0[4]}, 0.5);
    const std::vector<std::string> g1 = grid_ids(session->state_json());
    session->breed({g1[6]}, 0.5);
    const json nodes = session->lineage_json().at("nodes");
    std::map<std::string, json> by_id;
    for (const json& n : nodes) by_id[n.at("id")] = n;
    CHECK(by_id.size() == 3);
    CHECK(by_id.at(g1[6]).at("chosen") == true);
    CHECK(by_id.at(g1[6]).at("parents") == json({g0[1], g0[4]}));
    CHECK(by_id.at(g0[1]).at("chosen") == true);
    CHECK(by_id.at(g0[4]).at("thumb") == "/api/thumb/" + g0[4] + ".png");
    const std::string csv = read_text(tmp.path / "s" / "lineage.csv");
    CHECK(lines(csv) == 1 + kBreedGridSize + 10 + 11);
    CHECK(csv.find(g1[6] + "," + g0[1] + "," + g0[4] + ",1,1\n") != std::string::npos);
    CHECK(csv.find(g0[0] + ",,,0,0\n") != std::string::npos);
}

TEST_CASE("plants are a function of the seed and the choices: replay and resume give the same bytes", "[breed]") {
    TempDir tmp("breed");
    {
        const auto a = BreedSession::create(tmp.path / "a", tiny_breed_config(), {});
        make_choices(*a);
    }
    const auto b = BreedSession::replay(tmp.path / "a", tmp.path / "b");
    b.get();
    CHECK(session_difference(tmp.path / "a", tmp.path / "b") == "");
    CHECK(lines(read_text(tmp.path / "a" / "choices.jsonl")) == 7);

    // Interrupted after every choice and resumed: the same session.
    {
        auto c = BreedSession::create(tmp.path / "c", tiny_breed_config(), {});
        std::vector<std::string> g = grid_ids(c->state_json());
        c->breed({g[3], g[5]}, 0.5);
        c.reset();  // one session per directory at a time
        c = BreedSession::resume(tmp.path / "c");
        g = grid_ids(c->state_json());
        c->breed({g[7]}, 1.0);
        c.reset();  // one session per directory at a time
        c = BreedSession::resume(tmp.path / "c");
        c->undo();
        c.reset();  // one session per directory at a time
        c = BreedSession::resume(tmp.path / "c");
        g = grid_ids(c->state_json());
        c->breed({g[2]}, 0.2);
        c->undo();
        c.reset();  // one session per directory at a time
        c = BreedSession::resume(tmp.path / "c");
        c->redo();
    }
    CHECK(session_difference(tmp.path / "a", tmp.path / "c") == "");

    // Another seed, other plants.
    {
        const auto d = BreedSession::create(tmp.path / "d", tiny_breed_config(8), {});
        make_choices(*d);
    }
    CHECK(read_text(tmp.path / "a" / "genomes" / "p000000.genome.json") !=
          read_text(tmp.path / "d" / "genomes" / "p000000.genome.json"));
}

TEST_CASE("a session started from genomes keeps them and replays from its own copies", "[breed]") {
    TempDir tmp("breed");
    std::vector<std::vector<double>> from;
    {
        const auto a = BreedSession::create(tmp.path / "a", tiny_breed_config(), {});
        for (const char* id : {"p000004", "p000008"})
            from.push_back(read_json_object(read_text(tmp.path / "a" / "genomes" / (std::string(id) + ".genome.json")))
                               .at("params")
                               .get<std::vector<double>>());
    }
    {
        const auto s = BreedSession::create(tmp.path / "s", tiny_breed_config(), from);
        const json state = s->state_json();
        CHECK(state.at("grid")[0].at("parents").empty());
        CHECK(state.at("grid")[2].at("parents") == json({"p000000"}));
        CHECK(state.at("grid")[3].at("parents") == json({"p000001"}));
        CHECK(read_text(tmp.path / "s" / "genomes" / "p000000.genome.json") ==
              read_text(tmp.path / "a" / "genomes" / "p000004.genome.json"));
        make_choices(*s);
    }
    CHECK(read_text(tmp.path / "s" / "choices.jsonl").starts_with("{\"choice\":\"start\",\"from\":[\"p000000\",\"p000001\"]}\n"));
    BreedSession::replay(tmp.path / "s", tmp.path / "r");
    CHECK(session_difference(tmp.path / "s", tmp.path / "r") == "");
    std::vector<std::vector<double>> wrong = {std::vector<double>(3, 0.0)};
    CHECK_THROWS_WITH(BreedSession::create(tmp.path / "w", tiny_breed_config(), wrong), Catch::Contains("parameters"));
}

TEST_CASE("resume refuses what is not a session and drops a choice whose state was never written", "[breed]") {
    TempDir tmp("breed");
    CHECK_THROWS_WITH(BreedSession::resume(tmp.path), Catch::Contains("state.json") && Catch::Contains("missing"));
    {
        const auto s = BreedSession::create(tmp.path / "s", tiny_breed_config(), {});
        s->breed({grid_ids(s->state_json())[0]}, 0.5);
    }
    // A kill -9 between appending a choice and writing state.json leaves a
    // line the state does not hold: resume cuts it off.
    const std::string log = read_text(tmp.path / "s" / "choices.jsonl");
    write_text(tmp.path / "s" / "choices.jsonl", log + "{\"choice\":\"undo\"}\n");
    auto s = BreedSession::resume(tmp.path / "s");
    CHECK(s->state_json().at("generation") == 1);
    CHECK(read_text(tmp.path / "s" / "choices.jsonl") == log);
    s.reset();
    // A damaged state is refused with its file named.
    write_text(tmp.path / "s" / "state.json", "{\"format\": 3}");
    CHECK_THROWS_WITH(BreedSession::resume(tmp.path / "s"), Catch::Contains("state.json"));
}

TEST_CASE("one session per directory: a second resume is refused and leaves the files; a killed one holds nothing",
          "[breed]") {
    TempDir tmp("breed");
    const fs::path dir = tmp.path / "s";
    auto first = BreedSession::create(dir, tiny_breed_config(), {});
    first->breed({grid_ids(first->state_json())[0]}, 0.5);
    const std::vector<std::string> files = session_files(dir);
    std::map<std::string, std::string> bytes;
    for (const std::string& f : files) bytes[f] = read_text(dir / f);
    // Today's second server: refused before it reads or writes anything.
    CHECK_THROWS_WITH(BreedSession::resume(dir), Catch::Contains("in use by another morphogen process"));
    CHECK(session_files(dir) == files);
    for (const std::string& f : files) CHECK(read_text(dir / f) == bytes[f]);
    // The first session goes on, and its directory opens once it is gone
    // (the lock dies with its holder, as with kill -9).
    first->undo();
    const json state = first->state_json();
    first.reset();
    CHECK(BreedSession::resume(dir)->state_json() == state);
}

TEST_CASE("export writes the genome and an engine-ready GLB", "[breed]") {
    TempDir tmp("breed");
    const auto s = BreedSession::create(tmp.path / "s", tiny_breed_config(), {});
    // The grid's plant with the most faces: two levels need at least 64.
    std::string id;
    double faces = 0;
    const json state = s->state_json();
    for (const json& plant : state.at("grid"))
        if (plant.at("measures").at("faces").get<double>() > faces) {
            faces = plant.at("measures").at("faces").get<double>();
            id = plant.at("id");
        }
    REQUIRE(faces >= 64);
    PlantExportOptions options;
    options.height_m = 4.0;
    options.lods = 2;
    options.wind = true;
    const auto [genome, mesh] = s->export_plant(id, options);
    CHECK(genome == "exports/" + id + ".genome.json");
    CHECK(mesh == "exports/" + id + ".glb");
    CHECK(read_text(tmp.path / "s" / genome) == read_text(tmp.path / "s" / "genomes" / (id + ".genome.json")));
    const std::string glb = read_text(tmp.path / "s" / mesh);
    CHECK(glb.substr(0, 4) == "glTF");
    CHECK(glb.find("_WIND") != std::string::npos);
    CHECK(glb.find("LOD1") != std::string::npos);
    CHECK(glb.find("plant_" + id) != std::string::npos);
    PlantExportOptions bad;
    bad.height_m = -1.0;
    CHECK(status_of([&] { s->export_plant(id, bad); }) == 400);
    CHECK(status_of([&] { s->export_plant("p123456", {}); }) == 404);
}

TEST_CASE("a choice that cannot be saved changes nothing: the session stays what its files say", "[breed]") {
    TempDir tmp("breed");
    const fs::path dir = tmp.path / "s";
    auto s = BreedSession::create(dir, tiny_breed_config(), {});
    s->breed({grid_ids(s->state_json())[0]}, 0.5);
    const json before = s->state_json();
    const std::string log = read_text(dir / "choices.jsonl");
    const std::string state_file = read_text(dir / "state.json");
    const std::size_t genome_files = files_in(dir / "genomes");
    // state.json cannot be replaced while a non-empty directory stands in its place.
    fs::rename(dir / "state.json", tmp.path / "state.json.kept");
    fs::create_directories(dir / "state.json" / "blocker");
    const std::vector<std::string> g = grid_ids(before);
    CHECK_THROWS(s->breed({g[1], g[2]}, 0.5));
    CHECK_THROWS(s->undo());
    CHECK(s->state_json() == before);
    CHECK(read_text(dir / "choices.jsonl") == log);
    CHECK(files_in(dir / "genomes") == genome_files);
    CHECK(files_in(dir / "meshes") == genome_files);
    // The disk is back: the next choices follow the last saved one, and the
    // files resume and replay to this session.
    fs::remove_all(dir / "state.json");
    fs::rename(tmp.path / "state.json.kept", dir / "state.json");
    s->breed({g[1], g[2]}, 0.5);
    s->undo();
    const json after = s->state_json();
    CHECK(lines(read_text(dir / "choices.jsonl")) == lines(log) + 2);
    s.reset();
    CHECK(BreedSession::resume(dir)->state_json() == after);
    BreedSession::replay(dir, tmp.path / "r");
    CHECK(session_difference(dir, tmp.path / "r") == "");
    CHECK(state_file != read_text(dir / "state.json"));
}
