// The MPI messages' encoding (cluster/protocol.hpp): evaluations come back
// with every bit, and a malformed message is refused, never read past its end.
#include "cluster/protocol.hpp"

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

using namespace morphogen;
using namespace morphogen::cluster;

namespace {
bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
}  // namespace

TEST_CASE("work and results survive encoding bit for bit", "[cluster][protocol]") {
    const double nan_payload = std::bit_cast<double>(std::uint64_t{0x7ff8000000001234});
    std::vector<WorkItem> work{{0, {}}, {7, {1.0, -0.0, 1e-310, std::nextafter(1.0, 2.0), nan_payload}}};
    const std::vector<WorkItem> work_back = decode_work(encode_work(work));
    REQUIRE(work_back.size() == 2);
    CHECK(work_back[0].params.empty());
    CHECK(work_back[1].index == 7);
    REQUIRE(work_back[1].params.size() == 5);
    for (std::size_t k = 0; k < 5; ++k) CHECK(same_bits(work_back[1].params[k], work[1].params[k]));

    Evaluation valid{0.1 + 0.2, true, "", 123.0, {-0.0, 2.5e-300}};
    Evaluation invalid{0.0, false, std::string("bad\0mesh,\n\"x\"", 14), 0.0, {}};
    const std::vector<ResultItem> results{{3, valid}, {1, invalid}};
    const std::vector<ResultItem> back = decode_results(encode_results(results));
    REQUIRE(back.size() == 2);
    CHECK(back[0].index == 3);
    CHECK(back[0].evaluation.valid);
    CHECK(same_bits(back[0].evaluation.score, valid.score));
    CHECK(same_bits(back[0].evaluation.size, 123.0));
    REQUIRE(back[0].evaluation.descriptors.size() == 2);
    CHECK(same_bits(back[0].evaluation.descriptors[0], -0.0));
    CHECK(same_bits(back[0].evaluation.descriptors[1], 2.5e-300));
    CHECK_FALSE(back[1].evaluation.valid);
    CHECK(back[1].evaluation.error == invalid.error);
    CHECK(decode_int(encode_int(-130)) == -130);
    const Ready ready = decode_ready(encode_ready({16, cpu_kind()}));
    CHECK(ready.threads == 16);
    CHECK(ready.cpu == cpu_kind());
    CHECK_FALSE(ready.cpu.empty());
}

TEST_CASE("malformed messages are refused", "[cluster][protocol]") {
    const std::string work = encode_work({{2, {1.0, 2.0}}});
    for (std::size_t cut = 0; cut < work.size(); ++cut) CHECK_THROWS_AS(decode_work(work.substr(0, cut)), ProtocolError);
    CHECK_THROWS_AS(decode_work(work + "x"), ProtocolError);

    const std::string results = encode_results({{0, Evaluation{1.0, true, "", 2.0, {3.0}}}});
    for (std::size_t cut = 0; cut < results.size(); ++cut)
        CHECK_THROWS_AS(decode_results(results.substr(0, cut)), ProtocolError);
    std::string bad_flag = results;
    bad_flag[16] = 2;  // the validity byte after count and index
    CHECK_THROWS_AS(decode_results(bad_flag), ProtocolError);

    // A count far beyond the bytes present is refused before anything is allocated.
    std::string huge(8, '\xff');
    CHECK_THROWS_AS(decode_work(huge), ProtocolError);
    CHECK_THROWS_AS(decode_results(huge), ProtocolError);
    CHECK_THROWS_AS(decode_int("abc"), ProtocolError);
    CHECK_THROWS_AS(decode_ready(encode_int(4)), ProtocolError);
}
