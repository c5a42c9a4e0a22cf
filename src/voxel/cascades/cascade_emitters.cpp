// Light of the emissive faces on every face, computed exactly rather than carried by the
// cascades (docs/algorithms/voxel-radiance-cascades.md §4.1): a glowing voxel is usually smaller
// than the direction bins near it, so the chains would see it through a handful of segments.
//
// The irradiance at a point x with normal n from a uniformly emitting polygon of radiance L
// wholly in front of x is Lambert's contour integral E = L/2 |sum_i theta_i n . u_i|, with
// theta_i the angle between the directions to consecutive vertices and u_i the unit normal of
// the plane they span. Visibility is the fraction of four points on the emitting face that the
// face centre x sees (cutouts let light through, as for the sun; glass and water dim it by their
// transmittance).
#include <array>
#include <cmath>

#include "cascade_passages.h"
#include "cascade_state.h"
#include "luxel/core/parallel.h"
#include "luxel/voxel/surface_cast.h"

namespace luxel::voxel::cascades {

namespace {

// The corners of a face in order around it.
std::array<Vec3d, 4> faceCorners(const Face& face) {
    const Int3 n = normalFromIndex(face.normal);
    const int axis = face.normal / 2, a = (axis + 1) % 3, b = (axis + 2) % 3;
    Vec3d base{double(face.voxel.x), double(face.voxel.y), double(face.voxel.z)};
    if (n[axis] > 0) base[axis] += 1.0;
    std::array<Vec3d, 4> corners{base, base, base, base};
    corners[1][a] += 1.0;
    corners[2][a] += 1.0;
    corners[2][b] += 1.0;
    corners[3][b] += 1.0;
    return corners;
}

// Lambert's formula without the L/2 factor: the projected solid angle of the polygon at x.
double projectedSolidAngle(Vec3d x, Vec3d n, const std::array<Vec3d, 4>& polygon) {
    double sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        const Vec3d v0 = normalize(polygon[i] - x), v1 = normalize(polygon[(i + 1) % 4] - x);
        const Vec3d c = cross(v0, v1);
        const double s = length(c);
        if (!(s > 1e-12)) continue;
        const double theta = std::atan2(s, dot(v0, v1));
        sum += theta * dot(n, c / s);
    }
    return std::abs(sum) * 0.5;
}

// The mean over four points on the emitter of what reaches x from it: 1 in sight, 0 hidden,
// the transmittance through glass and water between (cascade_passages.h).
Rgb visibleFraction(const RadianceCascades::State& state, Vec3d x, int e) {
    const Face& emitter = state.faces.table[e];
    Rgb seen;
    for (int i = 0; i < 4; ++i) {
        const Vec3d target = faceQuarterCentre(emitter, i);
        const SegmentTrace trace = traceSegment(state, x, target - x, 1.0 + 1e-9);
        if (trace.end == std::uint32_t(e)) seen += traceTransmittance(trace);
    }
    return seen * 0.25f;
}

}  // namespace

bool computeEmitterIrradiance(RadianceCascades::State& state) {
    FaceData& faces = state.faces;
    std::vector<int> emitters;
    for (int f = 0; f < faces.table.size(); ++f) {
        if (faces.emission[f].maxComponent() > 0.0f) emitters.push_back(f);
    }
    faces.emitterIrradiance.assign(faces.table.size(), Rgb{});
    if (emitters.empty()) return true;
    if (double(emitters.size()) * faces.table.size() > kMaxEmitterPairs) return false;
    parallelForRange(faces.table.size(), 16, [&](int begin, int end) {
        for (int f = begin; f < end; ++f) {
            const Face& face = faces.table[f];
            const Int3 ni = normalFromIndex(face.normal);
            const Vec3d n{double(ni.x), double(ni.y), double(ni.z)};
            const Vec3d x = faceCentre(face);
            Rgb sum;
            for (int e : emitters) {
                if (e == f) continue;
                const Face& emitter = faces.table[e];
                const Int3 ei = normalFromIndex(emitter.normal);
                const Vec3d toReceiver = x - faceCentre(emitter);
                // The emitter must face x and lie in front of the receiving face.
                if (!(dot(Vec3d{double(ei.x), double(ei.y), double(ei.z)}, toReceiver) > 0.0) ||
                    !(dot(n, toReceiver) < 0.0)) {
                    continue;
                }
                const double omega = projectedSolidAngle(x, n, faceCorners(emitter));
                if (!(omega > 0.0)) continue;
                const Rgb visible = visibleFraction(state, x, e);
                if (visible.maxComponent() > 0.0f) {
                    sum += faces.emission[e] * visible * float(omega);
                }
            }
            faces.emitterIrradiance[f] = sum;
        }
    });
    return true;
}

}  // namespace luxel::voxel::cascades
