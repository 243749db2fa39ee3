// base/'s files at their own level: atomic files (atomic_file.hpp), append-only
// files and their FNV-1a hash (append_file.hpp, fnv_hash.hpp), and the
// background I/O thread (io_thread.hpp). The run's use of them is tested in
// tests/run/ and tests/app/.
#include "core/base/append_file.hpp"
#include "core/base/atomic_file.hpp"
#include "core/base/errors.hpp"
#include "core/base/fnv_hash.hpp"
#include "core/base/io_thread.hpp"
#include "tests/support/temp_dir.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <filesystem>
#include <future>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

using namespace morphogen;
using morphogen::testing::read_text;
using morphogen::testing::TempDir;
namespace fs = std::filesystem;

TEST_CASE("FNV-1a 64: the published values, bytewise and by words", "[base][files]") {
    CHECK(fnv1a64_hex("") == "cbf29ce484222325");
    CHECK(fnv1a64_hex("a") == "af63dc4c8601ec8c");
    CHECK(fnv1a64_hex("foobar") == "85944171f73967e8");
    // By words: the same for equal text, a different value for any changed byte.
    const std::string text = "0123456789abcdefXYZ";
    Fnv1a64 words, changed;
    words.update_words(text);
    std::string other = text;
    other[9] = '!';
    changed.update_words(other);
    CHECK(words.hex() != changed.hex());
    Fnv1a64 again;
    again.update_words(text);
    CHECK(again.value() == words.value());
}

TEST_CASE("write_file_atomically replaces the file whole and leaves no temporary", "[base][files]") {
    TempDir tmp("atomic");
    const fs::path path = tmp.path / "state.json";
    write_file_atomically(path, "first");
    CHECK(read_file_bytes(path, {1024, "test files"}) == "first");
    const std::array<std::string_view, 3> parts{"a", "", "bc"};
    write_file_atomically(path, parts);
    CHECK(read_file_bytes(path, {1024, "test files"}) == "abc");
    CHECK(temporary_path(path) == tmp.path / "state.json.tmp");
    CHECK_FALSE(fs::exists(temporary_path(path)));
}

TEST_CASE("a failed atomic write keeps the old file and names the path", "[base][files]") {
    TempDir tmp("atomic-fail");
    const fs::path path = tmp.path / "kept.txt";
    write_file_atomically(path, "old");
    // The temporary's name is taken by a directory: the write cannot happen.
    fs::create_directory(temporary_path(path));
    CHECK_THROWS_WITH(write_file_atomically(path, "new"), Catch::Contains(path.string()));
    CHECK(read_file_bytes(path, {1024, "test files"}) == "old");
    CHECK_THROWS_AS(read_file_bytes(tmp.path / "absent", {1024, "test files"}), IoError);
    CHECK_THROWS_AS(write_file_atomically(tmp.path / "no" / "dir.txt", "x"), IoError);
}

TEST_CASE("an append file knows its length and hash, and resumes only on its own prefix", "[base][files]") {
    TempDir tmp("append");
    const fs::path path = tmp.path / "lineage.csv";
    std::uint64_t length = 0;
    std::string hash;
    {
        AppendFile file = AppendFile::create(path, "id\n");
        file.write("1\n");
        CHECK(file.size() == 5);
        CHECK(file.hash_hex() == fnv1a64_hex("id\n1\n"));
        length = file.size();
        hash = file.hash_hex();
        file.write("2\n");  // written after the "checkpoint": cut off on resume
        file.sync();
    }
    CHECK(read_text(path) == "id\n1\n2\n");
    CHECK(AppendFile::check_prefix(path, length, hash) == "id\n1\n");
    CHECK(read_text(path) == "id\n1\n2\n");  // checking changes nothing
    {
        AppendFile file = AppendFile::resume(path, length, hash);
        CHECK(file.size() == length);
        file.write("3\n");
        CHECK(file.hash_hex() == fnv1a64_hex("id\n1\n3\n"));
    }
    CHECK(read_text(path) == "id\n1\n3\n");
    // A prefix that differs, or a file shorter than the length: refused, untouched.
    CHECK_THROWS_AS(AppendFile::resume(path, length, fnv1a64_hex("id\n9\n")), CheckpointError);
    CHECK_THROWS_AS(AppendFile::resume(path, 100, hash), CheckpointError);
    CHECK(read_text(path) == "id\n1\n3\n");
    CHECK_THROWS_AS(AppendFile::resume(tmp.path / "absent.csv", 0, fnv1a64_hex("")), IoError);
}

TEST_CASE("the I/O thread runs tasks in the order posted and waits for tickets", "[base][files]") {
    std::vector<int> order;
    {
        IoThread io(2);
        std::uint64_t last = 0;
        for (int i = 0; i < 20; ++i) last = io.post([&order, i] { order.push_back(i); });
        CHECK(last == 20);
        io.wait_for(last);
        CHECK(order.size() == 20);
        io.post([&order] { order.push_back(20); });
    }  // the destructor runs what is queued
    std::vector<int> expected(21);
    for (int i = 0; i <= 20; ++i) expected[i] = i;
    CHECK(order == expected);
}

TEST_CASE("after a task fails the I/O thread skips the rest and rethrows at the next call", "[base][files]") {
    IoThread io;
    bool later_ran = false;
    // The failing task waits until the second is queued: otherwise the second
    // post() may itself be "the next call" and rethrow (CI saw that race).
    std::promise<void> both_posted;
    std::shared_future<void> posted = both_posted.get_future().share();
    io.post([posted] {
        posted.wait();
        throw IoError("disk full");
    });
    io.post([&later_ran] { later_ran = true; });
    both_posted.set_value();
    CHECK_THROWS_WITH(io.drain(), "disk full");
    CHECK_FALSE(later_ran);
    CHECK_NOTHROW(io.drain());  // reported once
}

TEST_CASE("a failure is reported once; later posts are skipped quietly", "[base][files]") {
    IoThread io;
    const std::uint64_t failing = io.post([] { throw IoError("disk full"); });
    CHECK_THROWS_WITH(io.wait_for(failing), "disk full");
    bool later_ran = false;
    CHECK_NOTHROW(io.post([&later_ran] { later_ran = true; }));
    io.drain();
    CHECK_FALSE(later_ran);
}
