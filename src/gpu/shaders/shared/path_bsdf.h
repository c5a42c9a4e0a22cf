// The float kernels of the voxel path tracer's surface response and sun disk on the GPU
// (src/gpu/shaders/voxel/path_surface.glsl): the power heuristic, GGX's distribution, masking,
// reflectance and visible-normal sampling, and the direction in the sun's cone. They are the CPU's
// (src/voxel/path_trace_bsdf.cpp, src/voxel/sun_disk.cpp, in double) written for float:
// GGX's D takes the half vector's sin^2 and cos separately, D = a^2 / (pi (sin^2 + a^2 cos^2)^2),
// and sin^2 comes from the half vector's two tangential components (exact for the axis-aligned
// face normals), never as 1 - cos^2, so the narrowest lobes (alpha down to the mirror threshold
// 1e-4) keep their shape where the textbook form 1 + cos^2 (a^2 - 1) cancels to nothing. The
// C++ side compiles them too, and tests/voxel/path_bsdf_kernels_test.cpp checks them against the
// CPU tracer's double results (docs/algorithms/voxel-path-tracing.md, "On the GPU").
#ifndef LUXEL_GPU_SHARED_PATH_BSDF_H
#define LUXEL_GPU_SHARED_PATH_BSDF_H

#include "glsl_compat.h"
#include "optics.h"

#define LUXEL_PATH_PI 3.14159265358979f
// Below this GGX alpha (roughness 0.01) the specular lobe is a delta mirror (kMirrorAlpha).
#define LUXEL_PATH_MIRROR_ALPHA 1e-4f
// A ray that glass gave back its direction meets a delta sun when half its squared chord to the
// axis is below this (an angle of 1.4e-5 rad: rounding, not a different direction).
#define LUXEL_PATH_DELTA_SUN_CHORD 1e-10

LUXEL_SHARED_BEGIN

// The power heuristic's weight of a strategy of density `mine` against one of density `other`,
// as a ratio so that large densities do not overflow float; 0 when `mine` is 0.
LUXEL_FUNC float pathPowerHeuristic(float mine, float other) {
    if (!(mine > 0.0f)) return 0.0f;
    const float r = other / mine;
    return 1.0f / (1.0f + r * r);
}

// GGX's distribution for a half vector at cosine cosH and sine squared sin2H to the normal.
LUXEL_FUNC float pathGgxD(float cosH, float sin2H, float alpha) {
    const float a2 = alpha * alpha;
    const float f = sin2H + a2 * cosH * cosH;
    return a2 / (LUXEL_PATH_PI * f * f);
}

// Smith's masking G1 for GGX at cosine c: 2c / (c + sqrt(alpha^2 + (1 - alpha^2) c^2)).
LUXEL_FUNC float pathGgxMasking(float c, float alpha) {
    const float a2 = alpha * alpha;
    return 2.0f * c / (c + sqrt(a2 + (1.0f - a2) * c * c));
}

// What a visible normal of GGX depends on besides its two numbers: the view stretched by alpha
// (vh) and the two tangents of the disk it is sampled on, for the view `v` in the face's frame
// (tangents, then the normal; v.z = cos_v). Made once where one lobe draws several normals (the
// real-time solvers' GgxSampler, src/voxel/path_trace_bsdf.cpp).
struct PathGgxVisibleFrame {
    vec3 vh;
    vec3 t1;
    vec3 t2;
};

LUXEL_FUNC PathGgxVisibleFrame pathGgxVisibleFrame(vec3 v, float alpha) {
    PathGgxVisibleFrame f;
    f.vh = normalize(vec3(alpha * v.x, alpha * v.y, v.z));
    const float lensq = f.vh.x * f.vh.x + f.vh.y * f.vh.y;
    f.t1 =
        lensq > 0.0f ? vec3(-f.vh.y, f.vh.x, 0.0f) * (1.0f / sqrt(lensq)) : vec3(1.0f, 0.0f, 0.0f);
    f.t2 = cross(f.vh, f.t1);
    return f;
}

// A visible normal of GGX (Heitz 2018, "Sampling the GGX Distribution of Visible Normals") in the
// frame `f` of pathGgxVisibleFrame, from two numbers in [0, 1), before normalisation: the half
// vector in the face's frame times a positive factor.
LUXEL_FUNC vec3 pathGgxVisibleNormalUnnormalised(PathGgxVisibleFrame f, float alpha, float u1,
                                                 float u2) {
    const float r = sqrt(u1), phi = 2.0f * LUXEL_PATH_PI * u2;
    const float p1 = r * cos(phi);
    const float s = 0.5f * (1.0f + f.vh.z);
    const float p2 = (1.0f - s) * sqrt(max(0.0f, 1.0f - p1 * p1)) + s * r * sin(phi);
    const vec3 nh = f.t1 * p1 + f.t2 * p2 + f.vh * sqrt(max(0.0f, 1.0f - p1 * p1 - p2 * p2));
    return vec3(alpha * nh.x, alpha * nh.y, max(0.0f, nh.z));
}

// The visible normal for the view `v` in the face's frame: the half vector in the same frame.
LUXEL_FUNC vec3 pathGgxVisibleNormal(vec3 v, float alpha, float u1, float u2) {
    return normalize(
        pathGgxVisibleNormalUnnormalised(pathGgxVisibleFrame(v, alpha), alpha, u1, u2));
}

// GGX's D times the height-correlated visibility for the unit light direction l at cosine cosL
// to the axis-aligned face normal n, seen from the unit `view` at cosine cosView: f / S of a
// specular lobe, the highlight of a delta light being S D Vis cos_l L.
LUXEL_FUNC float pathGgxReflectance(vec3 n, vec3 view, vec3 l, float cosView, float cosL,
                                    float alpha) {
    const vec3 h = normalize(view + l);
    const float cosH = dot(n, h);
    const vec3 across = h - n * cosH;
    return pathGgxD(cosH, dot(across, across), alpha) * ggxSmithVisibility(cosView, cosL, alpha);
}

// The unit direction at 1 - cos(theta) = oneMinusCos from the unit `axis`, at azimuth phi about
// it in the orthonormal tangents (t, b) (SunDisk's cone; the host computes the tangents in
// double).
LUXEL_FUNC vec3 pathConeDirection(vec3 axis, vec3 t, vec3 b, float oneMinusCos, float phi) {
    const float sinTheta = sqrt(max(0.0f, oneMinusCos * (2.0f - oneMinusCos)));
    return normalize(axis * (1.0f - oneMinusCos) + t * (sinTheta * cos(phi)) +
                     b * (sinTheta * sin(phi)));
}

// Whether unit direction d lies in the cone of 1 - cos r = oneMinusCos about `axis` (never for
// a delta sun): 1 - cos of the angle from the chord, |d - axis|^2 / 2 (no cancellation).
LUXEL_FUNC bool pathConeContains(vec3 axis, float oneMinusCos, vec3 d) {
    if (!(oneMinusCos > 0.0f)) return false;
    const vec3 chord = d - axis;
    return 0.5f * dot(chord, chord) <= oneMinusCos;
}

LUXEL_SHARED_END

#endif
