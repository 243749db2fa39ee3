// Genomes outside the JSON of a search state (evolution/genome_blob.hpp): the
// exact bits back, and refusal of a blob or a reference that does not fit.
#include "evolution/ga/ga_state_json.hpp"
#include "evolution/genome_blob.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

using namespace morphogen;

namespace {
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}
const std::vector<double> special{-0.0, 0.0, std::numeric_limits<double>::denorm_min(), -2.2250738585072009e-308,
                                  1e308, -std::numeric_limits<double>::max(), 0.1, 1.0 / 3.0};
}  // namespace

TEST_CASE("a genome blob gives back the exact bits, little-endian", "[evolution][checkpoint]") {
    GenomeBlobWriter writer;
    std::vector<double> reversed(special.rbegin(), special.rend());
    CHECK(writer.add(special) == 0);
    CHECK(writer.add(reversed) == 1);
    CHECK(writer.count() == 2);
    CHECK(writer.dimension() == special.size());
    REQUIRE(writer.bytes().size() == 2 * special.size() * 8);
    // 1e308 is 0x7FE1CCF385EBC8A0: its lowest byte first.
    CHECK(static_cast<unsigned char>(writer.bytes()[4 * 8]) == 0xA0);
    CHECK(static_cast<unsigned char>(writer.bytes()[4 * 8 + 7]) == 0x7F);
    CHECK(static_cast<unsigned char>(writer.bytes()[7]) == 0x80);  // -0.0: the sign bit only
    CHECK_THROWS_AS(writer.add(std::vector<double>{1.0}), std::invalid_argument);  // another length

    GenomeBlobReader reader(writer.bytes(), 2, special.size());
    CHECK(same_bits(reader.take(1, "b"), reversed));
    CHECK_THROWS_WITH(reader.check_all_taken("s"), Catch::Contains("1 of its 2 genomes belong to no individual"));
    CHECK(same_bits(reader.take(0, "a"), special));
    CHECK(std::signbit(GenomeBlobReader(writer.bytes(), 2, special.size()).take(0, "a")[0]));
    CHECK_NOTHROW(reader.check_all_taken("s"));
    CHECK_THROWS_WITH(reader.take(0, "x.genome"), Catch::Contains("x.genome: genome 0 is used twice"));
    CHECK_THROWS_WITH(reader.take(2, "x.genome"), Catch::Contains("genome 2 does not exist"));
}

TEST_CASE("a genome blob of the wrong size or with a non-finite value is refused", "[evolution][checkpoint]") {
    GenomeBlobWriter writer;
    writer.add(special);
    const std::string bytes = writer.bytes();
    CHECK_THROWS_AS(GenomeBlobReader(bytes.substr(0, bytes.size() - 1), 1, special.size()), std::invalid_argument);
    CHECK_THROWS_AS(GenomeBlobReader(bytes + std::string(8, '\0'), 1, special.size()), std::invalid_argument);
    CHECK_THROWS_AS(GenomeBlobReader(bytes, 2, special.size()), std::invalid_argument);
    CHECK_THROWS_AS(GenomeBlobReader(bytes, 1, 0), std::invalid_argument);
    CHECK_NOTHROW(GenomeBlobReader("", 0, 0));
    for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        std::string damaged = bytes;
        std::memcpy(damaged.data() + 3 * 8, &bad, 8);
        GenomeBlobReader reader(damaged, 1, special.size());
        CHECK_THROWS_WITH(reader.take(0, "p"), Catch::Contains("parameter 3 of genome 0 is not finite"));
    }
}

TEST_CASE("a GA state round-trips through JSON and a genome blob bit for bit", "[evolution][checkpoint]") {
    GaParams params;
    params.population = 4;
    GaState state;
    state.births = 3;
    for (std::uint64_t i = 0; i < 3; ++i) {
        Individual ind;
        ind.id = i;
        ind.params = special;
        ind.params[i] = -ind.params[i];
        ind.fitness = i == 1 ? invalid_fitness : 0.5 * static_cast<double>(i);
        ind.size = 10;
        state.population.push_back(ind);
    }
    state.best = state.population[2];
    GenomeBlobWriter writer;
    const nlohmann::json document = ga_state_to_json(state, &writer);
    CHECK(writer.count() == 4);  // three members and the best
    CHECK_FALSE(document["population"][0].contains("params"));
    CHECK(document["population"][2]["genome"] == 2);
    GenomeBlobReader reader(writer.bytes(), writer.count(), special.size());
    const GaState back = ga_state_from_json(document, params, special.size(), &reader);
    for (std::size_t i = 0; i < 3; ++i) CHECK(same_bits(back.population[i].params, state.population[i].params));
    CHECK(same_bits(back.best->params, state.best->params));

    // Inline parameters are refused where the genomes are in a blob, and a blob's genome of another size.
    nlohmann::json inline_params = ga_state_to_json(state);
    GenomeBlobReader fresh(writer.bytes(), writer.count(), special.size());
    CHECK_THROWS_WITH(ga_state_from_json(inline_params, params, special.size(), &fresh),
                      Catch::Contains("ga.population[0].params: genomes are stored in the binary part"));
    GenomeBlobReader other(writer.bytes(), writer.count() * 2, special.size() / 2);
    CHECK_THROWS_WITH(ga_state_from_json(document, params, special.size(), &other),
                      Catch::Contains("4 parameters per genome, the problem has 8"));
}
