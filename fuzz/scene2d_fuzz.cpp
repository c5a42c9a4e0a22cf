// libFuzzer target for 2D scene files (luxel::gi2d::parseScene2D): any bytes must give a scene or
// an Error, never a crash or a sanitizer report. A scene that parses must survive its own writer:
// sceneToJson's text parses again and writes back to the same text.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "luxel/gi2d/scene2d_json.h"
#include "scene_files.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace luxel;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    // Image layers resolve in the fixed files folder; documents naming other places are skipped.
    if (const Result<json::Json> root = json::parse(text, "fuzz.json");
        root && !fuzz::namesOnlyLocalFiles(*root)) {
        return 0;
    }
    const std::string baseDir = LUXEL_FUZZ_FILES_DIR;
    const Result<gi2d::Scene2D> scene = gi2d::parseScene2D(text, "fuzz.json", baseDir);
    if (!scene) {
        if (scene.error().message().empty()) __builtin_trap();  // an error says what is wrong
        return 0;
    }
    const std::string written = gi2d::sceneToJson(*scene);
    const Result<gi2d::Scene2D> again = gi2d::parseScene2D(written, "written.json", baseDir);
    if (!again) __builtin_trap();
    if (gi2d::sceneToJson(*again) != written) __builtin_trap();
    return 0;
}
