#include "voxel/vox_materials.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "luxel/core/tonemap.h"
#include "luxel/voxel/texture_set.h"

namespace luxel::voxel::vox {
namespace {

Rgb linearOf(Voxel c) {
    return {srgbToLinear(c.r / 255.0f), srgbToLinear(c.g / 255.0f), srgbToLinear(c.b / 255.0f)};
}

// A MATL number in [lo, hi] (absent or unreadable: `fallback`).
float number(const Dict& d, const char* key, float fallback, float lo, float hi) {
    const std::string* text = lookup(d, key);
    double v = 0;
    if (!text || !parseNumber(*text, v)) return fallback;
    return static_cast<float>(std::clamp(v, static_cast<double>(lo), static_cast<double>(hi)));
}

bool has(const Dict& d, const char* key) {
    return lookup(d, key) != nullptr;
}

bool sameMaterial(const Material& a, const Material& b) {
    const auto rgb = [](Rgb x, Rgb y) { return x.r == y.r && x.g == y.g && x.b == y.b; };
    return rgb(a.albedo, b.albedo) && a.metallic == b.metallic && a.roughness == b.roughness &&
           a.ior == b.ior && a.transmission == b.transmission && rgb(a.absorption, b.absorption) &&
           rgb(a.emission, b.emission);
}

// MagicaVoxel writes `_ior` as the index of refraction minus one and `_ri` as the index itself.
float iorOf(const Dict& d) {
    if (has(d, "_ri")) return number(d, "_ri", 1.5f, 1.0f, 4.0f);
    if (has(d, "_ior")) return std::clamp(number(d, "_ior", 0.5f, 0.0f, 3.0f) + 1.0f, 1.0f, 4.0f);
    return 1.5f;
}

// Glass colour tints by absorption (material.h: the surface colour does not tint transmitted
// light): -ln(colour) per voxel, scaled by _att (at least 0.25 so thin coloured glass shows).
Rgb absorptionOf(const Dict& d, Voxel colour) {
    const float att = std::max(number(d, "_att", 0.0f, 0.0f, 100.0f), 0.25f);
    const Rgb c = linearOf(colour);
    const auto a = [&](float x) { return std::min(-std::log(std::max(x, 0.02f)) * att, 1000.0f); };
    return {a(c.r), a(c.g), a(c.b)};
}

// The material of one MATL dict, or nothing for a plain diffuse block.
std::optional<Material> materialOf(const Dict& d, Voxel colour, int id, FeatureWarnings& w) {
    const std::string* typeText = lookup(d, "_type");
    const std::string type = typeText ? *typeText : "_diffuse";
    const float weight = number(d, "_weight", 1.0f, 0.0f, 1.0f);
    Material m = defaultMaterial();
    const auto ignored = [&](const char* key, const char* what) {
        if (has(d, key) && number(d, key, 0, 0, 1e9) != 0.0f) {
            w.add("MATL", std::string(key) + " (" + what + ") has no luxel equivalent; ignored",
                  id);
        }
    };
    if (type == "_diffuse") return std::nullopt;
    if (type == "_metal") {
        m.metallic = has(d, "_metal") ? number(d, "_metal", 1, 0, 1) : weight;
        m.roughness = number(d, "_rough", 0.1f, 0.0f, 1.0f);
        ignored("_spec", "specular");
        ignored("_plastic", "plastic");
    } else if (type == "_glass") {
        m.transmission = has(d, "_trans")   ? number(d, "_trans", 1, 0, 1)
                         : has(d, "_alpha") ? number(d, "_alpha", 1, 0, 1)
                                            : weight;
        m.roughness = number(d, "_rough", 0.0f, 0.0f, 1.0f);
        m.ior = iorOf(d);
        m.absorption = absorptionOf(d, colour);
    } else if (type == "_emit") {
        const float emit = has(d, "_emit") ? number(d, "_emit", 1, 0, 1e3) : weight;
        const float flux = number(d, "_flux", 0.0f, 0.0f, 8.0f);
        const float ldr = number(d, "_ldr", 0.0f, 0.0f, 1.0f);
        const Rgb c = linearOf(colour);
        const float k = std::min(kEmitScale * emit * std::exp2(flux), 1e4f);
        m.emission = {c.r * k + c.r * ldr, c.g * k + c.g * ldr, c.b * k + c.b * ldr};
    } else if (type == "_blend") {
        m.metallic = number(d, "_metal", 0, 0, 1);
        m.transmission =
            has(d, "_trans") ? number(d, "_trans", 0, 0, 1) : number(d, "_alpha", 0, 0, 1);
        m.roughness = number(d, "_rough", 0.1f, 0.0f, 1.0f);
        m.ior = iorOf(d);
        w.add("MATL", "_blend approximated as one surface with its metal and glass shares", id);
        if (m.metallic == 0 && m.transmission == 0) return std::nullopt;
    } else if (type == "_media") {
        const std::string* kind = lookup(d, "_media_type");
        w.add("MATL", "_media" + (kind ? " " + *kind : std::string()) + " approximated as diffuse",
              id);
        return std::nullopt;
    } else {
        w.add("MATL", "unknown _type '" + type + "' approximated as diffuse", id);
        return std::nullopt;
    }
    if (has(d, "_d") && type != "_glass") ignored("_d", "media density");
    return m;
}

std::string joinIds(const std::vector<int>& ids) {
    std::string s;
    const std::size_t shown = std::min<std::size_t>(ids.size(), 8);
    for (std::size_t i = 0; i < shown; ++i) {
        if (i > 0) s += i + 1 == ids.size() ? " and " : ", ";
        s += std::to_string(ids[i]);
    }
    if (shown < ids.size()) s += " and " + std::to_string(ids.size() - shown) + " more";
    return s;
}

std::string fmt(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", static_cast<double>(v));
    return buf;
}

}  // namespace

void FeatureWarnings::add(const std::string& what, const std::string& message, int id) {
    const auto key = std::make_pair(what, message);
    auto [it, fresh] = ids_.try_emplace(key);
    if (fresh) order_.push_back(key);
    if (std::find(it->second.begin(), it->second.end(), id) == it->second.end()) {
        it->second.push_back(id);
    }
}

void FeatureWarnings::lines(std::vector<std::string>& out) const {
    for (const auto& key : order_) {
        const std::vector<int>& ids = ids_.at(key);
        // A negative id: a remark about the whole palette, without ids.
        const bool whole = ids.size() == 1 && ids.front() < 0;
        std::string line = key.first;
        if (!whole) line.append(" ").append(joinIds(ids));
        out.push_back(line.append(": ").append(key.second));
    }
}

PaletteMapping mapPalette(const std::array<Voxel, 256>& palette, const std::map<int, Dict>& matl,
                          const std::array<std::uint64_t, 256>& used, FeatureWarnings& warnings) {
    PaletteMapping out;
    out.slot.fill(PaletteMapping::kPlain);
    // Files whose palette alpha is 0 everywhere it is used were written without alpha: opaque.
    bool anyAlpha = false;
    for (int i = 1; i < 256; ++i) anyAlpha |= used[i] && palette[i].a != 0;
    std::vector<std::uint64_t> uses;
    for (int i = 1; i < 256; ++i) {
        if (!used[i]) continue;
        const auto found = matl.find(i);
        std::optional<Material> m;
        if (found != matl.end()) m = materialOf(found->second, palette[i], i, warnings);
        const std::uint8_t alpha = palette[i].a;
        if (anyAlpha && alpha == 0) {
            warnings.add("palette index", "alpha 0: its voxels are left out (invisible)", i);
            out.slot[i] = PaletteMapping::kSkip;
            continue;
        }
        if (anyAlpha && alpha < 255) {
            // Palette alpha is opacity: the rest of the light passes through, unbent (ior 1)
            // unless a glass MATL gives its own index.
            if (!m) {
                m = defaultMaterial();
                m->ior = 1.0f;
            }
            m->transmission = std::max(m->transmission, 1.0f - alpha / 255.0f);
        }
        if (!m) continue;
        int slot = -1;
        for (std::size_t k = 0; k < out.materials.size(); ++k) {
            if (sameMaterial(out.materials[k], *m)) slot = static_cast<int>(k);
        }
        if (slot < 0) {
            m->name = "vox " + std::to_string(i);
            slot = static_cast<int>(out.materials.size());
            out.materials.push_back(*m);
            uses.push_back(0);
        }
        uses[slot] += used[i];
        out.slot[i] = slot;
    }
    if (!anyAlpha) {
        for (int i = 1; i < 256; ++i) {
            if (used[i]) {
                warnings.add("palette", "alpha is 0 for every colour used; read as opaque", -1);
                break;
            }
        }
    }
    if (out.materials.size() > static_cast<std::size_t>(kMaxTextures)) {
        // Keep the most used materials; the rest become plain blocks.
        std::vector<int> order(out.materials.size());
        for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
        std::stable_sort(order.begin(), order.end(),
                         [&](int a, int b) { return uses[a] > uses[b]; });
        std::vector<int> remap(order.size(), PaletteMapping::kPlain);
        std::vector<Material> kept;
        for (int k : order) {
            if (kept.size() == static_cast<std::size_t>(kMaxTextures)) break;
            remap[k] = static_cast<int>(kept.size());
            kept.push_back(out.materials[k]);
        }
        for (int i = 1; i < 256; ++i) {
            if (out.slot[i] < 0) continue;
            if (remap[out.slot[i]] < 0) {
                warnings.add("MATL",
                             "beyond luxel's " + std::to_string(kMaxTextures) +
                                 " material slots; drawn as a plain block",
                             i);
            }
            out.slot[i] = remap[out.slot[i]];
        }
        out.materials = std::move(kept);
    }
    return out;
}

Dict matlFor(const Material& m, Voxel colour) {
    Dict d;
    const Rgb c = linearOf(colour);
    const float maxEmission = std::max({m.emission.r, m.emission.g, m.emission.b});
    const float maxColour = std::max({c.r, c.g, c.b});
    if (maxEmission > 0 && maxColour > 0) {
        // emission = colour x kEmitScale x _emit x 2^_flux: _emit in (0, 1], _flux a whole
        // number when possible.
        float k = maxEmission / maxColour / kEmitScale;
        int flux = 0;
        while (k > 1.0f && flux < 8) {
            k /= 2.0f;
            ++flux;
        }
        d = {{"_type", "_emit"}, {"_emit", fmt(k)}, {"_flux", std::to_string(flux)}};
    } else if (m.transmission > 0) {
        d = {{"_type", "_glass"},
             {"_trans", fmt(m.transmission)},
             {"_rough", fmt(m.roughness)},
             {"_ri", fmt(m.ior)},
             {"_ior", fmt(m.ior - 1.0f)}};
        const float att = std::max({m.absorption.r, m.absorption.g, m.absorption.b});
        if (att > 0) d.emplace_back("_att", fmt(0.25f));
    } else if (m.metallic > 0) {
        d = {{"_type", "_metal"}, {"_metal", fmt(m.metallic)}, {"_rough", fmt(m.roughness)}};
    } else {
        d = {{"_type", "_diffuse"}, {"_rough", fmt(m.roughness)}};
    }
    return d;
}

}  // namespace luxel::voxel::vox
