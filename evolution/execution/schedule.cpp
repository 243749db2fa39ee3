#include "evolution/execution/schedule.hpp"

#include <algorithm>

namespace morphogen {

namespace {
// First birth of the batch holding `birth` (batches restart at every generation).
std::uint64_t batch_start(std::uint64_t birth, std::uint64_t P, std::uint64_t B) {
    const std::uint64_t generation_start = birth - birth % P;
    return generation_start + (birth - generation_start) / B * B;
}
}  // namespace

std::uint64_t BirthSchedule::source(std::uint64_t birth) const {
    if (kind == ScheduleKind::batch) return batch_start(birth, population, width);
    if (birth < population) return 0;
    return std::max(birth + 1 - std::min(birth + 1, width), population);
}

std::uint64_t BirthSchedule::conceivable_end(std::uint64_t births) const {
    if (kind == ScheduleKind::batch) {
        const std::uint64_t start = batch_start(births, population, width);
        const std::uint64_t generation_end = births - births % population + population;
        return std::min(start + width, generation_end);
    }
    if (births < population) return population;
    return births + width;
}

std::uint64_t BirthSchedule::kept_begin(std::uint64_t births) const { return std::max(births, population); }

std::uint64_t BirthSchedule::kept_end(std::uint64_t births) const {
    // source() is non-decreasing, so the births with a source below `births`
    // are a prefix of [births, conceivable_end(births)).
    std::uint64_t end = births;
    const std::uint64_t last = conceivable_end(births);
    while (end < last && source(end) < births) ++end;
    return std::max(end, kept_begin(births));
}

std::string BirthSchedule::describe() const {
    return kind == ScheduleKind::batch ? "batch " + std::to_string(width) : "pipeline, lag " + std::to_string(width);
}

}  // namespace morphogen
