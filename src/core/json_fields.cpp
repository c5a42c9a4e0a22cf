#include "core/json_fields.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <system_error>

#include "core/json_source_map.h"
#include "luxel/core/memory.h"

namespace luxel::json {

void fail(std::string field, std::string message, bool atKey) {
    throw Invalid{std::move(field), std::move(message), atKey};
}

std::string member(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
}

std::string element(const std::string& parent, std::size_t index) {
    return parent + "[" + std::to_string(index) + "]";
}

std::string describe(const Json& v) {
    if (v.is_array()) {
        return "an array of " + std::to_string(v.size()) +
               (v.size() == 1 ? " element" : " elements");
    }
    return v.type_name();
}

std::string formatNumber(double v) {
    char buffer[64];
    const bool whole = std::abs(v) < 1e15 && v == std::floor(v);
    const auto [end, ec] =
        whole ? std::to_chars(buffer, buffer + sizeof(buffer), v, std::chars_format::fixed)
              : std::to_chars(buffer, buffer + sizeof(buffer), v);
    return ec == std::errc() ? std::string(buffer, end) : std::string("?");
}

const Json* find(const Json& object, const char* key) {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

const Json& require(const Json& object, const std::string& path, const char* key) {
    const Json* v = find(object, key);
    if (!v) fail(member(path, key), "required field is missing");
    return *v;
}

void checkFields(const Json& object, const std::string& path,
                 const std::vector<const char*>& allowed, const std::string& context) {
    for (auto it = object.begin(); it != object.end(); ++it) {
        const bool known = std::any_of(allowed.begin(), allowed.end(),
                                       [&](const char* name) { return it.key() == name; });
        if (!known) {
            std::string names;
            for (const char* name : allowed)
                names += (names.empty() ? "" : ", ") + std::string(name);
            fail(member(path, it.key()),
                 "unknown field '" + it.key() + "' (allowed " + context + ": " + names + ")", true);
        }
    }
}

void checkObject(const Json& v, const std::string& path, const std::vector<const char*>& allowed) {
    requireObject(v, path);
    checkFields(v, path, allowed, path.empty() ? "at the top level" : "in " + path);
}

void requireObject(const Json& v, const std::string& path) {
    if (!v.is_object()) fail(path, "must be an object, got " + describe(v));
}

void requireArray(const Json& v, const std::string& path) {
    if (!v.is_array()) fail(path, "must be an array, got " + describe(v));
}

std::string readString(const Json& v, const std::string& path) {
    if (!v.is_string()) fail(path, "must be a string, got " + describe(v));
    return v.get<std::string>();
}

bool readBool(const Json& v, const std::string& path) {
    if (!v.is_boolean()) fail(path, "must be true or false, got " + describe(v));
    return v.get<bool>();
}

double readNumber(const Json& v, const std::string& path) {
    if (!v.is_number()) fail(path, "must be a number, got " + describe(v));
    const double x = v.get<double>();
    // The parser rejects NaN and overflow, but a Json built in code may hold them.
    if (!std::isfinite(x)) fail(path, "must be finite, got " + formatNumber(x));
    return x;
}

double readNumberIn(const Json& v, const std::string& path, double lo, double hi) {
    const double x = readNumber(v, path);
    if (x < lo || x > hi) {
        fail(path, "must be in " + formatNumber(lo) + ".." + formatNumber(hi) + ", got " +
                       formatNumber(x));
    }
    return x;
}

std::int64_t readWholeNumber(const Json& v, const std::string& path, std::int64_t lo,
                             std::int64_t hi) {
    const double x = readNumber(v, path);
    if (x != std::floor(x)) fail(path, "must be a whole number, got " + formatNumber(x));
    return static_cast<std::int64_t>(
        readNumberIn(v, path, static_cast<double>(lo), static_cast<double>(hi)));
}

std::vector<double> readNumbers(const Json& v, const std::string& path, std::size_t n, double lo,
                                double hi) {
    if (!v.is_array() || v.size() != n) {
        fail(path, "must be an array of " + std::to_string(n) + " numbers, got " + describe(v));
    }
    std::vector<double> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back(readNumberIn(v[i], element(path, i), lo, hi));
    return out;
}

namespace {

// nlohmann's message without "[json.exception.parse_error.101] parse error at line 2, column 8: ",
// since the location is given in our own form.
std::string stripJsonExceptionPrefix(std::string message) {
    if (!message.empty() && message[0] == '[') {
        const std::size_t end = message.find("] ");
        if (end != std::string::npos) message.erase(0, end + 2);
    }
    if (message.rfind("parse error", 0) == 0) {
        const std::size_t colon = message.find(": ");
        if (colon != std::string::npos) message.erase(0, colon + 2);
    }
    return message;
}

Error numberOverflowError(std::string_view text, const std::string& sourceName) {
    SourceLocation where;
    where.file = sourceName;
    const std::optional<std::size_t> offset = findNonFiniteJsonNumber(text);
    if (!offset) return Error(where, "invalid JSON: a number is too large (must be finite)");
    const TextPosition pos = textPositionAt(text, *offset);
    where.line = pos.line;
    where.column = pos.column;
    std::size_t end = *offset;
    while (end < text.size() &&
           std::string_view("+-.0123456789eE").find(text[end]) != std::string_view::npos) {
        ++end;
    }
    return Error(where, "invalid JSON: number " + clip(text.substr(*offset, end - *offset)) +
                            " is too large (must be finite)");
}

}  // namespace

std::string clip(std::string_view text, std::size_t maxBytes) {
    if (text.size() <= maxBytes) return std::string(text);
    std::size_t end = maxBytes;
    // Do not split a UTF-8 code point: back up over continuation bytes.
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
    return std::string(text.substr(0, end)) + "...";
}

std::string boundMessage(std::string_view message) {
    std::string out;
    std::size_t pos = 0;
    while (pos < message.size()) {
        const std::size_t open = message.find('\'', pos);
        const std::size_t close =
            open == std::string_view::npos ? open : message.find('\'', open + 1);
        if (close == std::string_view::npos) {
            out += message.substr(pos);
            break;
        }
        out += message.substr(pos, open + 1 - pos);
        out += clip(message.substr(open + 1, close - open - 1));
        out += '\'';
        pos = close + 1;
    }
    return clip(out, kMaxMessageBytes);
}

namespace {

// Bytes a document costs per value, measured roughly for ordered_json: the 16-byte value, its
// slot in the parent (a key string and a pair for object members) and allocator overhead.
constexpr std::uint64_t kBytesPerJsonValue = 96;

std::uint64_t maxJsonValues() {
    const std::uint64_t available = availableMemoryBytes();
    if (available == 0) return kMaxJsonValues;
    return std::max<std::uint64_t>(1, std::min(kMaxJsonValues, available / kBytesPerJsonValue));
}

// The checking pass: counts values and nesting, builds nothing. Returning false stops the parse.
struct BoundedSax final : nlohmann::json_sax<Json> {
    explicit BoundedSax(std::uint64_t limit) : maxValues(limit) {}

    bool value() { return ++values <= maxValues; }
    bool open() {
        if (++depth > kMaxNestingDepth) {
            tooDeep = true;
            return false;
        }
        return value();
    }
    bool close() {
        --depth;
        return true;
    }

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return open(); }
    bool key(string_t&) override { return true; }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(); }
    bool end_array() override { return close(); }
    bool parse_error(std::size_t, const std::string&,
                     const nlohmann::detail::exception& e) override {
        // Kept as nlohmann's own type (a parse_error, or out_of_range for 1e999), so parse()
        // words it like a failed document parse.
        if (const auto* syntax = dynamic_cast<const Json::parse_error*>(&e)) {
            failure = std::make_exception_ptr(*syntax);
        } else if (const auto* range = dynamic_cast<const Json::out_of_range*>(&e)) {
            failure = std::make_exception_ptr(*range);
        } else {
            failure = std::make_exception_ptr(Json::other_error::create(599, e.what(), nullptr));
        }
        return false;
    }

    std::uint64_t maxValues;
    std::uint64_t values = 0;
    int depth = 0;
    bool tooDeep = false;
    std::exception_ptr failure;
};

Error locatedError(const std::string& sourceName, std::string_view text, std::size_t offset,
                   const std::string& message) {
    SourceLocation where;
    where.file = sourceName;
    const TextPosition pos = textPositionAt(text, offset);
    where.line = pos.line;
    where.column = pos.column;
    return Error(where, boundMessage(message));
}

std::string tooDeepMessage() {
    return "invalid JSON: nesting deeper than " + std::to_string(kMaxNestingDepth) +
           " levels (the nesting depth limit)";
}

// Depth and duplicate keys, located: called once nlohmann has accepted the text up to the problem.
std::optional<Error> structureError(std::string_view text, const std::string& sourceName) {
    const auto problem = findJsonStructureProblem(text, kMaxNestingDepth);
    if (!problem) return std::nullopt;
    if (problem->kind == JsonStructureProblem::Kind::TooDeep)
        return locatedError(sourceName, text, problem->offset, tooDeepMessage());
    return locatedError(sourceName, text, problem->offset,
                        "invalid JSON: duplicate key '" + problem->key +
                            "' (keys must be unique within an object)");
}

}  // namespace

