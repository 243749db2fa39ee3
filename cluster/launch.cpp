#include "cluster/launch.hpp"

#include <charconv>
#include <cstdlib>
#include <cstring>

namespace morphogen::cluster {

namespace {
// A non-negative int from the environment; none if unset or malformed.
std::optional<int> env_int(const char* name) {
    const char* text = std::getenv(name);
    if (text == nullptr) return std::nullopt;
    int value = 0;
    const char* end = text + std::strlen(text);
    const auto [ptr, ec] = std::from_chars(text, end, value);
    if (ec != std::errc() || ptr != end || ptr == text || value < 0) return std::nullopt;
    return value;
}
}  // namespace

std::optional<Launch> detect_launch() {
    struct Pair {
        const char* size;
        const char* rank;
    };
    static constexpr Pair pairs[] = {{"OMPI_COMM_WORLD_SIZE", "OMPI_COMM_WORLD_RANK"},
                                     {"PMI_SIZE", "PMI_RANK"},
                                     {"PMIX_SIZE", "PMIX_RANK"},
                                     {"SLURM_STEP_NUM_TASKS", "SLURM_PROCID"}};
    for (const Pair& pair : pairs) {
        const std::optional<int> size = env_int(pair.size);
        if (!size || *size < 1) continue;
        return Launch{std::string(pair.size) + "=" + std::to_string(*size), *size, env_int(pair.rank).value_or(0)};
    }
    return std::nullopt;
}

bool built_with_mpi() { return MORPHOGEN_HAVE_MPI != 0; }

}  // namespace morphogen::cluster
