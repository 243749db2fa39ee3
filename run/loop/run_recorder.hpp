#pragma once
// What a session writes as its births are inserted (docs/algorithm.md §11):
// at each generation's end that generation's lineage.csv rows and its
// history.csv row, the exported individual's files to best/ (every
// run.export_every and at the end), archive.csv and checkpoint.json (every
// run.checkpoint_every and at the end). The slow writes (exports, fsyncs,
// checkpoints) go to an IoThread, in order; a generation's end first waits
// for the last checkpoint posted, so what a kill -9 finds on disk is at most
// one finished generation past the last due checkpoint (§11.1).
#include "evolution/individual.hpp"
#include "evolution/execution/pipeline.hpp"
#include "run/growth_problem.hpp"
#include "core/base/io_thread.hpp"
#include "run/loop/progress.hpp"
#include "run/searches/run_search.hpp"
#include "run/loop/session_files.hpp"

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

namespace morphogen {

class RunRecorder {
public:
    // Everything passed in outlives the recorder. `pipeline` gives the births
    // a checkpoint keeps; `progress` shows the births and generations.
    RunRecorder(RunSession& session, GrowthProblem& problem, const RunSearch& search, const BirthPipeline& pipeline,
                Progress& progress);
    // Finishes the writes already posted (unless one failed).
    ~RunRecorder() = default;
    RunRecorder(const RunRecorder&) = delete;
    RunRecorder& operator=(const RunRecorder&) = delete;

    // After each insertion (BirthPipeline::OnInsert).
    void inserted(const Individual& child, const std::string& error, const Inserted& what, const std::string& kept);
    // Posts a checkpoint of the state now (the lineage rows not yet written
    // first); the I/O thread writes archive.csv and then the checkpoint.
    void checkpoint();
    // Returns when every posted write is done; throws the first that failed.
    void drain() { io_.drain(); }

private:
    using Clock = std::chrono::steady_clock;
    void end_generation(const Inserted& what);
    HistoryRow history_row(std::uint64_t generation, const Inserted& what) const;
    void export_best(std::uint64_t generation);
    void write_rows();
    void check_log() const;
    double elapsed_s() const;

    RunSession& session_;
    GrowthProblem& problem_;
    const RunSearch& search_;
    const BirthPipeline& pipeline_;
    Progress& progress_;
    std::uint64_t population_;
    std::uint64_t target_births_;
    std::size_t descriptor_columns_;  // of lineage.csv's rows
    Clock::time_point session_start_ = Clock::now();
    double elapsed_before_;  // run time of the sessions before this one
    Clock::time_point generation_start_ = session_start_;
    std::uint64_t generation_first_birth_;
    std::string rows_;  // lineage.csv rows not yet written
    // The exported individual's files as its evaluation kept them (none after
    // a resume, until it changes).
    std::optional<std::uint64_t> kept_id_;
    std::string kept_files_;
    std::uint64_t checkpoint_ticket_ = 0;  // the last checkpoint posted
    // Declared last, so it finishes its writes before anything it uses goes.
    IoThread io_;
};

}  // namespace morphogen
