// Archives: grid cells and clipping, CVT nearest centroid and centroids,
// the insertion rule, and the archive's statistics.
#include "evolution/archives/archive.hpp"
#include "evolution/archives/archive_stats.hpp"
#include "evolution/archives/cvt.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <set>

using namespace morphogen;

namespace {
Individual elite(std::uint64_t id, double fitness, std::vector<double> descriptors, double size = 1.0) {
    Individual ind;
    ind.id = id;
    ind.fitness = fitness;
    ind.size = size;
    ind.descriptors = std::move(descriptors);
    return ind;
}
const double inf = std::numeric_limits<double>::infinity();
}  // namespace

TEST_CASE("grid cells: bins by the formula, row-major with the first descriptor slowest", "[evolution][archive]") {
    Archive a = Archive::grid({{"height", 0, 20, 4}, {"footprint", -1, 3, 5}});
    CHECK(a.cells() == 20);
    CHECK(a.dimensions() == 2);
    // height 12 -> floor(12/20*4) = 2; footprint 1.5 -> floor(2.5/4*5) = 3
    CHECK(a.bins_of(std::vector<double>{12, 1.5}) == std::vector<std::uint64_t>{2, 3});
    CHECK(a.cell_of(std::vector<double>{12, 1.5}) == 2u * 5u + 3u);
    // bin edges belong to the upper bin
    CHECK(a.bins_of(std::vector<double>{5, -0.2}) == std::vector<std::uint64_t>{1, 1});
    // three descriptors: ((b0 * n1) + b1) * n2 + b2
    Archive three = Archive::grid({{"a", 0, 1, 2}, {"b", 0, 1, 3}, {"c", 0, 1, 4}});
    CHECK(three.cells() == 24);
    CHECK(three.cell_of(std::vector<double>{0.9, 0.5, 0.3}) == (1u * 3u + 1u) * 4u + 1u);
    std::set<std::uint64_t> seen;
    for (double x = 0.05; x < 1; x += 0.5)
        for (double y = 0.1; y < 1; y += 1.0 / 3)
            for (double z = 0.1; z < 1; z += 0.25) seen.insert(*three.cell_of(std::vector<double>{x, y, z}));
    CHECK(seen.size() == 24);
    CHECK(*seen.rbegin() == 23);
}

TEST_CASE("grid cells: values outside the range clip to the edge cells", "[evolution][archive]") {
    Archive a = Archive::grid({{"x", 0, 10, 10}});
    CHECK(a.cell_of(std::vector<double>{-5}) == 0u);
    CHECK(a.cell_of(std::vector<double>{-0.0}) == 0u);
    CHECK(a.cell_of(std::vector<double>{0}) == 0u);
    CHECK(a.cell_of(std::vector<double>{9.999}) == 9u);
    CHECK(a.cell_of(std::vector<double>{10}) == 9u);  // max itself is in the last bin
    CHECK(a.cell_of(std::vector<double>{1e300}) == 9u);
    CHECK(a.cell_of(std::vector<double>{-1e308}) == 0u);
    CHECK(a.cell_of(std::vector<double>{std::numeric_limits<double>::max()}) == 9u);
    // not placeable: non-finite or the wrong number of descriptors
    CHECK_FALSE(a.cell_of(std::vector<double>{std::nan("")}));
    CHECK_FALSE(a.cell_of(std::vector<double>{inf}));
    CHECK_FALSE(a.cell_of(std::vector<double>{}));
    CHECK_FALSE(a.cell_of(std::vector<double>{1, 2}));
    CHECK_THROWS_AS(a.bins_of(std::vector<double>{std::nan("")}), std::invalid_argument);
}

