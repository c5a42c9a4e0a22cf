// Where values sit in JSON text: maps field paths such as "shapes[2].radius" to line:column, so
// that errors found after parsing (with nlohmann) can point at the offending text.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>

#include "luxel/core/error.h"

namespace luxel {

// A 1-based position in text. Columns count UTF-8 code points, not bytes.
struct TextPosition {
    int line = 0;
    int column = 0;
};

// The position of the byte at `offset` in `text` (offset == text.size() is the end of the text;
// larger offsets are clamped to it). A leading UTF-8 byte order mark takes no column.
TextPosition textPositionAt(std::string_view text, std::size_t offset);

// The position of a nlohmann::json parse_error: its `byte` member counts the bytes read, so the
// offending byte is the one before it.
TextPosition jsonParseErrorPosition(std::string_view text, std::size_t byte);

// The offset of the first number in JSON text that overflows a double (such as 1e999), which
// nlohmann reports without a position. The text needs to be valid only up to that number.
std::optional<std::size_t> findNonFiniteJsonNumber(std::string_view text);

// A problem in JSON text that nlohmann accepts but luxel refuses: nesting deeper than a limit
// (which would make every recursive walk of the document a stack overflow) or an object that names
// a key twice (nlohmann keeps the last silently).
struct JsonStructureProblem {
    enum class Kind { TooDeep, DuplicateKey };
    Kind kind = Kind::TooDeep;
    std::size_t offset = 0;  // the opening bracket beyond the limit, or the repeated key
    std::string key;         // the repeated key, unescaped
};

// The first such problem in file order. Scans iteratively (no recursion), leniently: on malformed
// text it reports what it found before the problem.
std::optional<JsonStructureProblem> findJsonStructureProblem(std::string_view text, int maxDepth);

// Positions of every value in a JSON text that is known to be valid (it is scanned, not checked;
// on malformed text the map holds what was seen before the problem).
//
// Paths use the display form: "" is the root, "canvas[1]" an array element, "shapes[2].radius" an
// object member. Keys are unescaped, so they match the parsed keys. Only values up to
// kMaxRecordedDepth levels deep are recorded, which keeps pathological nesting cheap.
class JsonSourceMap {
  public:
    static constexpr int kMaxRecordedDepth = 64;

    static JsonSourceMap build(std::string_view text);
    // Records only `focus` and its parents: what locating one field needs, in time linear in the
    // text and memory independent of it.
    static JsonSourceMap build(std::string_view text, std::optional<std::string_view> focus);

    // The start of the value at `fieldPath` (for a missing path: of its nearest recorded parent).
    // The result names `fieldPath` as the field; its file is left empty for the caller to fill.
    SourceLocation locate(const std::string& fieldPath) const;
    // Same, but for an object member the start of its key (an unknown field is reported there).
    SourceLocation locateKey(const std::string& fieldPath) const;

    bool contains(const std::string& fieldPath) const { return entries_.count(fieldPath) != 0; }
    std::size_t size() const { return entries_.size(); }

  private:
    struct Entry {
        TextPosition value;
        TextPosition key;  // the member's key; the value itself for array elements and the root
    };

    const Entry* findNearest(const std::string& fieldPath) const;

    std::unordered_map<std::string, Entry> entries_;
};

}  // namespace luxel
