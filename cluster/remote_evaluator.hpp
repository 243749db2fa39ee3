#pragma once
// Rank 0's side of a session (GenomeEvaluator, evolution/execution/genome_evaluator.hpp):
// the workers (ranks 1..N-1) grow and score genomes while rank 0 keeps the
// search state and writes every file. Rank 0 does not evaluate itself: it
// must answer a worker that finishes at once (a genome can cost ten times
// another), and its own work per birth is small (docs/performance.md).
//
// Streaming: every worker keeps up to 2x its threads genomes queued, so its
// threads never wait for rank 0; it returns each result as soon as it is
// done, and rank 0 sends it the next genome at once. Genomes beyond what the
// workers hold wait on rank 0 in submission order. Which process scores which
// genome never changes a result.
#include "cluster/world.hpp"
#include "evolution/execution/genome_evaluator.hpp"
#include "run/loop/run_session.hpp"
#include "run/config/experiment_config.hpp"

#include <deque>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace morphogen::cluster {

class RemoteEvaluator : public GenomeEvaluator {
public:
    // Sends the resolved config to every worker and waits until each has
    // built its problem; throws std::runtime_error naming a worker that cannot,
    // or one whose CPU kind (cpu_kind) differs from rank 0's.
    RemoteEvaluator(World& world, const ExperimentConfig& config, std::filesystem::path run_dir);
    // Genomes left with the workers (an exception on rank 0 that cancel()
    // could not clean up) would leave the job hanging, so it is aborted.
    ~RemoteEvaluator() override;

    void submit(std::uint64_t birth, std::span<const double> params, double keep_from) override;
    std::optional<ScoredBirth> next(std::chrono::milliseconds timeout) override;
    // Waits for the workers' results still due and drops them.
    void cancel() override;
    int capacity() const override;
    std::string description() const override;
    // Rank 0's own cost per birth: CPU time outside waiting (conceiving,
    // inserting, writing rows and checkpoints), CPU time polling while
    // waiting, and the share of the wall time it waited for workers.
    std::string summary() const override;

private:
    struct Queued {
        std::uint64_t birth;
        std::vector<double> params;
        double keep_from;
    };
    // Sends queued genomes to every worker with room (up to 2x its threads).
    void dispatch();
    // Takes one result message if there is one; returns whether there was.
    bool receive_results();

    World& world_;
    std::filesystem::path run_dir_;
    std::vector<int> threads_;      // per rank; threads_[0] unused
    std::vector<int> outstanding_;  // per rank: genomes sent, results not yet back
    std::deque<Queued> queued_;     // submitted, not yet sent
    std::deque<ScoredBirth> ready_; // back from the workers, not yet taken
    std::size_t dropped_ = 0;       // results still due for genomes cancel() forgot
    double start_wall_ = 0, start_cpu_ = 0;  // when the session started
    double wait_wall_ = 0, wait_cpu_ = 0;    // inside next()
    std::uint64_t genomes_ = 0;
};

// The evaluators of rank 0's sessions: a RemoteEvaluator over `world` (which
// outlives every session) for each.
EvaluatorFactory remote_evaluators(World& world);

}  // namespace morphogen::cluster
