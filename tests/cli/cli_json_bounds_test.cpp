// `luxel info` refuses pathological JSON with exit code 1 and one line.
#include <gtest/gtest.h>

#include <string>

#include "support/cli_fixture.h"

namespace {

class CliJsonBounds : public luxel::test::CliFixture {};

TEST_F(CliJsonBounds, DeeplyNestedSceneIsOneLineError) {
    const int n = 90000;
    const std::string scene =
        write("deep.json", "{\"canvas\": " + std::string(n, '[') + std::string(n, ']') + "}");
    expectError("info " + scene, "deep.json:1:267: invalid JSON: nesting deeper than 256 levels");
}

TEST_F(CliJsonBounds, DuplicateKeyIsOneLineError) {
    const std::string scene = write("dup.json", "{\"canvas\": [8, 8],\n \"canvas\": [4, 4]}");
    expectError("info " + scene, "dup.json:2:2: invalid JSON: duplicate key 'canvas'");
}

}  // namespace
