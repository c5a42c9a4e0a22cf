// The shipped 2D scenes the benchmarks run, read through the one scene-file reader.
#pragma once

#include <stdexcept>
#include <string>

#include "luxel/scene/scene_file.h"

namespace luxel::bench {

// scenes/2d/<name>; throws (ending the benchmark with the message) when it cannot be read.
inline gi2d::Scene2D loadShipped2D(const std::string& name) {
    auto file = scene::loadSceneFile(std::string(LUXEL_SOURCE_DIR) + "/scenes/2d/" + name);
    if (!file) throw std::runtime_error(file.error().message());
    if (file->kind() != scene::SceneKind::TwoD) throw std::runtime_error(name + ": not a 2D scene");
    return std::move(file->twoD());
}

}  // namespace luxel::bench
