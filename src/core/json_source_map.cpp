// JsonSourceMap: a lenient scanner that records the line:column of every value in JSON text.
#include "core/json_source_map.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <unordered_set>
#include <vector>

namespace luxel {
namespace {

constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

bool isJsonSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// Walks the text byte by byte, keeping the line and code-point column of the current byte.
class Cursor {
  public:
    explicit Cursor(std::string_view text) : text_(text) {
        if (text_.substr(0, kUtf8Bom.size()) == kUtf8Bom) pos_ = kUtf8Bom.size();
    }

    bool atEnd() const { return pos_ >= text_.size(); }
    char peek() const { return atEnd() ? '\0' : text_[pos_]; }
    std::size_t offset() const { return pos_; }
    TextPosition position() const { return {line_, column_}; }

    void advance() {
        if (atEnd()) return;
        const auto byte = static_cast<unsigned char>(text_[pos_++]);
        if (byte == '\n') {
            ++line_;
            column_ = 1;
        } else if (!atEnd() && (static_cast<unsigned char>(text_[pos_]) & 0xC0) == 0x80) {
            // The next byte continues this code point: it shares the column.
        } else {
            ++column_;
        }
    }

    void advanceTo(std::size_t offset) {
        while (pos_ < offset && !atEnd()) advance();
    }

    void skipSpace() {
        while (!atEnd() && isJsonSpace(text_[pos_])) advance();
    }

