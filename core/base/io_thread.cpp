#include "core/base/io_thread.hpp"

namespace morphogen {

IoThread::IoThread(std::size_t max_queued) : max_queued_(max_queued == 0 ? 1 : max_queued) {
    thread_ = std::thread([this] { serve(); });
}

IoThread::~IoThread() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
    thread_.join();
}

void IoThread::rethrow_failure() {
    if (failure_ && !failure_reported_) {
        failure_reported_ = true;
        std::rethrow_exception(failure_);
    }
}

std::uint64_t IoThread::post(std::function<void()> task) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return failure_ || tasks_.size() < max_queued_; });
    rethrow_failure();
    if (failure_) return posted_;  // reported before: nothing runs after a failure
    tasks_.push_back(std::move(task));
    changed_.notify_all();
    return ++posted_;
}

void IoThread::wait_for(std::uint64_t ticket) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this, ticket] { return failure_ || done_ >= ticket; });
    rethrow_failure();
}

void IoThread::drain() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return failure_ || (tasks_.empty() && !running_task_); });
    rethrow_failure();
}

void IoThread::serve() {
    std::unique_lock lock(mutex_);
    for (;;) {
        changed_.wait(lock, [this] { return stopping_ || !tasks_.empty(); });
        if (tasks_.empty() || failure_) {
            if (stopping_) return;
            done_ += tasks_.size();
            tasks_.clear();
            continue;
        }
        std::function<void()> task = std::move(tasks_.front());
        tasks_.pop_front();
        running_task_ = true;
        lock.unlock();
        std::exception_ptr failed;
        try {
            task();
        } catch (...) {
            failed = std::current_exception();
        }
        lock.lock();
        running_task_ = false;
        ++done_;
        if (failed && !failure_) failure_ = failed;
        changed_.notify_all();
    }
}

}  // namespace morphogen
