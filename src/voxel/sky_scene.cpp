// The scene-file "sky": a named analytic sky model, a gradient or the Preetham clear sky.
#include "voxel/sky_scene.h"

#include <initializer_list>
#include <string>

#include "luxel/voxel/sky_model.h"

namespace luxel::voxel {

using namespace json;

namespace {

Rgb readRadiance(const Json& v, const std::string& path) {
    const auto c = readNumbers(v, path, 3, 0, 1e4);
    return {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
}

}  // namespace

void readSkyJson(const Json& sky, ShadeOptions& options) {
    checkObject(sky, "sky", {"model", "top", "horizon", "zenith", "turbidity"});
    std::string model = "gradient";
    if (const Json* v = find(sky, "model")) model = readString(*v, "sky.model");
    // Fields a model does not take are errors, not silently ignored.
    const auto refuse = [&](std::initializer_list<const char*> keys, const std::string& why) {
        for (const char* key : keys) {
            if (find(sky, key)) fail(member("sky", key), why, true);
        }
    };
    if (model == "gradient") {
        refuse({"zenith"},
               "only the \"cie-overcast\" and \"preetham\" models take a zenith radiance (the "
               "gradient model takes \"top\" and \"horizon\")");
        refuse({"turbidity"}, "only the \"preetham\" model takes a turbidity");
        options.skyModel = ShadeOptions::SkyModel::Gradient;
        if (const Json* v = find(sky, "top")) options.skyTop = readRadiance(*v, "sky.top");
        if (const Json* v = find(sky, "horizon")) {
            options.skyHorizon = readRadiance(*v, "sky.horizon");
        }
    } else if (model == "cie-overcast") {
        refuse({"top", "horizon"},
               "the \"cie-overcast\" model takes \"zenith\" alone (its horizon is zenith "
               "/ 3), not \"top\" or \"horizon\"");
        refuse({"turbidity"}, "only the \"preetham\" model takes a turbidity");
        const SkyGradient g =
            cieOvercastSky(readRadiance(require(sky, "sky", "zenith"), "sky.zenith"));
        options.skyModel = ShadeOptions::SkyModel::Gradient;
        options.skyTop = g.top;
        options.skyHorizon = g.horizon;
    } else if (model == "preetham") {
        refuse({"top", "horizon"},
               "the \"preetham\" model takes \"turbidity\" and \"zenith\" (its colours "
               "come from the sun and the turbidity), not \"top\" or \"horizon\"");
        options.skyModel = ShadeOptions::SkyModel::Preetham;
        if (const Json* v = find(sky, "turbidity")) {
            options.skyTurbidity = static_cast<float>(
                readNumberIn(*v, "sky.turbidity", kPreethamMinTurbidity, kPreethamMaxTurbidity));
        }
        if (const Json* v = find(sky, "zenith")) {
            if (!v->is_number()) {
                fail("sky.zenith",
                     "the \"preetham\" model takes the zenith's luminance as one number (its "
                     "colour comes from the model)",
                     true);
            }
            options.skyZenithLuminance = static_cast<float>(readNumberIn(*v, "sky.zenith", 0, 1e4));
        }
    } else {
        fail("sky.model",
             "unknown sky model '" + model + "' (known: gradient, cie-overcast, preetham)");
    }
}

}  // namespace luxel::voxel
