#include "core/base/json_text.hpp"

#include <algorithm>
#include <cstring>
#include <iterator>
#include <optional>
#include <vector>

namespace morphogen {

using nlohmann::json;

namespace {

std::string where(std::size_t line, std::size_t column, const std::string& key_path) {
    std::string text = "line " + std::to_string(line) + ", column " + std::to_string(column);
    if (!key_path.empty()) text += ", in " + key_path;
    return text;
}

// Cuts `text` to about `limit` bytes keeping its head and tail, never inside a
// UTF-8 sequence: a message stays one readable line however long the input.
std::string shorten(const std::string& text, std::size_t limit) {
    if (text.size() <= limit) return text;
    auto boundary = [&](std::size_t i) {
        while (i > 0 && i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) --i;
        return i;
    };
    const std::size_t head = boundary(limit / 2);
    const std::size_t tail = boundary(text.size() - limit / 2);
    return text.substr(0, head) + "..." + text.substr(tail);
}

// A key as it appears in a path: bare when plain, else quoted with escapes
// (so a key holding a newline cannot split the message).
std::string path_key(const std::string& key) {
    const bool plain = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
               c == '$';
    });
    return plain ? key : json(key).dump(-1, ' ', false, json::error_handler_t::replace);
}

// Iterates over the text and records the furthest byte the lexer has read, so
// that SAX callbacks (which get no position) can be placed in the text. The
// lexer reads one byte at a time and only a number looks one byte ahead.
struct CountingIterator {
    using iterator_category = std::forward_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    const char* at = nullptr;
    const char** furthest = nullptr;

    reference operator*() const { return *at; }
    CountingIterator& operator++() {
        ++at;
        if (at > *furthest) *furthest = at;
        return *this;
    }
    CountingIterator operator++(int) {
        CountingIterator before = *this;
        ++*this;
        return before;
    }
    bool operator==(const CountingIterator& other) const { return at == other.at; }
};

struct Failure {
    std::size_t offset;  // byte the error points at
    std::string key_path;
    std::string reason;
};

// Builds the document like nlohmann's own DOM parser (a stack of open
// containers, no recursion) and refuses what the strict rules forbid.
class StrictBuilder {
public:
    using number_integer_t = json::number_integer_t;
    using number_unsigned_t = json::number_unsigned_t;
    using number_float_t = json::number_float_t;
    using string_t = json::string_t;
    using binary_t = json::binary_t;

    StrictBuilder(std::string_view text, const char** furthest, json& root)
        : text_(text), furthest_(furthest), root_(root) {}

    bool null() { return put(nullptr); }
    bool boolean(bool value) { return put(value); }
    bool number_integer(number_integer_t value) { return put(value); }
    bool number_unsigned(number_unsigned_t value) { return put(value); }
    bool number_float(number_float_t value, const string_t&) { return put(value); }
    bool string(string_t& value) { return put(std::move(value)); }
    bool binary(binary_t& value) { return put(json::binary(std::move(value))); }  // not produced by JSON text

