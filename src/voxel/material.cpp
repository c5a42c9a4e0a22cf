// Materials: defaults, validation, and the table indexed by texture slot (material.h).
#include "luxel/voxel/material.h"

#include <cmath>
#include <sstream>

#include "luxel/voxel/texture_set.h"

namespace luxel::voxel {
namespace {

std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

Status inRange(const char* field, float v, double lo, double hi) {
    if (!std::isfinite(v) || v < lo || v > hi) {
        return Error(std::string(field) + " must be in " + number(lo) + ".." + number(hi) +
                     ", got " + number(v));
    }
    return Ok{};
}

Status rgbInRange(const char* field, Rgb c, double lo, double hi) {
    for (int i = 0; i < 3; ++i) {
        if (Status s = inRange(field, c[i], lo, hi); !s) return s;
    }
    return Ok{};
}

}  // namespace

Material defaultMaterial() {
    Material m;
    m.name = "default";
    m.proceduralTexture = true;
    return m;
}

std::string materialSlotName(const std::string& materialName) {
    return "material:" + materialName;
}

Status validateMaterial(const Material& m) {
    for (Status s : {rgbInRange("albedo", m.albedo, 0, 1), inRange("metallic", m.metallic, 0, 1),
                     inRange("roughness", m.roughness, 0, 1), inRange("ior", m.ior, 1, 4),
                     inRange("transmission", m.transmission, 0, 1),
                     rgbInRange("absorption", m.absorption, 0, 1e3),
                     rgbInRange("emission", m.emission, 0, 1e4)}) {
        if (!s) return Error("material '" + m.name + "': " + s.error().message());
    }
    return Ok{};
}

MaterialTable::MaterialTable() : plain_(defaultMaterial()) {
    updateFlags();
}

Status MaterialTable::setPlain(Material material) {
    if (Status s = validateMaterial(material); !s) return s;
    plain_ = std::move(material);
    updateFlags();
    return Ok{};
}

Status MaterialTable::setSlot(int slot, Material material) {
    if (slot < 0 || slot >= kMaxTextures) {
        return Error("material slot " + std::to_string(slot) + " is outside 0.." +
                     std::to_string(kMaxTextures - 1));
    }
    if (Status s = validateMaterial(material); !s) return s;
    if (slot >= slotCount()) {
        slots_.resize(slot + 1);
        set_.resize(slot + 1, false);
    }
    slots_[slot] = std::move(material);
    set_[slot] = true;
    updateFlags();
    return Ok{};
}

bool MaterialTable::hasSlot(int slot) const {
    return slot >= 0 && slot < slotCount() && set_[slot];
}

void MaterialTable::updateFlags() {
    const auto transmits = [](const Material& m) {
        return m.transmission > 0.0f && m.metallic < 1.0f;
    };
    emits_ = plain_.emission.maxComponent() > 0.0f;
    transmits_ = transmits(plain_);
    for (std::size_t i = 0; i < slots_.size(); ++i) {
        if (!set_[i]) continue;
        emits_ = emits_ || slots_[i].emission.maxComponent() > 0.0f;
        transmits_ = transmits_ || transmits(slots_[i]);
    }
}

const Material& MaterialTable::forSlot(int slot) const {
    return hasSlot(slot) ? slots_[slot] : plain_;
}

}  // namespace luxel::voxel
