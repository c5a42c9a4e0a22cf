// The face table of the voxel radiance cascades (surface_faces.h).
#include "surface_faces.h"

#include <bit>
#include <string>

#include "luxel/core/parallel.h"
#include "octahedral_bins.h"

namespace luxel::voxel::cascades {

namespace {

std::uint64_t mix(std::uint64_t x) {  // splitmix64's finaliser: spreads grid keys over the table
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

// Texture slots with at least one cutout texel: rays pass through such voxels, so faces behind
// them can be reached.
std::vector<bool> cutoutSlots(const TextureSet* textures) {
    std::vector<bool> cutout(256, false);
    if (!textures) return cutout;
    for (int slot = 0; slot < textures->size(); ++slot) {
        for (const Texel& t : (*textures)[slot].texels) {
            if (t.cutout()) {
                cutout[slot] = true;
                break;
            }
        }
    }
    return cutout;
}

}  // namespace

std::int64_t FaceTable::countExposed(const VoxelWorld& world) {
    const Int3 s = world.size();
    std::int64_t count = 0;
    for (int z = 0; z < s.z; ++z) {
        for (int y = 0; y < s.y; ++y) {
            for (int x = 0; x < s.x; ++x) {
                if (!world.solid(x, y, z)) continue;
                count += !world.solid(x + 1, y, z) + !world.solid(x - 1, y, z) +
                         !world.solid(x, y + 1, z) + !world.solid(x, y - 1, z) +
                         !world.solid(x, y, z + 1) + !world.solid(x, y, z - 1);
            }
        }
    }
    return count;
}

Result<FaceTable> FaceTable::build(const VoxelWorld& world, const TextureSet* textures,
                                   std::int64_t maxFaces, const ShadeOptions* shading) {
    FaceTable table;
    table.size_ = world.size();
    const std::vector<bool> cutout = cutoutSlots(textures);
    const auto transmissive = [&](Voxel v) {
        if (!shading || !shading->refraction || !v.solid()) return false;
        const Material& m = shading->materials.forSlot(textureSlotOf(v));
        return m.transmission > 0.0f && m.metallic < 1.0f;
    };
    // Whether light reaches the face of `from` towards (x, y, z).
    const auto open = [&](Voxel from, int x, int y, int z) {
        const Voxel v = world.get(x, y, z);
        if (!v.solid()) return true;
        const int slot = textureSlotOf(v);
        if (textures && slot >= 0 && slot < textures->size() && cutout[slot]) return true;
        return transmissive(v) && !transmissive(from);
    };
    const Int3 s = world.size();
    for (int z = 0; z < s.z; ++z) {
        for (int y = 0; y < s.y; ++y) {
            for (int x = 0; x < s.x; ++x) {
                const Voxel from = world.get(x, y, z);
                if (!from.solid()) continue;
                for (int n = 0; n < 6; ++n) {
                    const Int3 d = normalFromIndex(n);
                    if (!open(from, x + d.x, y + d.y, z + d.z)) continue;
                    if (std::int64_t(table.faces_.size()) >= maxFaces) {
                        return Error("radiance cascades: the world has more than " +
                                     std::to_string(maxFaces) +
                                     " open voxel faces, more than the memory limit allows");
                    }
                    table.faces_.push_back({{x, y, z}, std::uint8_t(n)});
                }
            }
        }
    }
    const std::uint64_t capacity = std::bit_ceil(std::uint64_t(table.faces_.size()) * 2 + 16);
    table.mask_ = capacity - 1;
    table.slots_.assign(capacity, Slot{});
    for (int id = 0; id < table.size(); ++id) {
        const std::uint64_t k = table.key(table.faces_[id].voxel, table.faces_[id].normal);
        std::uint64_t slot = mix(k) & table.mask_;
        while (table.slots_[slot].stored() != 0) slot = (slot + 1) & table.mask_;
        table.slots_[slot] = {std::uint32_t(k + 1), std::uint32_t((k + 1) >> 32), id};
    }
    table.neighbours_.resize(table.faces_.size() * 8);
    parallelForRange(table.size(), 1024, [&](int begin, int end) {
        for (int id = begin; id < end; ++id) {
            const Face& f = table.faces_[id];
            const int axis = f.normal / 2, a = (axis + 1) % 3, b = (axis + 2) % 3;
            std::int32_t* out = &table.neighbours_[std::size_t(id) * 8];
            for (int db = -1; db <= 1; ++db) {
                for (int da = -1; da <= 1; ++da) {
                    if (da == 0 && db == 0) continue;
                    Int3 v = f.voxel;
                    v[a] += da, v[b] += db;
                    *out++ = table.find(v, f.normal);
                }
            }
        }
    });
    return table;
}

int FaceTable::find(Int3 v, int normal) const {
    if (v.x < 0 || v.y < 0 || v.z < 0 || v.x >= size_.x || v.y >= size_.y || v.z >= size_.z) {
        return -1;
    }
    const std::uint64_t k = key(v, normal) + 1;
    for (std::uint64_t slot = mix(k - 1) & mask_;; slot = (slot + 1) & mask_) {
        const Slot& s = slots_[slot];
        const std::uint64_t stored = s.stored();
        if (stored == k) return s.id;
        if (stored == 0) return -1;
    }
}

std::uint64_t FaceTable::bytes() const {
    return faces_.size() * sizeof(Face) + slots_.size() * sizeof(Slot) +
           neighbours_.size() * sizeof(std::int32_t);
}

Vec3d faceCentre(const Face& face) {
    const Int3 n = normalFromIndex(face.normal);
    Vec3d c{face.voxel.x + 0.5, face.voxel.y + 0.5, face.voxel.z + 0.5};
    return c + Vec3d{double(n.x), double(n.y), double(n.z)} * 0.5;
}

Vec3d faceQuarterCentre(const Face& face, int i) {
    const int axis = face.normal / 2, a = (axis + 1) % 3, b = (axis + 2) % 3;
    Vec3d p = faceCentre(face);
    p[a] += (i & 1) ? 0.25 : -0.25;
    p[b] += (i & 2) ? 0.25 : -0.25;
    return p;
}

}  // namespace luxel::voxel::cascades
