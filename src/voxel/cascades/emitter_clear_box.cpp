// The empty box in front of an emitting face (emitter_clear_box.h;
// docs/algorithms/voxel-radiance-cascades.md §5, "Near lines proven clear").
#include "emitter_clear_box.h"

#include <algorithm>
#include <cmath>

#include "voxel/face_normal.h"
#include "voxel/shadow_blockers.h"

namespace luxel::voxel::cascades {

namespace {

// Whether every cell lo <= c < hi is inside the world and empty.
bool allEmpty(const VoxelWorld& world, Int3 lo, Int3 hi) {
    const Int3 size = world.size();
    for (int a = 0; a < 3; ++a) {
        if (lo[a] < 0 || hi[a] > size[a]) return false;
    }
    for (int z = lo.z; z < hi.z; ++z)
        for (int y = lo.y; y < hi.y; ++y)
            for (int x = lo.x; x < hi.x; ++x) {
                if (world.solid(x, y, z)) return false;
            }
    return true;
}

}  // namespace

EmitterClearBox growEmitterClearBox(const VoxelWorld& world, Int3 corner, int normal, int sizeA,
                                    int sizeB, int reach) {
    const Int3 n = normalFromIndex(normal);
    const int axis = normal / 2;
    EmitterClearBox box;
    box.emitterAxis = axis;
    box.emitterPlane = corner[axis] + (n[axis] > 0 ? 1 : 0);
    box.rectLo = corner;
    box.rectHi = {corner.x + 1, corner.y + 1, corner.z + 1};
    box.rectHi[(axis + 1) % 3] = corner[(axis + 1) % 3] + sizeA;
    box.rectHi[(axis + 2) % 3] = corner[(axis + 2) % 3] + sizeB;
    const Int3 front{corner.x + n.x, corner.y + n.y, corner.z + n.z};
    const Int3 one{box.rectHi.x + n.x, box.rectHi.y + n.y, box.rectHi.z + n.z};
    if (!allEmpty(world, front, one)) return box;
    box.lo = front;
    box.hi = one;
    // The farthest bounds `reach` allows: every side but the emitter's own.
    Int3 farLo{front.x - reach, front.y - reach, front.z - reach};
    Int3 farHi{one.x + reach, one.y + reach, one.z + reach};
    if (n[axis] > 0) {
        farLo[axis] = front[axis];
    } else {
        farHi[axis] = one[axis];
    }
    // One layer a side in turn, so the box widens evenly until every side is stopped.
    bool grew = true;
    while (grew) {
        grew = false;
        for (int side = 0; side < 6; ++side) {
            const int a = side / 2;
            const bool up = side % 2 == 0;
            if (up ? box.hi[a] >= farHi[a] : box.lo[a] <= farLo[a]) continue;
            Int3 lo = box.lo, hi = box.hi;
            if (up) {
                lo[a] = box.hi[a];
                hi[a] = box.hi[a] + 1;
            } else {
                lo[a] = box.lo[a] - 1;
                hi[a] = box.lo[a];
            }
            if (!allEmpty(world, lo, hi)) {
                // Stopped for good on this side.
                (up ? farHi[a] : farLo[a]) = up ? box.hi[a] : box.lo[a];
                continue;
            }
            (up ? box.hi[a] : box.lo[a]) = up ? hi[a] : lo[a];
            grew = true;
        }
    }
    return box;
}

bool lineProvenClear(const EmitterClearBox& box, const Hit& hit) {
    if (box.empty() || !hit.hit || hit.normal == Int3{}) return false;
    const auto inBox = [&](Int3 c) {
        return c.x >= box.lo.x && c.y >= box.lo.y && c.z >= box.lo.z && c.x < box.hi.x &&
               c.y < box.hi.y && c.z < box.hi.z;
    };
    const Int3 outside{hit.voxel.x + hit.normal.x, hit.voxel.y + hit.normal.y,
                       hit.voxel.z + hit.normal.z};
    // The face between the hit voxel and its outside cell is then on the box's boundary.
    if (!inBox(outside) || inBox(hit.voxel)) return false;
    const int a = normalIndex(hit.normal) / 2;
    const Vec3d& p = hit.point;
    if (p[a] != double(hit.voxel[a] + (hit.normal[a] > 0 ? 1 : 0))) return false;
    for (int b = 0; b < 3; ++b) {
        if (!(p[b] >= double(box.lo[b]) && p[b] <= double(box.hi[b]))) return false;
    }
    // Strictly in front of the emitter's plane: a line along that plane could graze its cells.
    const int e = box.emitterAxis;
    const double plane = double(box.emitterPlane);
    return box.lo[e] == box.emitterPlane ? p[e] > plane : p[e] < plane;
}

bool rayProvenToRect(const EmitterClearBox& box, const Hit& hit, const Vec3d& direction,
                     double reach, Int3* voxel) {
    if (!(reach > 0.0) || !std::isfinite(reach) || !lineProvenClear(box, hit)) return false;
    constexpr double m = ShadowBlockers::kEdgeMargin;
    const int e = box.emitterAxis;
    Int3 cell = box.rectLo;
    for (int k = 1; k <= 2; ++k) {
        const int b = (e + k) % 3;
        const double c = hit.point[b] + reach * direction[b];
        if (!(c > double(box.rectLo[b]) + m && c < double(box.rectHi[b]) - m)) return false;
        const double whole = std::floor(c);
        if (!(c - whole > m && c - whole < 1.0 - m)) return false;
        cell[b] = int(whole);
    }
    *voxel = cell;
    return true;
}

}  // namespace luxel::voxel::cascades
