// Reads the "post" section of a scene file.
#include "post/post_json.h"

namespace luxel::post {

using namespace json;

PostOptions postOptionsFromJson(const Json& v, const std::string& path) {
    checkObject(v, path, {"bloom", "exposure", "tone", "internal_scale", "upscaler", "sharpness"});
    PostOptions o;
    if (const Json* b = find(v, "bloom")) {
        const std::string bp = member(path, "bloom");
        checkObject(*b, bp, {"strength", "levels", "karis"});
        if (const Json* s = find(*b, "strength")) {
            o.bloom.strength = static_cast<float>(readNumberIn(*s, member(bp, "strength"), 0, 1));
        }
        if (const Json* l = find(*b, "levels")) {
            o.bloom.levels = static_cast<int>(readWholeNumber(*l, member(bp, "levels"), 1, 16));
        }
        if (const Json* k = find(*b, "karis"))
            o.bloom.karisAverage = readBool(*k, member(bp, "karis"));
    }
    if (const Json* e = find(v, "exposure")) {
        o.tone.exposureStops =
            static_cast<float>(readNumberIn(*e, member(path, "exposure"), -32, 32));
    }
    if (const Json* t = find(v, "tone")) {
        const std::string name = readString(*t, member(path, "tone"));
        const auto curve = parseToneCurve(name);
        if (!curve)
            fail(member(path, "tone"),
                 "unknown tone curve '" + name + "' (known: clamp, reinhard, aces)");
        o.tone.curve = *curve;
    }
    if (const Json* s = find(v, "internal_scale")) {
        o.internalScale = static_cast<float>(
            readNumberIn(*s, member(path, "internal_scale"), kMinInternalScale, 1));
    }
    if (const Json* u = find(v, "upscaler")) {
        const std::string name = readString(*u, member(path, "upscaler"));
        const auto upscaler = parseUpscaler(name);
        if (!upscaler)
            fail(member(path, "upscaler"),
                 "unknown upscaler '" + name + "' (known: bilinear, edge)");
        o.upscaler = *upscaler;
    }
    if (const Json* s = find(v, "sharpness")) {
        o.sharpness = static_cast<float>(readNumberIn(*s, member(path, "sharpness"), 0, 1));
    }
    return o;
}

}  // namespace luxel::post