    bool start_object(std::size_t) { return open(json::object()); }
    bool start_array(std::size_t) { return open(json::array()); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    bool key(string_t& key) {
        Frame& frame = frames_.back();
        frame.key = std::move(key);
        frame.has_key = true;
        if (frame.container->contains(frame.key)) {
            // The lexer has just read the closing quote; point at the opening one.
            return fail(string_start(consumed() - 1), path(),
                        "duplicate key " + json(frame.key).dump(-1, ' ', false, json::error_handler_t::replace) +
                            " (the object already has it; JSON readers differ on which value wins)");
        }
        return true;
    }

    bool parse_error(std::size_t position, const std::string& last_token, const json::exception& error) {
        if (error.id == 406) {  // out_of_range.406: a number beyond double range
            const std::size_t start = position >= last_token.size() ? position - last_token.size() : 0;
            return fail(start, path(),
                        "the number " + shorten(last_token, 40) +
                            " is beyond the range of a double (about -1.8e308 to 1.8e308)");
        }
        std::string what = error.what();
        if (auto at = what.find("syntax error"); at != std::string::npos) {
            what = what.substr(at);
        } else if (auto colon = what.find(": "); colon != std::string::npos) {
            what = what.substr(colon + 2);
        }
        // The lexer reports the position after the byte it stopped at.
        return fail(position == 0 ? 0 : position - 1, path(), shorten(what, 200));
    }

    const std::optional<Failure>& failure() const { return failure_; }

private:
    struct Frame {
        json* container;
        std::string key;  // the object's current key
        bool has_key = false;
        std::size_t count = 0;  // the array's elements so far
    };

    std::size_t consumed() const { return static_cast<std::size_t>(*furthest_ - text_.data()); }

    // Offset of the opening quote of the string whose closing quote is at `end`:
    // the nearest quote before it not escaped by an odd run of backslashes.
    std::size_t string_start(std::size_t end) const {
        for (std::size_t i = end; i-- > 0;) {
            if (text_[i] != '"') continue;
            std::size_t slashes = 0;
            while (slashes < i && text_[i - 1 - slashes] == '\\') ++slashes;
            if (slashes % 2 == 0) return i;
        }
        return end;
    }

    // Offset of the first byte of the document (after a UTF-8 BOM and blanks).
    std::size_t document_start() const {
        std::size_t i = text_.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
        while (i < text_.size() && std::strchr(" \t\r\n", text_[i]) != nullptr && text_[i] != '\0') ++i;
        return i;
    }

    // The key path of the value being read: the innermost array's index is the
    // element now being read (`count`), an outer array's the one still open.
    std::string path() const {
        std::string text;
        for (std::size_t f = 0; f < frames_.size(); ++f) {
            const Frame& frame = frames_[f];
            if (frame.container->is_array()) {
                const bool innermost = f + 1 == frames_.size();
                const std::size_t index = innermost || frame.count == 0 ? frame.count : frame.count - 1;
                // Appended piece by piece: "[" + to_string(...) trips GCC 12's false -Wrestrict.
                text += '[';
                text += std::to_string(index);
                text += ']';
            } else if (frame.has_key) {
                if (!text.empty()) text += '.';
                text += path_key(frame.key);
            }
        }
        return shorten(text, 80);
    }

    bool fail(std::size_t offset, std::string key_path, std::string reason) {
        failure_ = Failure{offset, std::move(key_path), std::move(reason)};
        return false;
    }

    // Where a new value goes: the root, the end of the open array or the
    // current key of the open object. Null only for a non-object root.
    json* slot(const json& value) {
        if (frames_.empty()) {
            if (!value.is_object()) {
                fail(document_start(), "",
                     std::string("the document is ") + value.type_name() + ", not a JSON object");
                return nullptr;
            }
            return &root_;
        }
        Frame& frame = frames_.back();
        if (frame.container->is_array()) {
            ++frame.count;
            frame.container->push_back(nullptr);
            return &frame.container->back();
        }
        return &(*frame.container)[frame.key];
    }

    bool put(json value) {
        json* target = slot(value);
        if (target == nullptr) return false;
        *target = std::move(value);
        return true;
    }

    bool open(json container) {
        if (frames_.size() >= max_json_depth) {
            return fail(consumed() - 1, path(),
                        "nesting deeper than " + std::to_string(max_json_depth) +
                            " levels of objects and arrays (morphogen's limit)");
        }
        json* target = slot(container);
        if (target == nullptr) return false;
        *target = std::move(container);
        frames_.push_back(Frame{target, {}, false, 0});
        return true;
    }

    bool close() {
        frames_.pop_back();
        return true;
    }

    std::string_view text_;
    const char** furthest_;
    json& root_;
    std::vector<Frame> frames_;
    std::optional<Failure> failure_;
};

[[noreturn]] void throw_at(std::string_view text, const Failure& failure) {
    const std::size_t offset = std::min(failure.offset, text.size());
    const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + offset, '\n'));
    const std::size_t line_start = text.rfind('\n', offset == 0 ? std::string_view::npos : offset - 1);
    const std::size_t column = line_start == std::string_view::npos || offset == 0 ? offset + 1 : offset - line_start;
    throw JsonTextError(line, column, failure.key_path, failure.reason);
}

}  // namespace

JsonTextError::JsonTextError(std::size_t line_, std::size_t column_, std::string key_path_, std::string reason_)
    : std::runtime_error(where(line_, column_, key_path_) + ": " + reason_),
      line(line_),
      column(column_),
      key_path(std::move(key_path_)),
      reason(std::move(reason_)) {}

json read_json_object(std::string_view text) {
    if (const void* nul = text.empty() ? nullptr : std::memchr(text.data(), '\0', text.size()); nul != nullptr) {
        const auto offset = static_cast<std::size_t>(static_cast<const char*>(nul) - text.data());
        throw_at(text, {offset, "", "a NUL byte, which JSON text cannot contain (binary data or a damaged file?)"});
    }
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
        throw_at(text, {text.size(), "", "the document is empty (expected a JSON object)"});

    json root;
    const char* furthest = text.data();
    StrictBuilder builder(text, &furthest, root);
    const CountingIterator first{text.data(), &furthest};
    const CountingIterator last{text.data() + text.size(), &furthest};
    const bool ok = json::sax_parse(first, last, &builder, json::input_format_t::json, /*strict=*/true,
                                    /*ignore_comments=*/false);
    if (!ok) {
        if (builder.failure()) throw_at(text, *builder.failure());
        // Not reached: every stop of the parse records why.
        throw_at(text, {static_cast<std::size_t>(furthest - text.data()), "", "invalid JSON"});
    }
    return root;
}

}  // namespace morphogen