  private:
    std::string_view text_;
    std::size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
};

void appendUtf8(std::string& out, std::uint32_t cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

// Reads 4 hex digits; false when they are not there.
bool readHex4(Cursor& cur, std::uint32_t& value) {
    value = 0;
    for (int i = 0; i < 4; ++i) {
        const char c = cur.peek();
        int digit;
        if (c >= '0' && c <= '9') {
            digit = c - '0';
        } else if (c >= 'a' && c <= 'f') {
            digit = c - 'a' + 10;
        } else if (c >= 'A' && c <= 'F') {
            digit = c - 'A' + 10;
        } else {
            return false;
        }
        value = value * 16 + static_cast<std::uint32_t>(digit);
        cur.advance();
    }
    return true;
}

// Reads a string starting at its opening quote, leaving the cursor after the closing one. With
// `decoded`, stores the unescaped text (the key as nlohmann sees it). False on malformed text.
bool readString(Cursor& cur, std::string* decoded) {
    if (cur.peek() != '"') return false;
    cur.advance();
    while (!cur.atEnd()) {
        const char c = cur.peek();
        if (c == '"') {
            cur.advance();
            return true;
        }
        if (c != '\\') {
            if (decoded) *decoded += c;
            cur.advance();
            continue;
        }
        cur.advance();
        const char esc = cur.peek();
        cur.advance();
        if (esc == 'u') {
            std::uint32_t cp;
            if (!readHex4(cur, cp)) return false;
            // A high surrogate followed by an escaped low surrogate is one code point.
            if (cp >= 0xD800 && cp <= 0xDBFF && cur.peek() == '\\') {
                cur.advance();
                if (cur.peek() != 'u') return false;
                cur.advance();
                std::uint32_t low;
                if (!readHex4(cur, low)) return false;
                if (low >= 0xDC00 && low <= 0xDFFF)
                    cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
            }
            if (decoded) appendUtf8(*decoded, cp);
            continue;
        }
        if (!decoded) continue;
        switch (esc) {
            case 'b':
                *decoded += '\b';
                break;
            case 'f':
                *decoded += '\f';
                break;
            case 'n':
                *decoded += '\n';
                break;
            case 'r':
                *decoded += '\r';
                break;
            case 't':
                *decoded += '\t';
                break;
            default:
                *decoded += esc;
                break;  // \" \\ \/
        }
    }
    return false;
}

// Skips a number or a literal (true, false, null).
void skipScalar(Cursor& cur) {
    while (!cur.atEnd()) {
        const char c = cur.peek();
        if (isJsonSpace(c) || c == ',' || c == ']' || c == '}' || c == ':') return;
        cur.advance();
    }
}

}  // namespace

TextPosition textPositionAt(std::string_view text, std::size_t offset) {
    Cursor cur(text);
    cur.advanceTo(offset);
    return cur.position();
}

TextPosition jsonParseErrorPosition(std::string_view text, std::size_t byte) {
    return textPositionAt(text, byte > 0 ? byte - 1 : 0);
}

std::optional<std::size_t> findNonFiniteJsonNumber(std::string_view text) {
    Cursor cur(text);
    while (!cur.atEnd()) {
        const char c = cur.peek();
        if (c == '"') {
            if (!readString(cur, nullptr)) return std::nullopt;
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            // Outside strings only numbers hold digits or '-'.
            const std::size_t start = cur.offset();
            skipScalar(cur);
            const std::string token(text.substr(start, cur.offset() - start));
            if (!std::isfinite(std::strtod(token.c_str(), nullptr))) return start;
        } else {
            cur.advance();
        }
    }
    return std::nullopt;
}

std::optional<JsonStructureProblem> findJsonStructureProblem(std::string_view text, int maxDepth) {
    struct Frame {
        bool isArray;
        std::unordered_set<std::string> keys;
    };
    std::vector<Frame> stack;
    bool expectKey = false;  // just after '{' or an object's ','
    Cursor cur(text);
    while (!cur.atEnd()) {
        const char c = cur.peek();
        const std::size_t offset = cur.offset();
        if (c == '{' || c == '[') {
            if (static_cast<int>(stack.size()) >= maxDepth) {
                return JsonStructureProblem{JsonStructureProblem::Kind::TooDeep, offset, {}};
            }
            stack.push_back({c == '[', {}});
            expectKey = c == '{';
            cur.advance();
        } else if (c == '}' || c == ']') {
            if (stack.empty()) return std::nullopt;
            stack.pop_back();
            expectKey = false;
            cur.advance();
        } else if (c == ',') {
            expectKey = !stack.empty() && !stack.back().isArray;
            cur.advance();
        } else if (c == '"') {
            std::string key;
            if (!readString(cur, expectKey ? &key : nullptr)) return std::nullopt;
            if (expectKey && !stack.back().keys.insert(key).second) {
                return JsonStructureProblem{JsonStructureProblem::Kind::DuplicateKey, offset,
                                            std::move(key)};
            }
            expectKey = false;
        } else {
            if (!isJsonSpace(c)) expectKey = false;
            cur.advance();
        }
    }
    return std::nullopt;
}

namespace {

// Whether `path` is `focus` or one of its parents ("shapes" and "shapes[2]" for
// "shapes[2].radius").
bool leadsTo(std::string_view path, std::string_view focus) {
    if (focus.substr(0, path.size()) != path) return false;
    return path.size() == focus.size() || path.empty() || focus[path.size()] == '.' ||
           focus[path.size()] == '[';
}

}  // namespace

JsonSourceMap JsonSourceMap::build(std::string_view text) {
    return build(text, std::nullopt);
}

JsonSourceMap JsonSourceMap::build(std::string_view text, std::optional<std::string_view> focus) {
    JsonSourceMap map;
    // An open array or object; `path` is empty when it lies deeper than kMaxRecordedDepth.
    struct Frame {
        bool isArray;
        bool recorded;
        std::string path;
        int index;
    };
    std::vector<Frame> stack;
    Cursor cur(text);

    // The value about to be read: its path, whether to record it, and where its key started.
    std::string path;
    bool record = true;
    TextPosition keyPos;
    bool expectValue = true;

    auto childPath = [&](const Frame& parent, const std::string& key, bool isIndex) {
        record = parent.recorded && static_cast<int>(stack.size()) <= kMaxRecordedDepth;
        if (!record) {
            path.clear();
        } else if (isIndex) {
            path = parent.path + "[" + key + "]";
        } else {
            path = parent.path.empty() ? key : parent.path + "." + key;
        }
        if (record && focus && !leadsTo(path, *focus)) {
            record = false;
            path.clear();
        }
    };
    // Reads `"key":` and prepares the member's value; false on malformed text.
    auto readKey = [&]() {
        cur.skipSpace();
        keyPos = cur.position();
        std::string key;
        if (!readString(cur, &key)) return false;
        cur.skipSpace();
        if (cur.peek() != ':') return false;
        cur.advance();
        childPath(stack.back(), key, false);
        return true;
    };

    keyPos = {};
    for (;;) {
        if (expectValue) {
            cur.skipSpace();
            if (cur.atEnd()) return map;
            const TextPosition valuePos = cur.position();
            if (record) map.entries_[path] = {valuePos, keyPos.line > 0 ? keyPos : valuePos};
            keyPos = {};
            const char c = cur.peek();
            if (c == '{' || c == '[') {
                cur.advance();
                stack.push_back({c == '[', record, path, 0});
                cur.skipSpace();
                if (cur.peek() == (c == '[' ? ']' : '}')) {
                    cur.advance();
                    stack.pop_back();
                    expectValue = false;
                } else if (c == '[') {
                    childPath(stack.back(), "0", true);
                } else if (!readKey()) {
                    return map;
                }
                continue;
            }
            if (c == '"') {
                if (!readString(cur, nullptr)) return map;
            } else {
                skipScalar(cur);
            }
            expectValue = false;
        }
        // After a value: a separator or the end of its container.
        if (stack.empty()) return map;
        cur.skipSpace();
        Frame& top = stack.back();
        const char c = cur.peek();
        if (c == ',') {
            cur.advance();
            if (top.isArray) {
                childPath(top, std::to_string(++top.index), true);
            } else if (!readKey()) {
                return map;
            }
            expectValue = true;
        } else if (c == (top.isArray ? ']' : '}')) {
            cur.advance();
            stack.pop_back();
        } else {
            return map;  // malformed
        }
    }
}

const JsonSourceMap::Entry* JsonSourceMap::findNearest(const std::string& fieldPath) const {
    std::string path = fieldPath;
    for (;;) {
        const auto it = entries_.find(path);
        if (it != entries_.end()) return &it->second;
        if (path.empty()) return nullptr;
        // Drop the last component: "[n]" or ".key" (or the first key).
        const std::size_t cut = path.find_last_of(".[");
        path.resize(cut == std::string::npos ? 0 : cut);
    }
}

SourceLocation JsonSourceMap::locate(const std::string& fieldPath) const {
    SourceLocation where;
    where.field = fieldPath;
    if (const Entry* entry = findNearest(fieldPath)) {
        where.line = entry->value.line;
        where.column = entry->value.column;
    }
    return where;
}

SourceLocation JsonSourceMap::locateKey(const std::string& fieldPath) const {
    SourceLocation where;
    where.field = fieldPath;
    if (const Entry* entry = findNearest(fieldPath)) {
        where.line = entry->key.line;
        where.column = entry->key.column;
    }
    return where;
}

}  // namespace luxel
