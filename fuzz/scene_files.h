// Shared by the scene fuzz targets: fuzzed scenes may name files (textures, image layers, .vox
// worlds). They are resolved against one fixed folder of small shipped files
// (LUXEL_FUZZ_FILES_DIR, scenes/voxel: textures/*.png and sample.vox), and a document that names
// an absolute path or climbs out with ".." is skipped before the reader sees it, so a run never
// reads arbitrary files of the machine (a large file, /proc, a device) and stays fast.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/json_fields.h"

#ifndef LUXEL_FUZZ_FILES_DIR
#error "LUXEL_FUZZ_FILES_DIR must name the folder fuzzed scenes resolve their files in"
#endif

namespace luxel::fuzz {

// Where a fuzzed scene "lives": relative file names resolve in LUXEL_FUZZ_FILES_DIR.
inline std::string scenePath(const char* fileName) {
    return std::string(LUXEL_FUZZ_FILES_DIR) + "/" + fileName;
}

// Whether every string value of the document stays inside the files folder: no
// absolute path, no "..". Walked with an explicit stack, since the document may be deeply nested.
inline bool namesOnlyLocalFiles(const json::Json& root) {
    std::vector<const json::Json*> pending{&root};
    const auto local = [](std::string_view s) {
        return s.find("..") == std::string_view::npos && (s.empty() || s.front() != '/');
    };
    while (!pending.empty()) {
        const json::Json* v = pending.back();
        pending.pop_back();
        if (v->is_string()) {
            if (!local(v->get_ref<const std::string&>())) return false;
        } else if (v->is_object()) {
            for (const json::Json& member : *v) pending.push_back(&member);
        } else if (v->is_array()) {
            for (const json::Json& e : *v) pending.push_back(&e);
        }
    }
    return true;
}

}  // namespace luxel::fuzz
