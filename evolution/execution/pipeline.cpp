#include "evolution/execution/pipeline.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace morphogen {

void take_evaluation(Individual& child, std::string& error, Evaluation&& e) {
    child.fitness = e.valid ? e.score : invalid_fitness;
    child.size = e.size;
    child.descriptors = std::move(e.descriptors);
    error = e.valid ? std::string() : std::move(e.error);
}

Inserted count_birth(std::uint64_t& births, std::uint64_t& invalid_in_generation, std::uint64_t population) {
    Inserted what;
    if (++births % population == 0) {
        what.ends_generation = true;
        what.generation_invalid = invalid_in_generation;
        invalid_in_generation = 0;
    }
    return what;
}

BirthPipeline::BirthPipeline(const BirthSchedule& schedule, Breeder& breeder, GenomeEvaluator& evaluator,
                             std::vector<Individual> kept)
    : schedule_(schedule), breeder_(breeder), evaluator_(evaluator) {
    const std::uint64_t births = breeder_.births();
    for (std::size_t k = 0; k < kept.size(); ++k) {
        if (kept[k].id != births + k)
            throw std::invalid_argument("kept birth " + std::to_string(kept[k].id) + " where birth " +
                                        std::to_string(births + k) + " was expected");
        slots_.push_back(Slot{std::move(kept[k]), std::nullopt});
    }
}

BirthPipeline::~BirthPipeline() {
    try {
        evaluator_.cancel();
    } catch (...) {
        // The evaluator's own destructor deals with what is left (cluster/: it ends the job).
    }
}

void BirthPipeline::conceive_due(std::uint64_t target) {
    const std::uint64_t births = breeder_.births();
    const std::uint64_t end = schedule_.conceivable_end(births);
    for (std::uint64_t birth = births + slots_.size(); birth < end; ++birth)
        slots_.push_back(Slot{breeder_.conceive(birth), std::nullopt});
    submit_below(target);
}

void BirthPipeline::submit_below(std::uint64_t target) {
    const std::uint64_t births = breeder_.births();
    for (; submitted_ < slots_.size() && births + submitted_ < target; ++submitted_) {
        Slot& slot = slots_[submitted_];
        slot.may_keep = keeping_ < kMaxKeepingBirths;
        keeping_ += slot.may_keep ? 1 : 0;
        evaluator_.submit(births + submitted_, slot.child.params,
                          slot.may_keep ? breeder_.export_floor() : std::numeric_limits<double>::infinity());
    }
}

bool BirthPipeline::run(std::uint64_t target, const OnInsert& on_insert, const std::function<bool()>& stop) {
    using namespace std::chrono_literals;
    while (breeder_.births() < target) {
        if (stop()) return false;
        conceive_due(target);
        if (!slots_.front().evaluation) {
            std::optional<ScoredBirth> scored = evaluator_.next(100ms);
            if (!scored) continue;
            const std::uint64_t births = breeder_.births();
            const std::uint64_t k = scored->birth - births;
            if (scored->birth < births || k >= submitted_ || slots_[k].evaluation)
                throw std::logic_error("the evaluator returned birth " + std::to_string(scored->birth) +
                                       ", which is not in flight");
            slots_[k].evaluation = std::move(scored->evaluation);
            continue;
        }
        Slot slot = std::move(slots_.front());
        slots_.pop_front();
        --submitted_;
        keeping_ -= slot.may_keep ? 1 : 0;
        std::string error;
        const std::string kept = std::move(slot.evaluation->kept);
        take_evaluation(slot.child, error, std::move(*slot.evaluation));
        const Inserted what = breeder_.insert(slot.child, error);
        on_insert(slot.child, error, what, kept);
    }
    return true;
}

std::vector<Individual> BirthPipeline::kept() const {
    const std::uint64_t births = breeder_.births();
    const std::uint64_t begin = schedule_.kept_begin(births), end = schedule_.kept_end(births);
    std::vector<Individual> out;
    for (std::uint64_t birth = begin; birth < end; ++birth) {
        const std::uint64_t k = birth - births;
        if (k >= slots_.size()) throw std::logic_error("a birth to keep was never conceived");
        Individual child = slots_[k].child;
        child.fitness = invalid_fitness;
        child.size = 0.0;
        child.descriptors.clear();
        out.push_back(std::move(child));
    }
    return out;
}

}  // namespace morphogen
