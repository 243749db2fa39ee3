// The recorder alone (run/loop/run_recorder.hpp): a session's pipeline driven by
// hand to a generation that is neither the last nor due for a checkpoint.
#include "evolution/execution/thread_evaluator.hpp"
#include "run/persistence/checkpoint.hpp"
#include "run/searches/ga_search.hpp"
#include "run/loop/progress.hpp"
#include "run/loop/run_recorder.hpp"
#include "tests/run/tiny_configs.hpp"
#include "tests/support/temp_dir.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

using namespace morphogen;
using namespace morphogen::test;
using morphogen::testing::read_text;
using morphogen::testing::TempDir;

namespace {
std::size_t lines(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }
}  // namespace

TEST_CASE("the recorder writes each generation's rows and checkpoints on its cadence", "[run][recorder]") {
    TempDir tmp("recorder");
    ExperimentConfig config = read_experiment_config(nlohmann::json::parse(tiny_config(5, 4, 2)), "test");
    config.run.checkpoint_every = 2;
    const RunPaths paths = run_paths(tmp.path / "run");
    create_run_dir(paths, false);
    RunState first;
    first.search = std::make_unique<GaSearchState>();
    RunSession session{paths,
                       config,
                       std::move(first),
                       AppendFile::create(paths.history, history_header),
                       AppendFile::create(paths.lineage, lineage_header),
                       make_run_loggers(paths),
                       std::nullopt};
    GrowthProblem problem(config);
    const std::unique_ptr<RunSearch> search = session.state.search->start(config, problem);
    ThreadEvaluator evaluator(problem, 1);
    Progress progress(session.log.both, session.log.file_only, 24, 5);
    BirthPipeline pipeline(birth_schedule(config.evolution), search->breeder(), evaluator);
    {
        RunRecorder recorder(session, problem, *search, pipeline, progress);
        // Generations 0, 1 and 2 of 5: checkpoints are due after 0 and 2.
        const auto on_insert = [&](const Individual& child, const std::string& error, const Inserted& what,
                                   const std::string& kept) { recorder.inserted(child, error, what, kept); };
        REQUIRE(pipeline.run(8, on_insert, [] { return false; }));
        recorder.drain();
        CHECK(lines(read_text(paths.history)) == 1 + 2);
        CHECK(lines(read_text(paths.lineage)) == 1 + 8);
        // Generation 1 was not due: the checkpoint is generation 0's.
        CHECK(load_checkpoint(paths.checkpoint).births() == 4);

        REQUIRE(pipeline.run(12, on_insert, [] { return false; }));
        recorder.drain();
        const RunState saved = load_checkpoint(paths.checkpoint);
        CHECK(saved.births() == 12);
        CHECK(saved.history.size() == 3);
        CHECK(saved.lineage_bytes == read_text(paths.lineage).size());

        // A stop's checkpoint takes the state as it is.
        REQUIRE(pipeline.run(13, on_insert, [] { return false; }));
        recorder.checkpoint();
        recorder.drain();
        CHECK(lines(read_text(paths.lineage)) == 1 + 13);
    }
    CHECK(session.state.births() == 13);
}
