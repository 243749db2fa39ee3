#include "cluster/remote_evaluator.hpp"

#include "cluster/protocol.hpp"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <stdexcept>

namespace morphogen::cluster {

namespace {
double clock_s(clockid_t clock) {
    timespec t{};
    clock_gettime(clock, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
double wall_s() { return clock_s(CLOCK_MONOTONIC); }
double cpu_s() { return clock_s(CLOCK_PROCESS_CPUTIME_ID); }  // all of rank 0's threads
}  // namespace

RemoteEvaluator::RemoteEvaluator(World& world, const ExperimentConfig& config, std::filesystem::path run_dir)
    : world_(world),
      run_dir_(std::move(run_dir)),
      threads_(static_cast<std::size_t>(world.size()), 0),
      outstanding_(static_cast<std::size_t>(world.size()), 0) {
    const std::string text = config.resolved.dump();
    for (int w = 1; w < world_.size(); ++w) world_.send(w, tag_config, text);
    std::string failures;
    const std::string cpu = cpu_kind();
    for (int answered = 1; answered < world_.size(); ++answered) {
        const Message m = world_.receive(World::any_source, World::any_tag);
        std::string failure;
        if (m.tag == tag_ready) {
            const Ready ready = decode_ready(m.bytes);
            threads_[static_cast<std::size_t>(m.source)] = ready.threads;
            if (ready.cpu != cpu)
                failure = "worker rank " + std::to_string(m.source) + " runs on a " + ready.cpu + " CPU, rank 0 on " +
                          cpu + ": they round the network differently, so the run would depend on which process " +
                          "scored which genome; use nodes of one CPU kind";
        } else if (m.tag == tag_failed) {
            failure = "worker rank " + std::to_string(m.source) + " cannot start: " + m.bytes;
        } else {
            throw ProtocolError("unexpected message tag " + std::to_string(m.tag) + " from rank " +
                                std::to_string(m.source));
        }
        if (failures.empty()) failures = failure;
    }
    if (!failures.empty()) throw std::runtime_error(failures);
    start_wall_ = wall_s();
    start_cpu_ = cpu_s();
}

RemoteEvaluator::~RemoteEvaluator() {
    try {
        cancel();
        return;
    } catch (const std::exception& e) {
        std::cerr << "morphogen: " << e.what() << '\n';
    }
    std::cerr << "morphogen: rank 0 failed with genomes on the workers; ending every process (the run can be "
                 "resumed from its last checkpoint: morphogen resume "
              << run_dir_.string() << ")\n";
    world_.abort(1);
}

int RemoteEvaluator::capacity() const {
    int total = 0;
    for (std::size_t w = 1; w < threads_.size(); ++w) total += threads_[w];
    return total;
}

std::string RemoteEvaluator::description() const {
    const int total = capacity();
    const std::size_t workers = threads_.size() - 1;
    return std::to_string(workers) + (workers == 1 ? " worker process (" : " worker processes (") +
           std::to_string(total) + (total == 1 ? " thread" : " threads") +
           ") over MPI; rank 0 keeps the search state and the files";
}

std::string RemoteEvaluator::summary() const {
    if (genomes_ == 0) return {};
    const double wall = wall_s() - start_wall_, cpu = cpu_s() - start_cpu_;
    const double per_birth_ms = 1e3 / static_cast<double>(genomes_);
    char text[256];
    std::snprintf(text, sizeof text,
                  "rank 0 over %llu births: %.3f ms CPU per birth of its own work, %.3f ms polling; waited for the "
                  "workers %.1f %% of %.1f s",
                  static_cast<unsigned long long>(genomes_), (cpu - wait_cpu_) * per_birth_ms,
                  wait_cpu_ * per_birth_ms, wall > 0 ? 100.0 * wait_wall_ / wall : 0.0, wall);
    return text;
}

void RemoteEvaluator::submit(std::uint64_t birth, std::span<const double> params, double keep_from) {
    queued_.push_back(Queued{birth, std::vector<double>(params.begin(), params.end()), keep_from});
    dispatch();
}

void RemoteEvaluator::dispatch() {
    for (int w = 1; w < world_.size() && !queued_.empty(); ++w) {
        const auto r = static_cast<std::size_t>(w);
        const int room = 2 * std::max(1, threads_[r]) - outstanding_[r];
        if (room <= 0) continue;
        std::vector<WorkItem> items;
        for (int k = 0; k < room && !queued_.empty(); ++k) {
            items.push_back(WorkItem{queued_.front().birth, std::move(queued_.front().params), queued_.front().keep_from});
            queued_.pop_front();
        }
        outstanding_[r] += static_cast<int>(items.size());
        world_.post(w, tag_work, encode_work(items));
    }
    world_.progress();
}

bool RemoteEvaluator::receive_results() {
    world_.progress();
    std::optional<Message> m = world_.try_receive(World::any_source, tag_result);
    if (!m) return false;
    const auto r = static_cast<std::size_t>(m->source);
    for (ResultItem& item : decode_results(m->bytes)) {
        if (outstanding_[r] <= 0)
            throw std::runtime_error("worker rank " + std::to_string(m->source) + " returned a genome it was not sent");
        --outstanding_[r];
        if (dropped_ > 0) {
            --dropped_;
            continue;
        }
        ready_.push_back(ScoredBirth{item.index, std::move(item.evaluation)});
        ++genomes_;
    }
    dispatch();
    return true;
}

std::optional<ScoredBirth> RemoteEvaluator::next(std::chrono::milliseconds timeout) {
    const double wall0 = wall_s(), cpu0 = cpu_s();
    const double deadline = wall0 + 1e-3 * static_cast<double>(timeout.count());
    // Up to 2 ms between polls: the workers hold queued genomes, so a result
    // noticed late delays no worker, and rank 0 can share a core with one.
    World::Backoff backoff(2000);
    while (ready_.empty()) {
        if (receive_results()) {
            backoff.reset();
            continue;
        }
        if (wall_s() >= deadline) break;
        backoff.pause();
    }
    wait_wall_ += wall_s() - wall0;
    wait_cpu_ += cpu_s() - cpu0;
    if (ready_.empty()) return std::nullopt;
    ScoredBirth out = std::move(ready_.front());
    ready_.pop_front();
    return out;
}

void RemoteEvaluator::cancel() {
    queued_.clear();
    ready_.clear();
    std::size_t due = 0;
    for (std::size_t r = 1; r < outstanding_.size(); ++r) due += static_cast<std::size_t>(outstanding_[r]);
    dropped_ = due;
    World::Backoff backoff;
    while (dropped_ > 0) {
        if (receive_results())
            backoff.reset();
        else
            backoff.pause();
    }
    world_.flush();
}

EvaluatorFactory remote_evaluators(World& world) {
    return [&world](const RunSession& session, GrowthProblem&) {
        return SessionEvaluator{std::make_unique<RemoteEvaluator>(world, session.config, session.paths.dir), true};
    };
}

}  // namespace morphogen::cluster
