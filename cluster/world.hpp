#pragma once
// The MPI job this process belongs to: a small RAII wrapper over Open MPI's C
// API, the only place that includes mpi.h (world_mpi.cpp; world_none.cpp in a
// build without MPI, where a World is never made). The constructor
// initialises MPI, the destructor finalises it; messages are byte strings
// with a tag (protocol.hpp). Only the main thread calls MPI (FUNNELED).
#include <functional>
#include <list>
#include <optional>
#include <string>

namespace morphogen::cluster {

struct Message {
    int source = -1;
    int tag = -1;
    std::string bytes;
};

class World {
public:
    // MPI_Init_thread; throws std::runtime_error if MPI cannot start (or the
    // build has none).
    World(int& argc, char**& argv);
    ~World();  // MPI_Finalize
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }

    // Returns once `bytes` have left (MPI_Isend, then polls with short sleeps,
    // calling `idle` between polls: a send to a process that died never
    // completes, and the caller must still see a stop signal meanwhile).
    void send(int destination, int tag, const std::string& bytes, const std::function<void()>& idle = {});
    // The next message from `source` (any_source: anyone) with `tag` (any_tag:
    // any). Polls with short sleeps instead of MPI's busy wait, so a waiting
    // process leaves its core to the threads that compute; `idle` (if set) is
    // called between polls.
    Message receive(int source, int tag, const std::function<void()>& idle = {});
    // The next message from `source` with `tag` if one has arrived, without waiting.
    std::optional<Message> try_receive(int source, int tag);
    // Starts sending `bytes` and returns at once (MPI_Isend); the bytes are
    // kept until the send completes. Sends in flight are finished by
    // progress() (without waiting) and flush() (waiting, calling `idle`).
    void post(int destination, int tag, std::string bytes);
    void progress();
    void flush(const std::function<void()>& idle = {});
    // Sleeps a little, longer each time nothing happened (20 µs doubling to
    // `max_us`; reset() after something did): how every waiting loop here
    // waits, so a waiting process leaves its core to the threads that compute.
    class Backoff {
    public:
        explicit Backoff(int max_us = 250) : max_us_(max_us) {}
        void pause();
        void reset() { us_ = 20; }

    private:
        int us_ = 20;
        int max_us_;
    };

    // Ends every process of the job with `code` (MPI_Abort); for the rare
    // failure that leaves messages in flight, where waiting could hang.
    [[noreturn]] void abort(int code);

    static constexpr int any_source = -1;
    static constexpr int any_tag = -1;

private:
    struct Posted;  // an MPI request and the bytes it sends
    int rank_ = 0;
    int size_ = 1;
    std::list<Posted> posted_;
};

}  // namespace morphogen::cluster
