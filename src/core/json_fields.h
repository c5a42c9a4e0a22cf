// The one JSON toolkit of luxel's file readers (2D and voxel scenes): typed field access that
// throws json::Invalid naming the field path, one wording for every error, and the file and parse
// steps that turn problems into Errors located at file:line:column. Objects keep members in file
// order (ordered_json), so the first problem in the file is the one reported.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "luxel/core/error.h"

namespace luxel::json {

using Json = nlohmann::ordered_json;

// A field that failed validation: thrown by the readers below, turned into a located Error by
// locate(). `atKey` points at the member's key (unknown fields) rather than its value.
struct Invalid {
    std::string field;
    std::string message;
    bool atKey = false;
};

[[noreturn]] void fail(std::string field, std::string message, bool atKey = false);

// Field paths in the display form of JsonSourceMap: "shapes[2].radius".
std::string member(const std::string& parent, const std::string& key);
std::string element(const std::string& parent, std::size_t index);

// "string", "an array of 3 elements", ... for "got ..." in messages.
std::string describe(const Json& v);
// Text that reads back as the same double: whole numbers in full ("-4"), others shortest ("0.25").
std::string formatNumber(double v);

const Json* find(const Json& object, const char* key);
// The member, or "required field is missing".
const Json& require(const Json& object, const std::string& path, const char* key);
// Every member of `object` is one of `allowed`, else "unknown field 'k' (allowed <context>: ...)".
void checkFields(const Json& object, const std::string& path,
                 const std::vector<const char*>& allowed, const std::string& context);

// An object whose members are all `allowed` (checkFields with the context "at the top level" or
// "in <path>").
void checkObject(const Json& v, const std::string& path, const std::vector<const char*>& allowed);
void requireObject(const Json& v, const std::string& path);
void requireArray(const Json& v, const std::string& path);
std::string readString(const Json& v, const std::string& path);
bool readBool(const Json& v, const std::string& path);
// A finite number.
double readNumber(const Json& v, const std::string& path);
// A finite number in [lo, hi]: "must be in lo..hi, got x".
double readNumberIn(const Json& v, const std::string& path, double lo, double hi);
// A whole number in [lo, hi]: "must be a whole number, got x", then the range.
std::int64_t readWholeNumber(const Json& v, const std::string& path, std::int64_t lo,
                             std::int64_t hi);
// An array of exactly n numbers in [lo, hi]: "must be an array of n numbers, got ...".
std::vector<double> readNumbers(const Json& v, const std::string& path, std::size_t n, double lo,
                                double hi);

// Nesting deeper than this is refused by parse(): readers and nlohmann's own copy and dump walk
// documents recursively, so unbounded nesting would overflow the stack.
inline constexpr int kMaxNestingDepth = 256;
// A file holding more values (numbers, strings, arrays, ...) than this is refused by parse() before
// a document is built; the limit is lower when the memory available cannot hold the document.
// Shipped scenes hold a few hundred values; a 64 MiB file can hold 30 million.
inline constexpr std::uint64_t kMaxJsonValues = std::uint64_t{1} << 22;
// Input text quoted in an error message is cut to this many bytes (then "...").
inline constexpr std::size_t kMaxQuotedBytes = 200;
// A whole error message is cut to this many bytes, so that one refusal stays one readable line.
inline constexpr std::size_t kMaxMessageBytes = 600;

// `text` cut to at most `maxBytes` at a UTF-8 boundary, with "..." appended when cut.
std::string clip(std::string_view text, std::size_t maxBytes = kMaxQuotedBytes);
// `message` with every run quoted in '...' clipped to kMaxQuotedBytes and the whole clipped to
// kMaxMessageBytes. parse() and locate() pass every message through it.
std::string boundMessage(std::string_view message);

// Parses JSON text; errors are located ("file:line:col: invalid JSON: ..."), including numbers
// too large for a double (1e999), nesting deeper than kMaxNestingDepth and duplicate keys. Text
// with more than kMaxJsonValues values is refused. Time and memory are linear in the text.
Result<Json> parse(std::string_view text, const std::string& sourceName);

// The Error for a validation failure, located in `text` at the failing field.
Error locate(const Invalid& invalid, std::string_view text, const std::string& sourceName);

}  // namespace luxel::json
