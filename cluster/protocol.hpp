#pragma once
// The messages between rank 0 and the workers, as bytes (no MPI here, so the
// encoding is tested on its own). Doubles travel as their 8 bytes: a score,
// size or descriptor arrives with every bit it left with (NaN payloads and
// signed zeros included), so a run's files are the same for any number of
// processes. All processes of a job run the same executable on the same
// architecture, so native byte order is used.
#include "evolution/individual.hpp"

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace morphogen::cluster {

// MPI tags, one per message kind.
enum Tag : int {
    tag_config = 1,  // 0 -> worker: the resolved config (JSON text); a session starts
    tag_ready = 2,   // worker -> 0: its thread count and CPU kind (encode_ready)
    tag_work = 3,    // 0 -> worker: genomes to score (encode_work)
    tag_result = 4,  // worker -> 0: their evaluations (encode_results)
    tag_quit = 5,    // 0 -> worker: exit with this code (encode_int)
    tag_failed = 6,  // worker -> 0: why it cannot build the problem (text)
};

// A malformed message (a bug or a mismatched executable, never user input).
struct ProtocolError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct WorkItem {
    std::uint64_t index = 0;  // its birth
    std::vector<double> params;
    // Keep what exporting it needs if it scores at least this (+infinity: never).
    double keep_from = std::numeric_limits<double>::infinity();
};

struct ResultItem {
    std::uint64_t index = 0;
    Evaluation evaluation;
};

struct Ready {
    int threads = 1;
    std::string cpu;  // cpu_kind() of the worker
};

// Which of the kernels' builds (growth/: x86-64-v3 with FMA, or baseline) this
// CPU runs; processes that differ would round the network differently, so a
// run's bytes would depend on where a genome was scored.
std::string cpu_kind();

std::string encode_ready(const Ready& ready);
Ready decode_ready(const std::string& bytes);

std::string encode_int(int value);
int decode_int(const std::string& bytes);

std::string encode_work(const std::vector<WorkItem>& items);
std::vector<WorkItem> decode_work(const std::string& bytes);

std::string encode_results(const std::vector<ResultItem>& items);
std::vector<ResultItem> decode_results(const std::string& bytes);

}  // namespace morphogen::cluster
