#include "world.hpp"

#include <mpi.h>

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
// Between polls. 50 µs: negligible next to growing a genome (milliseconds),
// and a waiting process takes almost no CPU from the evaluating ones (MPI's
// own blocking calls spin).
void poll_pause() { std::this_thread::sleep_for(std::chrono::microseconds(50)); }
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

World::~World() { MPI_Finalize(); }

void World::send(int destination, int tag, const std::string& bytes, const std::function<void()>& idle) {
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) throw std::length_error("MPI message over 2 GiB");
    MPI_Request request;
    check(MPI_Isend(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, destination, tag, MPI_COMM_WORLD,
                    &request),
          "MPI_Isend");
    for (;;) {
        int done = 0;
        check(MPI_Test(&request, &done, MPI_STATUS_IGNORE), "MPI_Test");
        if (done) return;
        if (idle) idle();
        poll_pause();
    }
}

Message World::receive(int source, int tag, const std::function<void()>& idle) {
    const int from = source == any_source ? MPI_ANY_SOURCE : source;
    const int with = tag == any_tag ? MPI_ANY_TAG : tag;
    MPI_Status status;
    for (;;) {
        int ready = 0;
        check(MPI_Iprobe(from, with, MPI_COMM_WORLD, &ready, &status), "MPI_Iprobe");
        if (ready) break;
        if (idle) idle();
        poll_pause();
    }
    int count = 0;
    check(MPI_Get_count(&status, MPI_BYTE, &count), "MPI_Get_count");
    Message message{status.MPI_SOURCE, status.MPI_TAG, std::string(static_cast<std::size_t>(count), '\0')};
    check(MPI_Recv(message.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
                   MPI_STATUS_IGNORE),
          "MPI_Recv");
    return message;
}

void World::abort(int code) {
    MPI_Abort(MPI_COMM_WORLD, code);
    std::terminate();  // MPI_Abort does not return
}

}  // namespace morphogen::cluster
