// `evolve --from` (and run.from): generation 0 starts from given genomes (a
// genome file, a run directory's best or elites, a breed session's exports)
// and their mutants; the run keeps copies in seeds/, so it gives the same
// bytes for 1 and 2 threads and after a resume with the originals gone.
#include "tests/app/evolve_test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

using namespace morphogen;
using namespace morphogen::test;

namespace evolve_from_test {
// The fitness column of lineage.csv, one string per birth.
std::vector<std::string> fitness_column(const fs::path& run) {
    std::istringstream in(read_text(run / "lineage.csv"));
    std::vector<std::string> column;
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::istringstream row(line);
        for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
        column.push_back(cells.size() > 4 ? cells[4] : "");
    }
    return column;
}

// The highest fitness in a run's lineage.csv (its best's).
double best_fitness(const fs::path& run) {
    double best = -1e300;
    for (const std::string& f : fitness_column(run))
        if (!f.empty()) best = std::max(best, std::stod(f));
    return best;
}

nlohmann::json manifest(const fs::path& run) { return nlohmann::json::parse(read_text(run / "seeds" / "manifest.json")); }

std::string seeded_me_config(int population) {
    return R"({"network": {"outputs": 4, "hidden": [4]},
 "growth": {"steps": 8, "max_vertices": 200},
 "fitness": {"type": "height"},
 "evolution": {"algorithm": "map_elites", "population": )" + std::to_string(population) + R"(, "batch": 4, "mutation_rate": 0.2},
 "descriptors": [{"measure": "height", "min": 0, "max": 3, "bins": 6}, {"measure": "footprint", "min": 0, "max": 10, "bins": 5}],
 "archive": {"type": "grid", "qd_offset": -1},
 "run": {"seed": 3, "generations": 2, "export_every": 0}})";
}

// tiny_config with exports of each generation's best.
std::string exporting_config(int generations) {
    std::string text = tiny_config(generations);
    text.replace(text.find("\"export_every\": 0"), 17, "\"export_every\": 1");
    return text;
}

// A finished GA run of tiny_config (generation 2), with best/ exports.
fs::path source_run(const TempDir& tmp) {
    write_text(tmp.path / "source.json", exporting_config(2));
    const fs::path run = tmp.path / "source";
    REQUIRE(run_morphogen("evolve " + q(tmp.path / "source.json") + " --out " + q(run)).code == 0);
    return run;
}

std::string evolve(const fs::path& config, const fs::path& out, const std::string& more) {
    return "evolve " + q(config) + " --out " + q(out) + " " + more;
}
}  // namespace evolve_from_test

using namespace evolve_from_test;

TEST_CASE("evolve --from a genome file starts generation 0 from it and records a copy", "[app][evolve][from]") {
    TempDir tmp("from-file");
    const fs::path source = source_run(tmp);
    const fs::path genome = tmp.path / "best.genome.json";
    fs::copy_file(source / "best" / "gen_0002.genome.json", genome);
    write_text(tmp.path / "c.json", tiny_config(2));
    REQUIRE(run_morphogen(evolve(tmp.path / "c.json", tmp.path / "plain", "")).code == 0);
    const CliResult r = run_morphogen(evolve(tmp.path / "c.json", tmp.path / "seeded", "--from " + q(genome)));
    REQUIRE(r.code == 0);
    const std::vector<std::string> seeded = fitness_column(tmp.path / "seeded");
    const std::vector<std::string> plain = fitness_column(tmp.path / "plain");
    REQUIRE(seeded.size() == plain.size());
    CHECK(std::stod(seeded[0]) == best_fitness(source));  // birth 0 is the given genome itself
    CHECK(seeded != plain);                                // the rest are its mutants, not random genomes
    CHECK(!fs::exists(tmp.path / "plain" / "seeds"));       // a run without --from records none
    const nlohmann::json m = manifest(tmp.path / "seeded");
    REQUIRE(m["seeds"].size() == 1);
    CHECK(m["seeds"][0]["origin"] == genome.string());
    CHECK(nlohmann::json::parse(read_text(tmp.path / "seeded" / "seeds" / "seed_000.genome.json"))["params"] ==
          nlohmann::json::parse(read_text(genome))["params"]);
    CHECK(nlohmann::json::parse(read_text(tmp.path / "seeded" / "config.json"))["run"]["from"] ==
          nlohmann::json::array({genome.string()}));

    // run.from in the config does the same as --from
    nlohmann::json config = nlohmann::json::parse(tiny_config(2));
    config["run"]["from"] = {genome.string()};
    write_text(tmp.path / "keyed.json", config.dump());
    REQUIRE(run_morphogen(evolve(tmp.path / "keyed.json", tmp.path / "keyed", "")).code == 0);
    CHECK(read_text(tmp.path / "keyed" / "lineage.csv") == read_text(tmp.path / "seeded" / "lineage.csv"));

    // a relative run.from is taken from the config's folder, not the working directory
    fs::create_directories(tmp.path / "configs");
    config["run"]["from"] = {fs::relative(genome, tmp.path / "configs").string()};
    write_text(tmp.path / "configs" / "beside.json", config.dump());
    REQUIRE(run_morphogen(evolve(tmp.path / "configs" / "beside.json", tmp.path / "beside", "")).code == 0);
    CHECK(read_text(tmp.path / "beside" / "lineage.csv") == read_text(tmp.path / "seeded" / "lineage.csv"));
    CHECK(manifest(tmp.path / "beside")["seeds"][0]["origin"] ==
          (tmp.path / "configs" / fs::relative(genome, tmp.path / "configs")).lexically_normal().string());
}

