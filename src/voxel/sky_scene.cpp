// The scene-file "sky": a named analytic sky model, each a gradient for ShadeOptions.
#include "voxel/sky_scene.h"

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
    checkObject(sky, "sky", {"model", "top", "horizon", "zenith"});
    std::string model = "gradient";
    if (const Json* v = find(sky, "model")) model = readString(*v, "sky.model");
    if (model == "gradient") {
        if (find(sky, "zenith")) {
            fail("sky.zenith",
                 "only the \"cie-overcast\" model takes a zenith radiance (the "
                 "gradient model takes \"top\" and \"horizon\")",
                 true);
        }
        if (const Json* v = find(sky, "top")) options.skyTop = readRadiance(*v, "sky.top");
        if (const Json* v = find(sky, "horizon")) {
            options.skyHorizon = readRadiance(*v, "sky.horizon");
        }
    } else if (model == "cie-overcast") {
        for (const char* key : {"top", "horizon"}) {
            if (find(sky, key)) {
                fail(member("sky", key),
                     "the \"cie-overcast\" model takes \"zenith\" alone (its horizon is zenith "
                     "/ 3), not \"top\" or \"horizon\"",
                     true);
            }
        }
        const SkyGradient g =
            cieOvercastSky(readRadiance(require(sky, "sky", "zenith"), "sky.zenith"));
        options.skyTop = g.top;
        options.skyHorizon = g.horizon;
    } else {
        fail("sky.model", "unknown sky model '" + model + "' (known: gradient, cie-overcast)");
    }
}

}  // namespace luxel::voxel