TEST_CASE("bad archive shapes are refused", "[evolution][archive]") {
    CHECK_THROWS_WITH(Archive::grid({}), Catch::Contains("at least one"));
    CHECK_THROWS_WITH(Archive::grid({{"h", 1, 1, 3}}), Catch::Contains("descriptor 0 (h)") && Catch::Contains("min < max"));
    CHECK_THROWS_WITH(Archive::grid({{"h", 2, 1, 3}}), Catch::Contains("min < max"));
    CHECK_THROWS_AS(Archive::grid({{"h", 0, inf, 3}}), std::invalid_argument);
    CHECK_THROWS_AS(Archive::grid({{"h", -1e308, 1e308, 3}}), std::invalid_argument);  // max - min overflows
    CHECK_THROWS_WITH(Archive::grid({{"h", 0, 1, 0}}), Catch::Contains("bins >= 1"));
    CHECK_THROWS_WITH(Archive::grid({{"a", 0, 1, 2}, {"b", 0, 1, 2}, {"c", 0, 1, 2}, {"d", 0, 1, 2}}),
                      Catch::Contains("1 to 3"));
    CHECK_THROWS_WITH(Archive::grid({{"a", 0, 1, 1 << 20}, {"b", 0, 1, 1 << 20}, {"c", 0, 1, 2}}),
                      Catch::Contains("more than"));
    CHECK_THROWS_AS(Archive::cvt({{"a", 0, 1, 1}}, {}), std::invalid_argument);
    CHECK_THROWS_AS(Archive::cvt({{"a", 0, 1, 1}, {"b", 0, 1, 1}}, {0.5, 0.5, 0.5}), std::invalid_argument);
    CHECK_THROWS_WITH(Archive::cvt({{"a", 0, 1, 1}}, {0.5, 1.5}), Catch::Contains("outside [0, 1]"));
    CHECK_THROWS_AS(Archive::cvt({{"a", 0, 1, 1}}, {0.5, std::nan("")}), std::invalid_argument);
    CHECK_THROWS_WITH(Archive::cvt({{"a", 0, 1, 1}}, std::vector<double>(kMaxCvtCells + 1, 0.5)),
                      Catch::Contains("at most"));
    CHECK_THROWS_WITH(cvt_centroids(1, kMaxCvtCells + 1, 2), Catch::Contains("1 to"));
    CHECK_THROWS_AS(cvt_centroids(1, 0, 2), std::invalid_argument);
    CHECK_THROWS_AS(cvt_centroids(1, 5, 0), std::invalid_argument);
}

TEST_CASE("insertion: empty cell, better, equal (the newcomer wins), worse, invalid", "[evolution][archive]") {
    Archive a = Archive::grid({{"x", 0, 1, 2}, {"y", 0, 1, 2}});
    using P = Archive::Placement;
    CHECK(a.insert(elite(0, 1.0, {0.1, 0.1})).placement == P::filled);
    CHECK(a.insert(elite(1, 2.0, {0.2, 0.3})).placement == P::replaced);
    CHECK(a.elites().at(0).id == 1);
    CHECK(a.insert(elite(2, 2.0, {0.4, 0.4})).placement == P::replaced);  // equal fitness: the younger wins
    CHECK(a.elites().at(0).id == 2);
    CHECK(a.insert(elite(3, 1.5, {0.0, 0.0})).placement == P::rejected);  // worse
    CHECK(a.elites().at(0).id == 2);
    CHECK(a.insert(elite(4, invalid_fitness, {0.9, 0.9})).placement == P::rejected);  // invalid enters nowhere
    CHECK(a.insert(elite(5, 7.0, {0.9, std::nan("")})).placement == P::rejected);     // unplaceable
    CHECK(a.insert(elite(6, 7.0, {0.9})).placement == P::rejected);
    CHECK(a.occupied() == 1);
    CHECK(a.insert(elite(7, -3.0, {0.9, 0.1})).placement == P::filled);  // cell (1, 0) = 2
    CHECK(a.insert(elite(8, -9.0, {0.1, 0.9})).placement == P::filled);  // cell (0, 1) = 1
    REQUIRE(a.snapshot().size() == 3);
    CHECK(a.snapshot()[0]->id == 2);  // index order: cells 0, 1, 2
    CHECK(a.snapshot()[1]->id == 8);
    CHECK(a.snapshot()[2]->id == 7);
}

TEST_CASE("insertion reports the cell, the elite and the threshold it met", "[evolution][archive]") {
    Archive a = Archive::grid({{"x", 0, 1, 2}});
    const Archive::Insertion first = a.insert(elite(0, 1.0, {0.1}));
    CHECK(first.cell == 0u);
    CHECK_FALSE(first.elite_fitness);
    const Archive::Insertion second = a.insert(elite(1, 0.5, {0.2}));
    CHECK(second.placement == Archive::Placement::rejected);
    CHECK(second.elite_fitness == 1.0);
    CHECK_FALSE(a.insert(elite(2, 1.0, {std::nan("")})).cell);
    CHECK(a.thresholds().empty());  // none kept without keep_thresholds
}