TEST_CASE("evolve --from a run directory takes a GA run's best and a MAP-Elites run's elites", "[app][evolve][from]") {
    TempDir tmp("from-run");
    const fs::path source = source_run(tmp);
    write_text(tmp.path / "c.json", tiny_config(1));
    REQUIRE(run_morphogen(evolve(tmp.path / "c.json", tmp.path / "ga", "--from " + q(source))).code == 0);
    CHECK(std::stod(fitness_column(tmp.path / "ga")[0]) == best_fitness(source));
    CHECK(manifest(tmp.path / "ga")["seeds"][0]["origin"] == source.string() + " (best)");

    write_text(tmp.path / "me.json", seeded_me_config(12));
    REQUIRE(run_morphogen(evolve(tmp.path / "me.json", tmp.path / "me", "")).code == 0);
    std::istringstream archive(read_text(tmp.path / "me" / "archive.csv"));
    std::size_t elites = 0;
    for (std::string line; std::getline(archive, line);) elites += line.empty() ? 0 : 1;
    elites -= 1;  // header
    REQUIRE(elites >= 2);
    write_text(tmp.path / "me40.json", seeded_me_config(40));
    REQUIRE(run_morphogen(evolve(tmp.path / "me40.json", tmp.path / "seeded", "--threads 2 --from " + q(tmp.path / "me")))
                .code == 0);
    REQUIRE(run_morphogen(evolve(tmp.path / "me40.json", tmp.path / "seeded1",
                                 "--threads 1 --from " + q(tmp.path / "me")))
                .code == 0);
    check_same_results(tmp.path / "seeded", tmp.path / "seeded1");  // a seeded MAP-Elites run, 1 and 2 threads
    CHECK(read_text(tmp.path / "seeded" / "archive.csv") == read_text(tmp.path / "seeded1" / "archive.csv"));
    const nlohmann::json m = manifest(tmp.path / "seeded");
    REQUIRE(m["seeds"].size() == elites);
    CHECK(m["seeds"][1]["origin"] == (tmp.path / "me").string() + " (elite 1)");
    CHECK(std::stod(fitness_column(tmp.path / "seeded")[0]) <= best_fitness(tmp.path / "me"));
    std::vector<std::string> first = fitness_column(tmp.path / "seeded");
    first.resize(elites);
    CHECK(std::find_if(first.begin(), first.end(), [&](const std::string& f) {
              return std::stod(f) == best_fitness(tmp.path / "me");
          }) != first.end());  // the elites themselves come first, the best among them

    // more genomes than generation 0 holds: refused before the directory is made
    write_text(tmp.path / "two.json", tiny_config(1, 2, 1));
    const CliResult r = run_morphogen(evolve(tmp.path / "two.json", tmp.path / "small", "--from " + q(tmp.path / "me") +
                                                                                            " --from " + q(tmp.path / "me")));
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains("more than generation 0 holds"));
    CHECK(!fs::exists(tmp.path / "small"));
}

