#pragma once
// A GenomeEvaluator over a pool of threads of this process (std::thread):
// thread t scores with problem.evaluate(..., worker = t), taking genomes in
// the order they were submitted. The threads start in the constructor and
// are joined by the destructor (after the genome each is scoring).
#include "evolution/execution/genome_evaluator.hpp"
#include "evolution/problem.hpp"

#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

namespace morphogen {

class ThreadEvaluator final : public GenomeEvaluator {
public:
    // Calls problem.prepare(threads) and starts `threads` (>= 1) threads.
    // Throws std::runtime_error naming the count if the system refuses to
    // create them (after stopping those it made).
    ThreadEvaluator(Problem& problem, int threads);
    ~ThreadEvaluator() override;
    ThreadEvaluator(const ThreadEvaluator&) = delete;
    ThreadEvaluator& operator=(const ThreadEvaluator&) = delete;

    void submit(std::uint64_t birth, std::span<const double> params, double keep_from) override;
    std::optional<ScoredBirth> next(std::chrono::milliseconds timeout) override;
    void cancel() override;
    int capacity() const override { return static_cast<int>(threads_.size()); }
    std::string description() const override;

    // Results ready now, without waiting (for a caller that polls other things too).
    std::vector<ScoredBirth> take_ready();
    // Genomes submitted and not yet taken back.
    std::size_t outstanding() const;

private:
    struct Job {
        std::uint64_t birth;
        std::uint64_t epoch;  // cancel() bumps the epoch: older jobs' results are dropped
        std::vector<double> params;
        double keep_from;
    };
    void serve(int worker);

    const Problem& problem_;
    mutable std::mutex mutex_;
    std::condition_variable work_ready_, result_ready_, idle_;
    std::deque<Job> jobs_;
    std::deque<ScoredBirth> results_;
    std::uint64_t epoch_ = 0;
    std::size_t outstanding_ = 0;  // submitted in this epoch, not yet taken
    int busy_ = 0;                 // threads scoring a genome now
    bool stopping_ = false;
    std::vector<std::thread> threads_;
};

}  // namespace morphogen
