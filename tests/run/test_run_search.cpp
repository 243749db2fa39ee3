// The registry of searches and their states (run/searches/run_search.hpp,
// run/searches/search_state.hpp), each search through the interface alone.
#include "evolution/genome_blob.hpp"
#include "run/config/experiment_config.hpp"
#include "run/growth_problem.hpp"
#include "run/searches/nslc_search.hpp"
#include "run/searches/run_search.hpp"
#include "tests/run/search_states.hpp"

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <set>
#include <string>

using namespace morphogen;
using namespace morphogen::test;

namespace {
ExperimentConfig config_for(Algorithm algorithm) {
    nlohmann::json text = {{"run", {{"generations", 2}}}, {"evolution", {{"population", 4}}}};
    if (algorithm == Algorithm::map_elites) {
        text["evolution"]["algorithm"] = "map_elites";
        text["descriptors"] = {{{"measure", "height"}, {"min", 0}, {"max", 1}, {"bins", 3}}};
    }
    if (algorithm == Algorithm::nslc) {
        text["evolution"]["algorithm"] = "nslc";
        text["descriptors"] = {{{"measure", "height"}, {"min", 0}, {"max", 1}}};
    }
    return read_experiment_config(text, "test");
}

Individual member(std::uint64_t id, double fitness, std::size_t dimension) {
    Individual ind;
    ind.id = id;
    ind.fitness = fitness;
    ind.size = 10;
    ind.params.assign(dimension, 0.25 * static_cast<double>(id + 1));
    return ind;
}
}  // namespace

TEST_CASE("every algorithm has one registry row, with its own content key", "[run][search]") {
    std::set<std::string> keys;
    for (const SearchKind& kind : search_kinds()) {
        CHECK(&search_kind(kind.algorithm) == &kind);
        CHECK(keys.insert(kind.key).second);
    }
    CHECK(search_kind(Algorithm::steady_state).key == std::string("ga"));
    CHECK_FALSE(search_kind(Algorithm::steady_state).qd_history);
    CHECK(search_kind(Algorithm::map_elites).key == std::string("map_elites"));
    CHECK(search_kind(Algorithm::map_elites).qd_history);
    CHECK(search_kind(Algorithm::nslc).key == std::string("nslc"));
    CHECK_FALSE(search_kind(Algorithm::nslc).qd_history);
}

TEST_CASE("a search's first state is stored under its key and read back by its row", "[run][search]") {
    for (const Algorithm algorithm : {Algorithm::steady_state, Algorithm::map_elites, Algorithm::nslc}) {
        const ExperimentConfig config = config_for(algorithm);
        const SearchKind& kind = search_kind(algorithm);
        const std::unique_ptr<SearchState> first = kind.initial(config, 1, nullptr);
        REQUIRE(first);
        CHECK(first->key() == std::string(kind.key));
        CHECK(first->births() == 0);
        CHECK_FALSE(first->best());
        CHECK(first->archive_text().empty() == !kind.qd_history);
        const nlohmann::json stored = first->to_json(nullptr);
        const std::unique_ptr<SearchState> read = kind.load(stored, config, 0, nullptr);
        CHECK(read->to_json(nullptr) == stored);
    }
}

TEST_CASE("a GA state's genomes go to the blob and come back, and a copy is its own", "[run][search]") {
    const ExperimentConfig config = config_for(Algorithm::steady_state);
    GaState ga;
    ga.births = 2;
    ga.population = {member(1, 2.0, 3), member(0, 1.0, 3)};
    ga.best = ga.population[0];
    RunState state;
    state.search = std::make_unique<GaSearchState>(ga);

    GenomeBlobWriter writer;
    const nlohmann::json stored = state.search->to_json(&writer);
    CHECK(writer.count() == 3);  // two members and the best
    GenomeBlobReader reader(writer.bytes(), writer.count(), writer.dimension());
    const std::unique_ptr<SearchState> read = search_kind(Algorithm::steady_state).load(stored, config, 3, &reader);
    CHECK(read->to_json(nullptr) == state.search->to_json(nullptr));

    // each_genome reaches every object that holds a genome
    nlohmann::json walked = stored;
    std::set<std::string> paths;
    search_kind(Algorithm::steady_state).each_genome(walked, [&](nlohmann::json&, const std::string& path) {
        paths.insert(path);
    });
    CHECK(paths == std::set<std::string>{"ga.population[0]", "ga.population[1]", "ga.best"});

    RunState copy = state;
    ga_of(copy).births = 7;
    CHECK(state.births() == 2);
    CHECK(copy.births() == 7);
}

TEST_CASE("an NSLC state's genomes go to the blob and come back with its descriptors and archive", "[run][search]") {
    const ExperimentConfig config = config_for(Algorithm::nslc);
    NslcState nslc;
    nslc.births = 3;
    nslc.population = {member(2, 2.0, 3), member(0, 1.0, 3)};
    nslc.population[0].descriptors = {0.5};
    nslc.population[1].descriptors = {0.25};
    nslc.best = nslc.population[0];
    nslc.archive = {Individual{0, {}, {}, {}, 1.0, 0.0, {0.25}}, Individual{1, {}, {}, {}, 3.0, 0.0, {0.75}}};
    RunState state;
    state.search = std::make_unique<NslcSearchState>(nslc);

    GenomeBlobWriter writer;
    const nlohmann::json stored = state.search->to_json(&writer);
    CHECK(writer.count() == 3);  // two members and the best; archive points keep no genome
    CHECK(stored["archive"][1] == nlohmann::json{{"id", 1}, {"fitness", 3.0}, {"descriptors", {0.75}}});
    GenomeBlobReader reader(writer.bytes(), writer.count(), writer.dimension());
    const std::unique_ptr<SearchState> read = search_kind(Algorithm::nslc).load(stored, config, 3, &reader);
    CHECK(read->to_json(nullptr) == state.search->to_json(nullptr));
    CHECK(nslc_state(*read)->population[1].descriptors == std::vector<double>{0.25});

    nlohmann::json walked = stored;
    std::set<std::string> paths;
    search_kind(Algorithm::nslc).each_genome(walked, [&](nlohmann::json&, const std::string& path) {
        paths.insert(path);
    });
    CHECK(paths == std::set<std::string>{"nslc.population[0]", "nslc.population[1]", "nslc.best"});
}

TEST_CASE("a state's history statistics are those of its members", "[run][search]") {
    const ExperimentConfig config = config_for(Algorithm::steady_state);
    GaState ga;
    ga.births = 2;
    ga.population = {member(1, 3.0, 1), member(0, 1.0, 1)};
    const GaSearchState state(ga);
    HistoryRow row;
    state.fill(row, config);
    CHECK(row.best == 3.0);
    CHECK(row.worst == 1.0);
    CHECK(row.mean == 2.0);
    CHECK_FALSE(row.qd);
    const SearchView view = state.view();
    CHECK(view.members.size() == 2);
    CHECK(view.members_name == "ga.population");
    CHECK(view.members_are_first_births);
}

TEST_CASE("a started search continues from the state and saves it again", "[run][search]") {
    const ExperimentConfig config = config_for(Algorithm::steady_state);
    GrowthProblem problem(config);
    GaSearchState state;
    const std::unique_ptr<RunSearch> search = state.start(config, problem);
    CHECK(search->births() == 0);
    CHECK(search->completed_generations() == 0);
    CHECK(search->exported() == nullptr);
    const std::unique_ptr<SearchState> saved = search->save();
    CHECK(saved->key() == std::string("ga"));
    CHECK(saved->births() == 0);
}