TEST_CASE("evolve --from a breed session takes the genomes of its exports", "[app][evolve][from][breed]") {
    TempDir tmp("from-breed");
    const fs::path source = source_run(tmp);
    // what a breed session's Export writes: exports/<id>.genome.json (beside genomes/ of every plant)
    const fs::path session = tmp.path / "session";
    fs::create_directories(session / "exports");
    fs::create_directories(session / "genomes");
    fs::copy_file(source / "best" / "gen_0002.genome.json", session / "exports" / "b.genome.json");
    fs::copy_file(source / "best" / "gen_0000.genome.json", session / "exports" / "a.genome.json");
    fs::copy_file(source / "best" / "gen_0001.genome.json", session / "genomes" / "x.genome.json");
    write_text(tmp.path / "c.json", tiny_config(1));
    REQUIRE(run_morphogen(evolve(tmp.path / "c.json", tmp.path / "seeded", "--from " + q(session))).code == 0);
    const nlohmann::json m = manifest(tmp.path / "seeded");
    REQUIRE(m["seeds"].size() == 2);  // the exports only, by name
    CHECK(m["seeds"][0]["origin"] == (session / "exports" / "a.genome.json").string());
    CHECK(m["seeds"][1]["origin"] == (session / "exports" / "b.genome.json").string());
    CHECK(std::stod(fitness_column(tmp.path / "seeded")[1]) == best_fitness(source));
}

TEST_CASE("evolve --from a genome of another network shape names both shapes", "[app][evolve][from]") {
    TempDir tmp("from-shape");
    const fs::path source = source_run(tmp);
    std::string wide = tiny_config(1);
    wide.replace(wide.find("\"hidden\": [4]"), 13, "\"hidden\": [5]");
    write_text(tmp.path / "wide.json", wide);
    for (const fs::path& from : {source / "best" / "gen_0002.genome.json", source}) {
        CAPTURE(from);
        const CliResult r = run_morphogen(evolve(tmp.path / "wide.json", tmp.path / "out", "--from " + q(from)));
        CHECK(r.code == 2);
        CHECK_THAT(r.output, Catch::Contains(from.string()) && Catch::Contains("[12, 4, 4]") &&
                                 Catch::Contains("[12, 5, 4]"));
        CHECK(!fs::exists(tmp.path / "out"));
    }
    const CliResult missing = run_morphogen(evolve(tmp.path / "wide.json", tmp.path / "out", "--from " + q(tmp.path / "nope")));
    CHECK(missing.code == 3);
    CHECK_THAT(missing.output, Catch::Contains("nope"));
}

TEST_CASE("a seeded evolve gives the same bytes for 1 and 2 threads and after a resume without the original",
          "[app][evolve][from][resume]") {
    TempDir tmp("from-resume");
    const fs::path source = source_run(tmp);
    const fs::path genome = tmp.path / "given.genome.json";
    fs::copy_file(source / "best" / "gen_0002.genome.json", genome);
    write_text(tmp.path / "c.json", tiny_pipeline_config(4));
    REQUIRE(run_morphogen(evolve(tmp.path / "c.json", tmp.path / "one", "--threads 1 --from " + q(genome))).code == 0);
    REQUIRE(run_morphogen(evolve(tmp.path / "c.json", tmp.path / "two", "--threads 2 --from " + q(genome))).code == 0);
    check_same_results(tmp.path / "one", tmp.path / "two");
    CHECK(read_text(tmp.path / "one" / "seeds" / "manifest.json") == read_text(tmp.path / "two" / "seeds" / "manifest.json"));

    // stopped after generation 1, the original deleted, a copy of the directory resumed
    REQUIRE(run_morphogen(evolve(tmp.path / "c.json", tmp.path / "split",
                                 "--threads 2 --generations 1 --from " + q(genome)))
                .code == 0);
    fs::remove(genome);
    fs::copy(tmp.path / "split", tmp.path / "moved", fs::copy_options::recursive);
    REQUIRE(run_morphogen("resume " + q(tmp.path / "moved") + " --generations 4 --threads 1").code == 0);
    check_same_results(tmp.path / "one", tmp.path / "moved");

    // resume reads the recorded copies: a changed one is refused
    write_text(tmp.path / "split" / "seeds" / "seed_000.genome.json",
               read_text(tmp.path / "one" / "seeds" / "seed_000.genome.json") + " ");
    const CliResult changed = run_morphogen("resume " + q(tmp.path / "split") + " --generations 4");
    CHECK(changed.code == 5);
    CHECK_THAT(changed.output, Catch::Contains("seed_000.genome.json") && Catch::Contains("changed"));
}