Result<Json> parse(std::string_view text, const std::string& sourceName) {
    SourceLocation file;
    file.file = sourceName;
    try {
        // A first pass without a document checks the syntax, the depth and the number of values
        // (nlohmann's parser is iterative, so deep nesting costs no stack here). Only text that
        // passes every check is built into a document, so refusals cost no memory.
        const std::uint64_t limit = maxJsonValues();
        BoundedSax sax(limit);
        if (!Json::sax_parse(text.begin(), text.end(), &sax)) {
            if (sax.failure) std::rethrow_exception(sax.failure);
            if (sax.tooDeep) {
                if (auto error = structureError(text, sourceName)) return *error;
                return Error(file, tooDeepMessage());
            }
            return Error(file, "invalid JSON: more than " + std::to_string(limit) +
                                   " values (the limit for one file" +
                                   (limit < kMaxJsonValues ? " in the memory available" : "") +
                                   ")");
        }
        if (auto error = structureError(text, sourceName)) return *error;
        return Json::parse(text.begin(), text.end());
    } catch (const Json::parse_error& e) {
        const TextPosition pos = jsonParseErrorPosition(text, e.byte);
        SourceLocation where = file;
        where.line = pos.line;
        where.column = pos.column;
        return Error(where, boundMessage("invalid JSON: " + stripJsonExceptionPrefix(e.what())));
    } catch (const Json::out_of_range& e) {
        if (e.id == 406) return numberOverflowError(text, sourceName);  // e.g. 1e999
        return Error(file, boundMessage("invalid JSON: " + stripJsonExceptionPrefix(e.what())));
    } catch (const Json::exception& e) {
        return Error(file, boundMessage("invalid JSON: " + stripJsonExceptionPrefix(e.what())));
    }
}

Error locate(const Invalid& invalid, std::string_view text, const std::string& sourceName) {
    const JsonSourceMap map = JsonSourceMap::build(text, std::string_view(invalid.field));
    SourceLocation where = invalid.atKey ? map.locateKey(invalid.field) : map.locate(invalid.field);
    where.file = sourceName;
    where.field = clip(where.field);
    return Error(where, boundMessage(invalid.message));
}

}  // namespace luxel::json
