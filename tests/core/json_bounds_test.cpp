// Pathological JSON is refused with one short located line: deep nesting, duplicate keys, huge
// tokens. Runs in-process, so a stack overflow would fail the whole suite.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "core/json_fields.h"
#include "luxel/gi2d/scene2d_json.h"

namespace luxel::json {
namespace {

std::string parseError(const std::string& text) {
    auto root = parse(text, "t.json");
    EXPECT_FALSE(root.ok());
    return root.ok() ? "" : root.error().message();
}

std::string repeat(const std::string& s, int n) {
    std::string out;
    out.reserve(s.size() * static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) out += s;
    return out;
}

TEST(JsonBounds, DeepArraysAreRefusedAtTheBracketBeyondTheLimit) {
    const int n = 100000;
    const std::string text = "{\"canvas\": " + std::string(n, '[') + std::string(n, ']') + "}";
    // The root object is level 1, so the 256th '[' (offset 11 + 255) opens level 257.
    EXPECT_EQ(parseError(text),
              "t.json:1:267: invalid JSON: nesting deeper than 256 levels (the nesting depth "
              "limit)");
    // Unclosed nesting (a truncated file) is refused the same way.
    EXPECT_EQ(parseError("{\"canvas\": " + std::string(n, '[')),
              "t.json:1:267: invalid JSON: nesting deeper than 256 levels (the nesting depth "
              "limit)");
}

TEST(JsonBounds, NestingUpToTheLimitIsAccepted) {
    const int inner = kMaxNestingDepth - 1;  // plus the root object
    const std::string ok = "{\"a\": " + std::string(inner, '[') + std::string(inner, ']') + "}";
    EXPECT_TRUE(parse(ok, "t.json").ok());
    const std::string deep =
        "{\"a\": " + std::string(inner + 1, '[') + std::string(inner + 1, ']') + "}";
    EXPECT_FALSE(parse(deep, "t.json").ok());
}

TEST(JsonBounds, DeepObjectsAreRefusedByTheSceneReadersWithoutCrashing) {
    const int n = 100000;
    const std::string text = "{\"canvas\": [8, 8],\n\"shapes\": " + repeat("{\"a\": ", n) + "1" +
                             std::string(n, '}') + "}";
    auto scene = gi2d::parseScene2D(text, "deep.json", ".");
    ASSERT_FALSE(scene.ok());
    // Level 257 is the 256th nested object, at column 11 + 6 * 255 of line 2.
    EXPECT_EQ(scene.error().message(),
              "deep.json:2:1541: invalid JSON: nesting deeper than 256 levels (the nesting depth "
              "limit)");
}

TEST(JsonBounds, DuplicateKeysAreRefusedAtTheRepeatedKey) {
    EXPECT_EQ(parseError("{\"canvas\": [8, 8],\n  \"canvas\": [9, 9]}"),
              "t.json:2:3: invalid JSON: duplicate key 'canvas' (keys must be unique within an "
              "object)");
    // Escapes are compared after decoding, as the parser sees the keys.
    EXPECT_EQ(parseError("{\"a\": {\"b\": 1, \"\\u0062\": 2}}"),
              "t.json:1:16: invalid JSON: duplicate key 'b' (keys must be unique within an "
              "object)");
    // The same key in sibling objects, or as a string value, is fine.
    EXPECT_TRUE(
        parse(R"({"a": {"x": 1}, "b": {"x": 2}, "c": [{"x": 1}, {"x": 2}], "d": "a"})", "t.json")
            .ok());
}

TEST(JsonBounds, DuplicateKeysInAShippedFormatAreRefusedByTheSceneReader) {
    auto scene =
        gi2d::parseScene2D(R"({"canvas": [8, 8], "shapes": [], "shapes": []})", "dup.json", ".");
    ASSERT_FALSE(scene.ok());
    EXPECT_EQ(scene.error().message(),
              "dup.json:1:34: invalid JSON: duplicate key 'shapes' (keys must be unique within an "
              "object)");
}

TEST(JsonBounds, HugeBadTokensGiveOneShortLine) {
    const std::string digits(719000, '1');
    // An unterminated string, a malformed number and one too large for a double: each message
    // would otherwise quote the whole token.
    for (const std::string& text : {"{\"canvas\": \"" + digits, "{\"canvas\": " + digits + "e}",
                                    "{\"canvas\": " + digits + "}"}) {
        const std::string message = parseError(text);
        EXPECT_EQ(message.rfind("t.json:1:", 0), 0u) << message.substr(0, 300);
        EXPECT_NE(message.find("invalid JSON: "), std::string::npos) << message.substr(0, 300);
        EXPECT_LE(message.size(), kMaxMessageBytes + 3);
        EXPECT_NE(message.find(std::string(kMaxQuotedBytes - 1, '1') + "..."), std::string::npos)
            << message.substr(0, 300);
        EXPECT_EQ(message.find('\n'), std::string::npos);
    }
}

TEST(JsonBounds, InputQuotedByTheSceneReadersIsClipped) {
    const std::string key(500000, 'k');
    auto scene = gi2d::parseScene2D("{\"canvas\": [8, 8], \"" + key + "\": 1}", "k.json", ".");
    ASSERT_FALSE(scene.ok());
    const std::string& message = scene.error().message();
    EXPECT_LE(message.size(), kMaxMessageBytes + 3);
    EXPECT_EQ(message.rfind("k.json:1:20: ", 0), 0u) << message.substr(0, 300);
    EXPECT_NE(message.find("unknown field '" + std::string(kMaxQuotedBytes, 'k') + "...'"),
              std::string::npos)
        << message;

    auto shape = gi2d::parseScene2D(
        "{\"canvas\": [8, 8], \"shapes\": [{\"type\": \"" + key + "\"}]}", "s.json", ".");
    ASSERT_FALSE(shape.ok());
    EXPECT_LE(shape.error().message().size(), kMaxMessageBytes + 3);
    EXPECT_NE(shape.error().message().find("(known: "), std::string::npos)
        << shape.error().message();
}

double secondsToParse2D(const std::string& text) {
    const auto start = std::chrono::steady_clock::now();
    auto scene = gi2d::parseScene2D(text, "big.json", ".");
    EXPECT_FALSE(scene.ok());
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(JsonBounds, MoreValuesThanTheLimitAreRefusedBeforeADocumentIsBuilt) {
    const std::string text = "{\"canvas\": [8, 8], \"x\": [" + repeat("0,", kMaxJsonValues) + "0]}";
    const std::string message = parseError(text);
    EXPECT_EQ(message.rfind("t.json: invalid JSON: more than ", 0), 0u) << message;
    EXPECT_NE(message.find(" values (the limit for one file"), std::string::npos) << message;
}

// nlohmann's callback parser erases discarded values by scanning the parent array at every
// closing brace: quadratic on an array of objects (a 2 MB file took 85 s). Both passes of parse()
// are linear, so 400,000 objects take well under a second; the bound leaves room for slow runners.
TEST(JsonBounds, ArraysOfManyObjectsParseInLinearTime) {
    const std::string text = "{\"canvas\": [8, 8], \"shapes\": [" + repeat("{},", 400000) + "{}]}";
    EXPECT_LT(secondsToParse2D(text), 10.0);
}

// Locating an error records only the path to the failing field, not every value of the file (a
// 63 MiB file of numbers used to cost 3.4 GiB and a minute before its one-line refusal).
TEST(JsonBounds, LocatingAnErrorInAFileOfMillionsOfValuesIsFast) {
    const std::string text = "{\"canvas\": [8, 8],\n \"shapes\": [" +
                             repeat("{\"a\": [1, 2]},", 1000000) + "{}],\n \"x\": 1}";
    const auto start = std::chrono::steady_clock::now();
    auto scene = gi2d::parseScene2D(text, "big.json", ".");
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_FALSE(scene.ok());
    EXPECT_EQ(scene.error().message().rfind("big.json:3:2: x: unknown field 'x'", 0), 0u)
        << scene.error().message();
    EXPECT_LT(seconds, 20.0);
}

TEST(JsonBounds, ClipKeepsWholeUtf8CodePoints) {
    EXPECT_EQ(clip("abc", 3), "abc");
    EXPECT_EQ(clip("abcd", 3), "abc...");
    EXPECT_EQ(clip("a\xC3\xA9z", 2), "a...");  // never half of the two-byte 'é'
    EXPECT_EQ(boundMessage("bad '" + std::string(300, 'q') + "' here"),
              "bad '" + std::string(kMaxQuotedBytes, 'q') + "...' here");
}

}  // namespace
}  // namespace luxel::json
