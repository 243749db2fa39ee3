#include "cluster/remote_evaluator.hpp"

#include "cluster/protocol.hpp"
#include "run/stop_signals.hpp"

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
    : world_(world), run_dir_(std::move(run_dir)), threads_(static_cast<std::size_t>(world.size()), 0) {
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
    if (!in_flight_) return;
    std::cerr << "morphogen: rank 0 failed during a batch; ending every process (the run can be resumed from its "
                 "last checkpoint: morphogen resume "
              << run_dir_.string() << ")\n";
    world_.abort(1);
}

std::string RemoteEvaluator::description() const {
    int total = 0;
    for (std::size_t w = 1; w < threads_.size(); ++w) total += threads_[w];
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

std::vector<Evaluation> RemoteEvaluator::evaluate(const std::vector<std::vector<double>>& genomes) {
    const std::size_t n = genomes.size();
    const auto workers = static_cast<std::size_t>(world_.size() - 1);
    std::vector<Evaluation> out(n);
    std::vector<bool> done(n, false);
    const double wall0 = wall_s(), cpu0 = cpu_s();
    std::size_t next = 0, received = 0;
    in_flight_ = true;

    // A stop signal waits for the batch; if it came because a process died
    // (mpirun then signals everyone), this is the last word from rank 0.
    auto note_stop = [&] {
        if (stop_noted_ || !StopSignals::requested()) return;
        stop_noted_ = true;
        std::cerr << "morphogen: signal " << StopSignals::signal_number()
                  << ": finishing the current batch on the workers, then checkpointing; if a process died, the job "
                     "ends now and the run can be resumed from its last checkpoint: morphogen resume "
                  << run_dir_.string() << "\n";
    };
    // A chunk is the worker's thread count, but no more than an even share of
    // the batch, so small batches still reach every worker.
    const std::size_t share = std::max<std::size_t>(1, n / workers);
    auto hand_out = [&](int w) {
        const std::size_t k = std::min({static_cast<std::size_t>(std::max(1, threads_[static_cast<std::size_t>(w)])),
                                        share, n - next});
        std::vector<WorkItem> items(k);
        for (std::size_t j = 0; j < k; ++j) items[j] = WorkItem{next + j, genomes[next + j]};
        next += k;
        world_.send(w, tag_work, encode_work(items), note_stop);
    };
    for (int w = 1; w < world_.size() && next < n; ++w) hand_out(w);

    while (received < n) {
        const Message m = world_.receive(World::any_source, tag_result, note_stop);
        for (ResultItem& item : decode_results(m.bytes)) {
            if (item.index >= n || done[item.index])
                throw std::runtime_error("worker rank " + std::to_string(m.source) + " returned an unknown genome");
            done[item.index] = true;
            out[item.index] = std::move(item.evaluation);
            ++received;
        }
        if (next < n) hand_out(m.source);
    }
    in_flight_ = false;
    wait_wall_ += wall_s() - wall0;
    wait_cpu_ += cpu_s() - cpu0;
    genomes_ += n;
    return out;
}

}  // namespace morphogen::cluster
