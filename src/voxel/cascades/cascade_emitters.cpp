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
//
// Near a small emitter the light changes within one face by more than interpolation between face
// centres can draw, so the picture takes each emitter's light within a few voxels exactly at the
// pixel (cascade_near_emitters.cpp): here each face also gets the far share of its emitter
// irradiance (1 - nearEmitterWeight at its centre) and the list of emitters near it.
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

// The emitting face as the picture's near lists hold it.
gpu::shared::CascadeNearEmitter nearEmitter(const FaceData& faces, int e) {
    const Face& face = faces.table[e];
    const Rgb& l = faces.emission[e];
    return {face.voxel.x, face.voxel.y, face.voxel.z, face.normal, l.r, l.g, l.b, 0};
}

// Whether emitter e can light face f: it faces f's centre, which lies in front of it (both lie
// on voxel planes, so what holds at the centre holds over the whole face, bar its edges).
bool emitterFaces(const FaceData& faces, int e, int f) {
    if (e == f) return false;
    const Int3 ni = normalFromIndex(faces.table[f].normal);
    const Int3 ei = normalFromIndex(faces.table[e].normal);
    const Vec3d toReceiver = faceCentre(faces.table[f]) - faceCentre(faces.table[e]);
    return dot(Vec3d{double(ei.x), double(ei.y), double(ei.z)}, toReceiver) > 0.0 &&
           dot(Vec3d{double(ni.x), double(ni.y), double(ni.z)}, toReceiver) < 0.0;
}

// How far from a face's centre its farthest point lies (half its diagonal), and so how much
// nearer than its centre a point of it may be to an emitter.
constexpr double kHalfDiagonal = 0.70710678118654752;

// The share of emitter e's light the picture takes exactly at a point `distance` from its
// centre (none when the near term is off).
double nearShare(const RadianceCascades::State& state, double distance) {
    if (!state.options.nearEmitters) return 0.0;
    return gpu::shared::nearEmitterWeight(float(distance), LUXEL_NEAR_EMITTER_INNER,
                                          LUXEL_NEAR_EMITTER_OUTER);
}

// The near lists: per face the emitters whose near share is above 0 somewhere on it.
void listNearEmitters(RadianceCascades::State& state, const std::vector<int>& emitters) {
    FaceData& faces = state.faces;
    const int count = faces.table.size();
    faces.nearOffset.assign(std::size_t(count) + 1, 0);
    if (!state.options.nearEmitters) return;
    const double reach = double(LUXEL_NEAR_EMITTER_OUTER) + kHalfDiagonal;
    auto near = [&](int e, int f) {
        return emitterFaces(faces, e, f) &&
               length(faceCentre(faces.table[f]) - faceCentre(faces.table[e])) < reach;
    };
    std::vector<std::uint32_t> counts(count, 0);
    parallelForRange(count, 256, [&](int begin, int end) {
        for (int f = begin; f < end; ++f) {
            for (int e : emitters) counts[f] += near(e, f) ? 1 : 0;
        }
    });
    for (int f = 0; f < count; ++f) faces.nearOffset[f + 1] = faces.nearOffset[f] + counts[f];
    faces.nearEmitters.resize(faces.nearOffset[count]);
    // Each emitter's empty box, grown as far as its near share reaches (§5, "Near lines proven
    // clear").
    faces.nearBoxes.resize(emitters.size());
    const int boxReach = int(std::ceil(reach));
    parallelForRange(int(emitters.size()), 16, [&](int begin, int end) {
        for (int k = begin; k < end; ++k) {
            const Face& face = faces.table[emitters[std::size_t(k)]];
            faces.nearBoxes[std::size_t(k)] =
                growEmitterClearBox(*state.world, face.voxel, face.normal, 1, 1, boxReach);
        }
    });
    faces.nearBox.resize(faces.nearOffset[count]);
    parallelForRange(count, 256, [&](int begin, int end) {
        for (int f = begin; f < end; ++f) {
            std::uint32_t at = faces.nearOffset[f];
            for (std::size_t k = 0; k < emitters.size(); ++k) {
                if (!near(emitters[k], f)) continue;
                faces.nearBox[at] = std::uint32_t(k);
                faces.nearEmitters[at++] = nearEmitter(faces, emitters[k]);
            }
        }
    });
}

}  // namespace

bool computeEmitterIrradiance(RadianceCascades::State& state) {
    FaceData& faces = state.faces;
    ++faces.emitterVersion;
    std::vector<int> emitters;
    for (int f = 0; f < faces.table.size(); ++f) {
        if (faces.emission[f].maxComponent() > 0.0f) emitters.push_back(f);
    }
    faces.emitterIrradiance.assign(faces.table.size(), Rgb{});
    faces.emitterFar.assign(faces.table.size(), Rgb{});
    faces.nearOffset.assign(std::size_t(faces.table.size()) + 1, 0);
    faces.nearEmitters.clear();
    faces.nearBoxes.clear();
    faces.nearBox.clear();
    // The lamps the glossy surfaces light-sample (§4.2), whether or not the pairs below fit.
    faces.glossy = state.options.glossyEmitters
                       ? buildGlossyLamps(*state.world, state.shading.materials)
                       : GlossyLamps{};
    if (emitters.empty()) return true;
    if (double(emitters.size()) * faces.table.size() > kMaxEmitterPairs) return false;
    parallelForRange(faces.table.size(), 16, [&](int begin, int end) {
        for (int f = begin; f < end; ++f) {
            const Face& face = faces.table[f];
            const Int3 ni = normalFromIndex(face.normal);
            const Vec3d n{double(ni.x), double(ni.y), double(ni.z)};
            const Vec3d x = faceCentre(face);
            Rgb sum, far;
            for (int e : emitters) {
                if (!emitterFaces(faces, e, f)) continue;
                const Vec3d toReceiver = x - faceCentre(faces.table[e]);
                const double omega = projectedSolidAngle(x, n, faceCorners(faces.table[e]));
                if (!(omega > 0.0)) continue;
                const Rgb visible = visibleFraction(state, x, e);
                if (visible.maxComponent() > 0.0f) {
                    const Rgb light = faces.emission[e] * visible * float(omega);
                    sum += light;
                    far += light * float(1.0 - nearShare(state, length(toReceiver)));
                }
            }
            faces.emitterIrradiance[f] = sum;
            faces.emitterFar[f] = far;
        }
    });
    listNearEmitters(state, emitters);
    return true;
}

}  // namespace luxel::voxel::cascades