TEST_CASE("kept thresholds move by the learning rate toward a child that beats them", "[evolution][archive]") {
    Archive a = Archive::grid({{"x", 0, 1, 2}});
    a.keep_thresholds({0.5, 0.0});
    CHECK_NOTHROW(a.keep_thresholds({0.5, 0.0}));
    CHECK_THROWS_AS(a.keep_thresholds({0.1, 0.0}), std::invalid_argument);
    CHECK(a.insert(elite(0, 10.0, {0.1})).threshold == 0.0);  // 0 -> 0.5 * 0 + 0.5 * 10
    CHECK(a.thresholds().at(0) == 5.0);
    const Archive::Insertion second = a.insert(elite(1, 8.0, {0.1}));  // 5 -> 6.5; the elite stays the 10
    CHECK(second.threshold == 5.0);
    CHECK(second.placement == Archive::Placement::rejected);
    CHECK(a.thresholds().at(0) == 6.5);
    a.insert(elite(2, 4.0, {0.1}));  // below the threshold: no change
    CHECK(a.thresholds().at(0) == 6.5);
    a.insert(elite(3, -1.0, {0.9}));  // below threshold_min: no entry for its cell
    CHECK(a.elites().at(0).fitness == 10.0);
    CHECK(a.thresholds().size() == 1);
    a.restore_threshold(1, 0.25);
    CHECK(a.thresholds().at(1) == 0.25);
    Archive plain = Archive::grid({{"x", 0, 1, 2}});
    CHECK_THROWS_AS(plain.restore_threshold(0, 1.0), std::logic_error);
    CHECK_THROWS_AS(plain.keep_thresholds({1.5, 0.0}), std::invalid_argument);
}

TEST_CASE("restore checks the cell against the elite", "[evolution][archive]") {
    Archive a = Archive::grid({{"x", 0, 1, 4}});
    CHECK_NOTHROW(a.restore(2, elite(3, 1.0, {0.6})));
    CHECK_THROWS_WITH(a.restore(2, elite(4, 1.0, {0.6})), Catch::Contains("twice"));
    CHECK_THROWS_WITH(a.restore(1, elite(5, 1.0, {0.6})), Catch::Contains("map to cell 2"));
    CHECK_THROWS_WITH(a.restore(4, elite(6, 1.0, {0.9})), Catch::Contains("out of range"));
    CHECK_THROWS_WITH(a.restore(0, elite(7, invalid_fitness, {0.1})), Catch::Contains("invalid"));
    CHECK_THROWS_WITH(a.restore(0, elite(8, 1.0, {})), Catch::Contains("no cell"));
    CHECK(a.occupied() == 1);
}

TEST_CASE("coverage and QD-score arithmetic", "[evolution][archive]") {
    Archive a = Archive::grid({{"x", 0, 10, 10}, {"y", 0, 1, 4}});  // 40 cells
    ArchiveStats empty = archive_stats(a, 5.0);
    CHECK(empty.occupied == 0);
    CHECK(empty.coverage == 0.0);
    CHECK(empty.qd_score == 0.0);
    CHECK_FALSE(empty.fitness.best);
    a.insert(elite(0, 3.0, {0.5, 0.1}, 100));
    a.insert(elite(1, 7.5, {5.5, 0.1}, 200));
    a.insert(elite(2, -1.0, {9.5, 0.9}, 300));
    a.insert(elite(3, 2.0, {9.5, 0.8}, 400));  // replaces -1.0 in the same cell
    a.insert(elite(4, 10.0, {1.5, 0.6}, 500));
    const ArchiveStats s = archive_stats(a, 0.0);
    CHECK(s.occupied == 4);
    CHECK(s.cells == 40);
    CHECK(s.coverage == 0.1);
    CHECK(s.qd_score == 3.0 + 7.5 + 2.0 + 10.0);
    CHECK(*s.fitness.best == 10.0);
    CHECK(*s.fitness.worst == 2.0);
    CHECK(*s.fitness.mean == 22.5 / 4);
    CHECK(*s.fitness.median == 0.5 * (3.0 + 7.5));
    CHECK(*s.fitness.mean_size == (100 + 200 + 400 + 500) / 4.0);
    // the offset is subtracted once per occupied cell
    CHECK(archive_stats(a, 2.0).qd_score == 22.5 - 4 * 2.0);
    CHECK(archive_stats(a, -10.0).qd_score == 22.5 + 40.0);
}

