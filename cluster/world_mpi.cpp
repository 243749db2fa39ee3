#include "cluster/world.hpp"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <stdexcept>
#include <thread>

namespace morphogen::cluster {

namespace {
void check(int status, const char* what) {
    if (status == MPI_SUCCESS) return;
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(status, text, &length);
    throw std::runtime_error(std::string("MPI: ") + what + " failed: " + std::string(text, static_cast<std::size_t>(length)));
}
}  // namespace

World::World(int& argc, char**& argv) {
    int provided = 0;
    check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
    // Errors come back as codes (check() turns them into exceptions) instead
    // of MPI's default abort without context.
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

struct World::Posted {
    MPI_Request request = MPI_REQUEST_NULL;
    std::string bytes;
};

// A waiting process wakes at most 4,000 times a second (about 1 % of a core)
// instead of spinning like MPI's blocking calls, and a message waits at most
// 250 µs, little next to growing a genome (milliseconds).
void World::Backoff::pause() {
    std::this_thread::sleep_for(std::chrono::microseconds(us_));
    us_ = std::min(us_ * 2, max_us_);
}

World::~World() {
    for (Posted& p : posted_) MPI_Request_free(&p.request);
    MPI_Finalize();
}

void World::post(int destination, int tag, std::string bytes) {
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) throw std::length_error("MPI message over 2 GiB");
    Posted& p = posted_.emplace_back();
    p.bytes = std::move(bytes);
    check(MPI_Isend(p.bytes.data(), static_cast<int>(p.bytes.size()), MPI_BYTE, destination, tag, MPI_COMM_WORLD,
                    &p.request),
          "MPI_Isend");
}

void World::progress() {
    for (auto it = posted_.begin(); it != posted_.end();) {
        int done = 0;
        check(MPI_Test(&it->request, &done, MPI_STATUS_IGNORE), "MPI_Test");
        it = done ? posted_.erase(it) : std::next(it);
    }
}

void World::flush(const std::function<void()>& idle) {
    Backoff backoff;
    for (progress(); !posted_.empty(); progress()) {
        if (idle) idle();
        backoff.pause();
    }
}

std::optional<Message> World::try_receive(int source, int tag) {
    const int from = source == any_source ? MPI_ANY_SOURCE : source;
    const int with = tag == any_tag ? MPI_ANY_TAG : tag;
    MPI_Status status;
    int ready = 0;
    check(MPI_Iprobe(from, with, MPI_COMM_WORLD, &ready, &status), "MPI_Iprobe");
    if (!ready) return std::nullopt;
    int count = 0;
    check(MPI_Get_count(&status, MPI_BYTE, &count), "MPI_Get_count");
    Message message{status.MPI_SOURCE, status.MPI_TAG, std::string(static_cast<std::size_t>(count), '\0')};
    check(MPI_Recv(message.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
                   MPI_STATUS_IGNORE),
          "MPI_Recv");
    return message;
}

void World::send(int destination, int tag, const std::string& bytes, const std::function<void()>& idle) {
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) throw std::length_error("MPI message over 2 GiB");
    MPI_Request request;
    check(MPI_Isend(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, destination, tag, MPI_COMM_WORLD,
                    &request),
          "MPI_Isend");
    Backoff backoff;
    for (;;) {
        int done = 0;
        check(MPI_Test(&request, &done, MPI_STATUS_IGNORE), "MPI_Test");
        if (done) return;
        if (idle) idle();
        backoff.pause();
    }
}

Message World::receive(int source, int tag, const std::function<void()>& idle) {
    Backoff backoff;
    for (;;) {
        progress();
        if (std::optional<Message> message = try_receive(source, tag)) return std::move(*message);
        if (idle) idle();
        backoff.pause();
    }
}

void World::abort(int code) {
    MPI_Abort(MPI_COMM_WORLD, code);
    std::terminate();  // MPI_Abort does not return
}

}  // namespace morphogen::cluster
