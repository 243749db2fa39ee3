// The strict JSON reader (core/base/json_text.hpp) and the readers built on it:
// configs (ConfigError); genome files (IoError) in tests/core/growth/test_network.cpp.
// Hostile input first.
#include "core/base/config_reader.hpp"
#include "core/base/errors.hpp"
#include "core/base/json_text.hpp"
#include "tests/support/temp_dir.hpp"

#include <catch2/catch.hpp>

#include <type_traits>

using namespace morphogen;
using morphogen::testing::TempDir;
using nlohmann::json;

namespace {
// The error read_json_object throws for `text` (fails the test if none).
JsonTextError error_of(const std::string& text) {
    try {
        (void)read_json_object(text);
    } catch (const JsonTextError& e) {
        return e;
    }
    FAIL("accepted: " << text.substr(0, 200));
    throw std::logic_error("unreachable");
}
std::string nested_arrays(std::size_t depth) {
    return "{\"a\":" + std::string(depth, '[') + std::string(depth, ']') + "}";
}
bool one_line(const std::string& text) {
    return text.find('\n') == std::string::npos && text.find('\r') == std::string::npos;
}
}  // namespace

TEST_CASE("json text: well-formed objects read as nlohmann reads them", "[json]") {
    const std::string text = R"({"growth": {"steps": 5, "speed": -0.25e-3, "ground": true, "seed_mesh": null},
      "network": {"hidden": [30, 20]}, "s": "\u00e9\n", "big": 18446744073709551615, "neg": -9223372036854775808})";
    CHECK(read_json_object(text) == json::parse(text));
    CHECK(read_json_object("\xEF\xBB\xBF {}\n\t") == json::object());  // a UTF-8 BOM and trailing blanks are fine
    CHECK(read_json_object(R"({"a": 1e-400})")["a"] == 0.0);         // underflow rounds, as every reader does
    // The same key in different objects is no duplicate.
    CHECK(read_json_object(R"({"t": [{"a": 1}, {"a": 2}], "a": {"a": 3}})")["t"][1]["a"] == 2);
    static_assert(!std::is_base_of_v<Error, JsonTextError>, "callers must choose the error type");
}

