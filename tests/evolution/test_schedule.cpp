// The birth schedules (docs/algorithm.md §8.4) against cases worked by hand.
#include "evolution/execution/schedule.hpp"

#include <catch2/catch.hpp>

using namespace morphogen;

TEST_CASE("the pipeline schedule: birth i draws from the state after births <= i - W", "[evolution][schedule]") {
    const BirthSchedule s{ScheduleKind::pipeline, 10, 4};
    // Generation 0 is random: every birth below P may be conceived at once.
    CHECK(s.source(0) == 0);
    CHECK(s.source(9) == 0);
    CHECK(s.conceivable_end(0) == 10);
    CHECK(s.conceivable_end(9) == 10);
    // Births 10..13 wait for all of generation 0; then birth i needs births <= i-4, i.e. i-3 of them.
    CHECK(s.source(10) == 10);
    CHECK(s.source(13) == 10);
    CHECK(s.source(14) == 11);
    CHECK(s.source(20) == 17);
    CHECK(s.conceivable_end(10) == 14);
    CHECK(s.conceivable_end(17) == 21);
    // After 17 births, births 17..19 came from earlier states (kept by a checkpoint); 20 from this one.
    CHECK(s.kept_begin(17) == 17);
    CHECK(s.kept_end(17) == 20);
    CHECK(s.kept_end(10) == 10);  // right after generation 0 nothing is kept
    CHECK(s.kept_end(11) == 14);
    CHECK(s.kept_end(5) == 10);   // generation 0: random births are never kept
    CHECK(s.kept_begin(5) == 10);
    CHECK(s.describe() == "pipeline, lag 4");
}

TEST_CASE("the pipeline with lag 1 is sequential", "[evolution][schedule]") {
    const BirthSchedule s{ScheduleKind::pipeline, 5, 1};
    for (std::uint64_t i = 5; i < 40; ++i) {
        CHECK(s.source(i) == i);
        CHECK(s.conceivable_end(i) == i + 1);
        CHECK(s.kept_end(i) == s.kept_begin(i));
    }
}

TEST_CASE("the batch schedule: batches of B that never cross a generation", "[evolution][schedule]") {
    const BirthSchedule s{ScheduleKind::batch, 10, 4};
    // Generation 1 is births 10..19: batches 10-13, 14-17, 18-19.
    CHECK(s.source(12) == 10);
    CHECK(s.source(17) == 14);
    CHECK(s.source(19) == 18);
    CHECK(s.source(20) == 20);
    CHECK(s.conceivable_end(14) == 18);
    CHECK(s.conceivable_end(15) == 18);
    CHECK(s.conceivable_end(18) == 20);
    // Stopped inside a batch: its remaining births are kept; at a batch boundary nothing is.
    CHECK(s.kept_end(15) == 18);
    CHECK(s.kept_begin(15) == 15);
    CHECK(s.kept_end(14) == 14);
    CHECK(s.kept_end(20) == 20);
    CHECK(s.kept_end(3) == 10);
    CHECK(s.kept_begin(3) == 10);
    CHECK(s.describe() == "batch 4");
}
