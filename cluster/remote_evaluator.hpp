#pragma once
// Rank 0's side of a session (BatchEvaluator, evolution/batch.hpp): the
// workers (ranks 1..N-1) grow and score the genomes of each batch while rank 0
// keeps the search state and writes every file. Rank 0 does not evaluate
// itself: it must answer a worker that finishes at once (a genome can cost
// ten times another), and its own work per birth is small (docs/performance.md).
//
// Hand-out is dynamic: every worker gets a chunk of genomes (its thread
// count, at most batch/workers), and whoever sends results back gets the next
// chunk. Which process scores which genome never changes a result.
#include "cluster/world.hpp"
#include "evolution/batch.hpp"
#include "run/experiment_config.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace morphogen::cluster {

class RemoteEvaluator : public BatchEvaluator {
public:
    // Sends the resolved config to every worker and waits until each has
    // built its problem; throws std::runtime_error naming a worker that cannot,
    // or one whose CPU kind (cpu_kind) differs from rank 0's.
    RemoteEvaluator(World& world, const ExperimentConfig& config, std::filesystem::path run_dir);
    // A batch abandoned half way (an exception on rank 0) leaves messages in
    // flight, so the job is aborted rather than left to hang.
    ~RemoteEvaluator() override;

    std::vector<Evaluation> evaluate(const std::vector<std::vector<double>>& genomes) override;
    std::string description() const override;
    // Rank 0's own cost per birth: CPU time outside evaluate() (conceiving,
    // inserting, writing rows and checkpoints), CPU time polling inside it,
    // and the share of the wall time it waited for workers.
    std::string summary() const override;

private:
    World& world_;
    std::filesystem::path run_dir_;
    std::vector<int> threads_;  // per rank; threads_[0] unused
    bool in_flight_ = false;
    double start_wall_ = 0, start_cpu_ = 0;  // when the session started
    double wait_wall_ = 0, wait_cpu_ = 0;    // inside evaluate()
    std::uint64_t genomes_ = 0;
    bool stop_noted_ = false;
};

}  // namespace morphogen::cluster