TEST_CASE("CVT: the nearest centroid in the scaled space, ties to the lower index", "[evolution][archive][cvt]") {
    // Centroids in [0,1]^2; descriptors scaled by x in [0, 10], y in [-1, 1].
    const std::vector<double> centroids{0.25, 0.5,   //
                                        0.75, 0.5,   //
                                        0.5, 0.25,   //
                                        0.75, 0.5};  // a duplicate of centroid 1
    Archive a = Archive::cvt({{"x", 0, 10, 1}, {"y", -1, 1, 1}}, centroids);
    CHECK(a.kind() == ArchiveKind::cvt);
    CHECK(a.cells() == 4);
    CHECK(a.cell_of(std::vector<double>{2.0, 0.1}) == 0u);   // (0.2, 0.55)
    CHECK(a.cell_of(std::vector<double>{8.0, 0.0}) == 1u);   // (0.8, 0.5): on 1 and 3, the lower wins
    CHECK(a.cell_of(std::vector<double>{5.0, -0.6}) == 2u);  // (0.5, 0.2)
    CHECK(a.cell_of(std::vector<double>{5.0, 0.0}) == 0u);   // (0.5, 0.5): 0 and 1 at 0.0625, 2 at 0.0625 too
    // outside the ranges: clamped to [0,1] first
    CHECK(a.cell_of(std::vector<double>{1e9, 0.0}) == 1u);
    CHECK(a.cell_of(std::vector<double>{-1e9, 1e9}) == 0u);
    CHECK_FALSE(a.cell_of(std::vector<double>{std::nan(""), 0.0}));
    CHECK_THROWS_AS(a.bins_of(std::vector<double>{1, 0}), std::logic_error);
    // nearest_centroid by brute force over random points
    const std::vector<double> cloud = cvt_centroids(3, 50, 3);
    for (int i = 0; i < 200; ++i) {
        const std::vector<double> p{(i % 7) / 7.0, (i % 11) / 11.0, (i % 13) / 13.0};
        const std::size_t found = nearest_centroid(cloud, p);
        double best = inf;
        for (std::size_t c = 0; c < 50; ++c) {
            double d = 0;
            for (int k = 0; k < 3; ++k) d += (p[k] - cloud[c * 3 + k]) * (p[k] - cloud[c * 3 + k]);
            best = std::min(best, d);
        }
        double d = 0;
        for (int k = 0; k < 3; ++k) d += (p[k] - cloud[found * 3 + k]) * (p[k] - cloud[found * 3 + k]);
        CHECK(d == best);
    }
}

TEST_CASE("CVT centroids come from the seed alone, for any thread count", "[evolution][archive][cvt]") {
    const std::vector<double> one = cvt_centroids(7, 64, 2, 1);
    REQUIRE(one.size() == 128);
    CHECK(cvt_centroids(7, 64, 2, 2) == one);
    CHECK(cvt_centroids(7, 64, 2, 8) == one);
    CHECK(cvt_centroids(8, 64, 2, 1) != one);
    for (double x : one) CHECK((x >= 0.0 && x <= 1.0));
    // Lloyd spreads the centroids: each of the 4 quadrants holds about a quarter
    int quadrant[4] = {0, 0, 0, 0};
    for (std::size_t c = 0; c < 64; ++c) ++quadrant[(one[2 * c] >= 0.5) * 2 + (one[2 * c + 1] >= 0.5)];
    for (int q : quadrant) CHECK((q >= 12 && q <= 20));
    // and no two centroids are close: the smallest gap is well above that of
    // random points (expected ~ 0.5 / 64 for uniform points)
    double gap = inf;
    for (std::size_t i = 0; i < 64; ++i)
        for (std::size_t j = i + 1; j < 64; ++j)
            gap = std::min(gap, std::hypot(one[2 * i] - one[2 * j], one[2 * i + 1] - one[2 * j + 1]));
    CHECK(gap > 0.05);
    // every cell of a CVT archive built on them is reachable: each centroid is its own nearest
    Archive a = Archive::cvt({{"x", 0, 1, 1}, {"y", 0, 1, 1}}, one);
    for (std::size_t c = 0; c < 64; ++c)
        CHECK(a.cell_of(std::vector<double>{one[2 * c], one[2 * c + 1]}) == c);
}
