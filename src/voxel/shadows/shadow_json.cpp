// Scene-file fields for sun shadows.
#include "voxel/shadows/shadow_json.h"

#include <numbers>
#include <string>

namespace luxel::voxel {
namespace {

using namespace json;

std::string choice(const Json& v, const std::string& path, std::initializer_list<const char*> ok) {
    std::string list;
    for (const char* o : ok) {
        if (v.is_string() && v.get<std::string>() == o) return o;
        list += std::string(list.empty() ? "" : ", ") + "\"" + o + "\"";
    }
    fail(path, "must be one of " + list + ", got " + describe(v));
}

void readSettings(const Json& s, ShadowSettings& out) {
    checkObject(
        s, "render.shadows",
        {"method", "samples", "map_size", "storage", "filter", "filter_radius", "moment_bias",
         "light_bleed", "depth_bias", "normal_offset", "sdf_steps", "sdf_normal_offset",
         "sdf_distance", "blend_near", "blend_far", "split", "combine", "msm_filter"});
    if (const Json* v = find(s, "method")) {
        const std::string m = choice(*v, "render.shadows.method",
                                     {"hard", "exact", "msm", "vsm", "sdf", "blend", "flood"});
        parseShadowMethod(m, out.method);
    }
    auto whole = [&](const char* key, int& field, int lo, int hi) {
        if (const Json* v = find(s, key)) {
            field = static_cast<int>(readWholeNumber(*v, member("render.shadows", key), lo, hi));
        }
    };
    auto number = [&](const char* key, double& field, double lo, double hi) {
        if (const Json* v = find(s, key)) {
            field = readNumberIn(*v, member("render.shadows", key), lo, hi);
        }
    };
    whole("samples", out.exactSamples, 1, 65536);
    whole("map_size", out.mapSize, 16, 8192);
    whole("sdf_steps", out.sdfMaxSteps, 1, 4096);
    if (const Json* v = find(s, "storage")) {
        out.momentStorage = choice(*v, "render.shadows.storage", {"fp32", "16bit"}) == "fp32"
                                ? ShadowSettings::MomentStorage::Float32
                                : ShadowSettings::MomentStorage::Quantized16;
    }
    if (const Json* v = find(s, "filter")) {
        out.momentFilter = choice(*v, "render.shadows.filter", {"gaussian", "box"}) == "box"
                               ? ShadowSettings::MomentFilter::Box
                               : ShadowSettings::MomentFilter::Gaussian;
    }
    if (const Json* v = find(s, "msm_filter")) {
        out.msmFilter = choice(*v, "render.shadows.msm_filter", {"fixed", "penumbra"}) == "fixed"
                            ? ShadowSettings::MsmFilter::Fixed
                            : ShadowSettings::MsmFilter::PenumbraSized;
    }
    number("filter_radius", out.filterRadius, 0, 64);
    number("moment_bias", out.momentBias, 0, 0.1);
    number("light_bleed", out.lightBleedReduction, 0, 0.99);
    number("depth_bias", out.depthBias, 0, 16);
    number("normal_offset", out.normalOffset, 0, 2);
    number("sdf_normal_offset", out.sdfNormalOffset, 0, 2);
    number("blend_near", out.blendNear, 0, 1e6);
    number("blend_far", out.blendFar, 0, 1e6);
    if (out.blendFar < out.blendNear) {
        fail(find(s, "blend_far") ? "render.shadows.blend_far" : "render.shadows.blend_near",
             "blend_far must not be less than blend_near");
    }
    if (const Json* v = find(s, "sdf_distance")) {
        out.sdfDistance = choice(*v, "render.shadows.sdf_distance", {"cubes", "centres"}) == "cubes"
                              ? ShadowSettings::SdfDistance::Cubes
                              : ShadowSettings::SdfDistance::Centres;
    }
    if (const Json* v = find(s, "split")) {
        out.sdfNear = choice(*v, "render.shadows.split", {"sdf-near", "msm-near"}) == "sdf-near";
    }
    if (const Json* v = find(s, "combine")) {
        out.minInBand = choice(*v, "render.shadows.combine", {"lerp", "min"}) == "min";
    }
}

}  // namespace

void readShadowJson(const Json& render, ShadeOptions& options) {
    if (const Json* v = find(render, "shadows")) {
        if (v->is_boolean()) {
            options.shadows = v->get<bool>();
        } else if (v->is_object()) {
            options.shadows = true;
            readSettings(*v, options.shadowSettings);
        } else {
            fail("render.shadows", "must be true, false or an object, got " + describe(*v));
        }
    }
    if (const Json* v = find(render, "sun_radius")) {
        options.sunAngularRadius =
            readNumberIn(*v, "render.sun_radius", 0, 20) * std::numbers::pi / 180.0;
    }
}

}  // namespace luxel::voxel
