#include "evolution/execution/thread_evaluator.hpp"

#include "evolution/execution/safe_evaluation.hpp"

#include <stdexcept>
#include <system_error>

namespace morphogen {

ThreadEvaluator::ThreadEvaluator(Problem& problem, int threads) : problem_(problem) {
    if (threads < 1) throw std::invalid_argument("ThreadEvaluator needs at least one thread");
    problem.prepare(threads);
    threads_.reserve(static_cast<std::size_t>(threads));
    try {
        for (int t = 0; t < threads; ++t) threads_.emplace_back([this, t] { serve(t); });
    } catch (const std::system_error& e) {
        const std::size_t made = threads_.size();
        {
            const std::lock_guard lock(mutex_);
            stopping_ = true;
        }
        work_ready_.notify_all();
        for (std::thread& thread : threads_) thread.join();
        throw std::runtime_error("could not start " + std::to_string(threads) + " worker threads (the system made " +
                                 std::to_string(made) + ": " + e.what() + "); lower run.threads or pass --threads");
    }
}

ThreadEvaluator::~ThreadEvaluator() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
        jobs_.clear();
    }
    work_ready_.notify_all();
    for (std::thread& thread : threads_) thread.join();
}

std::string ThreadEvaluator::description() const {
    return std::to_string(threads_.size()) + (threads_.size() == 1 ? " thread" : " threads");
}

void ThreadEvaluator::submit(std::uint64_t birth, std::span<const double> params, double keep_from) {
    {
        const std::lock_guard lock(mutex_);
        jobs_.push_back(Job{birth, epoch_, std::vector<double>(params.begin(), params.end()), keep_from});
        ++outstanding_;
    }
    work_ready_.notify_one();
}

std::optional<ScoredBirth> ThreadEvaluator::next(std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex_);
    if (!result_ready_.wait_for(lock, timeout, [this] { return !results_.empty(); })) return std::nullopt;
    ScoredBirth out = std::move(results_.front());
    results_.pop_front();
    --outstanding_;
    return out;
}

std::vector<ScoredBirth> ThreadEvaluator::take_ready() {
    const std::lock_guard lock(mutex_);
    std::vector<ScoredBirth> out(std::make_move_iterator(results_.begin()), std::make_move_iterator(results_.end()));
    results_.clear();
    outstanding_ -= out.size();
    return out;
}

std::size_t ThreadEvaluator::outstanding() const {
    const std::lock_guard lock(mutex_);
    return outstanding_;
}

void ThreadEvaluator::cancel() {
    std::unique_lock lock(mutex_);
    ++epoch_;
    jobs_.clear();
    results_.clear();
    outstanding_ = 0;
    idle_.wait(lock, [this] { return busy_ == 0; });
}

void ThreadEvaluator::serve(int worker) {
    std::unique_lock lock(mutex_);
    for (;;) {
        work_ready_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
        if (stopping_) return;
        Job job = std::move(jobs_.front());
        jobs_.pop_front();
        ++busy_;
        lock.unlock();
        Evaluation evaluation = evaluate_safely(problem_, job.params, worker, job.keep_from);
        lock.lock();
        --busy_;
        if (job.epoch == epoch_) results_.push_back(ScoredBirth{job.birth, std::move(evaluation)});
        if (busy_ == 0) idle_.notify_all();
        result_ready_.notify_one();
    }
}

}  // namespace morphogen
