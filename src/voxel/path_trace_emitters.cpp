// Emissive voxels as lights (path_trace_emitters.h).
#include "luxel/voxel/path_trace_emitters.h"

#include <algorithm>
#include <cmath>

#include "luxel/voxel/texture_set.h"

namespace luxel::voxel {
namespace {

bool emits(const Material& m) {
    return m.emission.maxComponent() > 0.0f;
}

// The faces of `voxel` whose outward side holds `point`: up to three, as outward normals.
int facingFaces(Vec3d point, Int3 voxel, Int3 (&faces)[3]) {
    int count = 0;
    for (int a = 0; a < 3; ++a) {
        Int3 n{};
        if (point[a] > voxel[a] + 1.0) {
            n[a] = 1;
        } else if (point[a] < voxel[a]) {
            n[a] = -1;
        } else {
            continue;
        }
        faces[count++] = n;
    }
    return count;
}

int axisOf(Int3 normal) {
    return normal.x != 0 ? 0 : normal.y != 0 ? 1 : 2;
}

}  // namespace

PathEmitters PathEmitters::find(const VoxelWorld& world, const MaterialTable& materials) {
    PathEmitters out;
    bool any = emits(materials.plain());
    for (int slot = 0; slot < materials.slotCount() && !any; ++slot) {
        any = materials.hasSlot(slot) && emits(materials.forSlot(slot));
    }
    if (!any) return out;
    const Int3 chunks = world.chunkCount(), size = world.size();
    const int side = world.chunkSize();
    for (int cz = 0; cz < chunks.z; ++cz)
        for (int cy = 0; cy < chunks.y; ++cy)
            for (int cx = 0; cx < chunks.x; ++cx) {
                if (world.chunkSolidCount(cx, cy, cz) == 0) continue;
                for (int z = cz * side; z < std::min((cz + 1) * side, size.z); ++z)
                    for (int y = cy * side; y < std::min((cy + 1) * side, size.y); ++y)
                        for (int x = cx * side; x < std::min((cx + 1) * side, size.x); ++x) {
                            const Voxel v = world.get(x, y, z);
                            if (v.solid() && emits(materials.forSlot(textureSlotOf(v)))) {
                                if (out.size() == kMaxPathEmitters) return PathEmitters{};
                                out.voxels_.push_back({x, y, z});
                            }
                        }
            }
    return out;
}

PathEmitters::Sample PathEmitters::sample(Vec3d point, float u0, float u1, float u2,
                                          float u3) const {
    Sample s;
    if (voxels_.empty()) return s;
    const int n = size();
    s.voxel = voxels_[std::min(int(u0 * float(n)), n - 1)];
    Int3 faces[3];
    const int k = facingFaces(point, s.voxel, faces);
    if (k == 0) return s;
    s.normal = faces[std::min(int(u1 * float(k)), k - 1)];
    const int a = axisOf(s.normal), b = (a + 1) % 3, c = (a + 2) % 3;
    Vec3d q;
    q[a] = s.voxel[a] + (s.normal[a] > 0 ? 1.0 : 0.0);
    q[b] = s.voxel[b] + double(u2);
    q[c] = s.voxel[c] + double(u3);
    const Vec3d d = q - point;
    s.distance = length(d);
    if (!(s.distance > 0.0)) return s;
    s.direction = d / s.distance;
    const double cosLight = std::abs(s.direction[a]);
    if (!(cosLight > 0.0)) return s;
    s.pdf = s.distance * s.distance / (cosLight * n * k);
    return s;
}

double PathEmitters::pdf(Vec3d point, Int3 voxel, Int3 normal, Vec3d hit) const {
    if (voxels_.empty()) return 0.0;
    Int3 faces[3];
    const int k = facingFaces(point, voxel, faces);
    if (std::find(faces, faces + k, normal) == faces + k) return 0.0;
    const Vec3d d = hit - point;
    const double d2 = dot(d, d);
    const double cosLight = std::abs(d[axisOf(normal)]) / std::sqrt(d2);
    if (!(cosLight > 0.0)) return 0.0;
    return d2 / (cosLight * size() * k);
}

}  // namespace luxel::voxel
