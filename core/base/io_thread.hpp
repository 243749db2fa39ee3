#pragma once
// One background thread that runs file writes in the order they were posted
// (docs/algorithm.md §11.1): exports, fsyncs and checkpoints leave the run
// loop's thread, so evaluation goes on while they are written. Each task is
// itself atomic (atomic_file.hpp); running them in order keeps "a checkpoint
// never refers to an older archive.csv" and "checkpoint N+1 never lands
// before N". After a task fails, later ones are skipped and the failure is
// rethrown to the run loop at its next post() or drain().
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace morphogen {

class IoThread {
public:
    // At most `max_queued` tasks wait at once; post() blocks beyond that, so
    // a slow disk slows the run instead of filling the memory.
    explicit IoThread(std::size_t max_queued = 4);
    // Runs what is queued (unless a task failed), then joins.
    ~IoThread();
    IoThread(const IoThread&) = delete;
    IoThread& operator=(const IoThread&) = delete;

    // Queues `task` and returns its ticket: tickets count posts from 1.
    std::uint64_t post(std::function<void()> task);
    // Returns when every task up to `ticket` has run (0: at once).
    void wait_for(std::uint64_t ticket);
    // Returns when every posted task has run.
    void drain();

private:
    void serve();
    void rethrow_failure();  // with the lock held

    std::size_t max_queued_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<std::function<void()>> tasks_;
    std::uint64_t posted_ = 0;  // tickets handed out
    std::uint64_t done_ = 0;    // tickets run (or skipped after a failure)
    bool running_task_ = false;
    bool stopping_ = false;
    std::exception_ptr failure_;
    bool failure_reported_ = false;
    std::thread thread_;
};

}  // namespace morphogen