TEST_CASE("json text: nesting is limited without recursion", "[json]") {
    // The root object is level 1: 255 arrays inside it are the limit.
    CHECK_NOTHROW(read_json_object(nested_arrays(max_json_depth - 1)));
    const JsonTextError at_limit = error_of(nested_arrays(max_json_depth));
    CHECK(at_limit.line == 1);
    CHECK(at_limit.column == 5 + max_json_depth);  // the bracket that is one too deep
    CHECK_THAT(at_limit.reason, Catch::Contains("nesting deeper than 256"));
    CHECK(at_limit.key_path.rfind("a[0][0]", 0) == 0);
    CHECK(one_line(at_limit.what()));
    CHECK(at_limit.key_path.size() < 100);  // shortened, not 256 indices long
    // Far deeper than the stack could take if anything recursed over it.
    CHECK_THAT(error_of(nested_arrays(1'000'000)).reason, Catch::Contains("nesting deeper"));
    std::string objects;
    for (int i = 0; i < 300'000; ++i) objects += "{\"k\":";
    CHECK(error_of(objects + "1" + std::string(300'000, '}')).key_path.rfind("k.k.k", 0) == 0);
    // Unclosed deep nesting (a truncated file) is refused the same way.
    CHECK_THAT(error_of("{\"a\":" + std::string(500'000, '[')).reason, Catch::Contains("nesting deeper"));
}

TEST_CASE("json text: numbers beyond double range name line, column and key path", "[json]") {
    const JsonTextError e = error_of("{\"growth\": {\n  \"speed\": 1e309}}");
    CHECK(e.line == 2);
    CHECK(e.column == 12);  // where the number starts
    CHECK(e.key_path == "growth.speed");
    CHECK_THAT(e.reason, Catch::Contains("1e309") && Catch::Contains("beyond the range of a double"));
    CHECK(std::string(e.what()) == "line 2, column 12, in growth.speed: " + e.reason);
    CHECK(error_of(R"({"network": {"hidden": [4, 5, -1e400]}})").key_path == "network.hidden[2]");
    CHECK(error_of("{\"x\": " + std::string(400, '9') + "}").key_path == "x");  // an integer too long for a double
    CHECK(error_of(R"({"t": [[1, 2], [3, 1e999]]})").key_path == "t[1][1]");
}

TEST_CASE("json text: NUL bytes and anything after the document are refused", "[json]") {
    const JsonTextError nul = error_of(std::string("{\"a\": 1}\n\0junk", 14));
    CHECK(nul.line == 2);
    CHECK(nul.column == 1);
    CHECK_THAT(nul.reason, Catch::Contains("NUL"));
    CHECK_THAT(error_of(std::string("{\"a\": \"x\0y\"}", 12)).reason, Catch::Contains("NUL"));
    CHECK_THAT(error_of(R"({"a": 1} x)").reason, Catch::Contains("expected end of input"));
    CHECK(error_of(R"({"a": 1} x)").column == 10);
    CHECK_THROWS_AS(read_json_object("{}{}"), JsonTextError);
    CHECK_THROWS_AS(read_json_object("{} // comment"), JsonTextError);
    CHECK_THROWS_AS(read_json_object("{\"a\": 1 /* c */}"), JsonTextError);
    CHECK_THROWS_AS(read_json_object("{\"a\xff\": 1}"), JsonTextError);  // invalid UTF-8
    CHECK_THROWS_AS(read_json_object(R"({"a": 1,})"), JsonTextError);
    CHECK_THROWS_AS(read_json_object(R"({"a": NaN})"), JsonTextError);
}

TEST_CASE("json text: only an object is a document", "[json]") {
    for (const std::string text : {"null", "[]", "[{}]", "3", "\"s\"", "true", "\xEF\xBB\xBF null"}) {
        INFO(text);
        const JsonTextError e = error_of(text);
        CHECK_THAT(e.reason, Catch::Contains("not a JSON object"));
        CHECK(e.line == 1);
    }
    CHECK(error_of("\n\n  null").line == 3);
    CHECK(error_of("\n\n  null").column == 3);
    CHECK_THAT(error_of("").reason, Catch::Contains("empty"));
    CHECK_THAT(error_of(" \n\t\r\n").reason, Catch::Contains("empty"));
}

TEST_CASE("json text: duplicate keys are refused with their path and place", "[json]") {
    const JsonTextError top = error_of("{\"growth\":{\"steps\":5},\n \"growth\":{\"steps\":7}}");
    CHECK(top.key_path == "growth");
    CHECK(top.line == 2);
    CHECK(top.column == 2);  // the opening quote of the second "growth"
    CHECK_THAT(top.reason, Catch::Contains("duplicate key \"growth\""));
    CHECK(error_of(R"({"growth": {"steps": 5, "steps": 7}})").key_path == "growth.steps");
    CHECK(error_of(R"({"t": [{"a": 1}, {"a": 1, "a": 2}]})").key_path == "t[1].a");
    // Equal after unescaping, even with an escaped quote before the key.
    const JsonTextError escaped = error_of(R"({"q\"": 1, "steps": 5, "st\u0065ps": 7})");
    CHECK(escaped.key_path == "steps");
    CHECK(escaped.column == 24);
    const JsonTextError quote = error_of(R"({"a\"b": 1, "a\"b": 2})");
    CHECK(quote.column == 13);
    CHECK(quote.key_path == "\"a\\\"b\"");
    // A key that would break the line is shown escaped.
    const JsonTextError newline = error_of("{\"a\\nb\": {\"c\": 1e999}}");
    CHECK(newline.key_path == "\"a\\nb\".c");
    CHECK(one_line(newline.what()));
}

TEST_CASE("config text: every refusal is a ConfigError naming the source", "[json][config]") {
    const std::vector<std::string> texts = {"null", std::string("{\"a\":1}\n\0x", 10), "{\"a\":1,\"a\":2}",
                                            "{\"a\": 1e309}", "{} x", ""};
    for (const std::string& text : texts) {
        INFO(text);
        try {
            (void)parse_json_text(text, "c.json");
            FAIL("accepted");
        } catch (const ConfigError& e) {
            const std::string what = e.what();
            CHECK(what.rfind("c.json: invalid JSON at line ", 0) == 0);
            CHECK(one_line(what));
        }
    }
    CHECK_THROWS_AS(parse_json_text(nested_arrays(100'000), "deep.json"), ConfigError);
}

TEST_CASE("config files: unreadable files are IoErrors with the system's reason", "[json][config]") {
    TempDir dir("json-files");
    CHECK_THROWS_WITH(load_json_file(dir.file("missing.json")),
                      Catch::Contains("missing.json") && Catch::Contains("No such file"));
    CHECK_THROWS_AS(load_json_file(dir.path.string()), IoError);
    CHECK_THROWS_WITH(load_json_file(dir.path.string()), Catch::Contains("directory"));
    CHECK_THROWS_AS(load_json_file(dir.write("empty.json", "")), ConfigError);
    CHECK(load_json_file(dir.write("ok.json", "{\"a\": [1]}")) == json::parse("{\"a\": [1]}"));
}
