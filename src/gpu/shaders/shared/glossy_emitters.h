// The lamps in the radiance cascades' camera surface's glossy lobe, light-sampled and combined
// with its GGX rays by multiple importance sampling (docs/algorithms/voxel-radiance-cascades.md
// §4.2, "Far lamps in the glossy lobe"). The lamps are the ray caster's rectangles of coplanar
// emissive faces (shared/emitter_light.h); each cell of its grid keeps the few that light it most
// (the picks), and a point picks one of its cell's in proportion to an estimate of its light
// there (glossyPickWeight), then a uniform point on the part of it in front of the point. Shared by
// the CPU picture (src/voxel/cascades/glossy_emitters.cpp) and the GPU's
// (voxel/glossy_emitters.glsl), in float.
//
// Buffers of cascades_picture after shared/cascade_picture_layout.h's 0..22:
//   23 uint per grid cell x LUXEL_GLOSSY_PICKS: the cell's picks, indices into 24, the unused
//      ones LUXEL_GLOSSY_NO_PICK
//   24 CascadeNearEmitter: the rectangles
#ifndef LUXEL_GPU_SHARED_GLOSSY_EMITTERS_H
#define LUXEL_GPU_SHARED_GLOSSY_EMITTERS_H

#include "emitter_light.h"
#include "glsl_compat.h"
#include "near_emitters.h"

// Lamps a grid cell keeps for its points to pick from (the strongest by lampCellScore).
#define LUXEL_GLOSSY_PICKS 8
#define LUXEL_GLOSSY_NO_PICK 0xFFFFFFFFu
// Light samples per camera sample of a glossy surface, beside its GGX rays.
#define LUXEL_GLOSSY_LIGHT_SAMPLES 1

LUXEL_SHARED_BEGIN

// The point at (u, v) in [0, 1)^2 of the span, uniform in area.
LUXEL_FUNC vec3 emitterSpanPoint(CascadeNearEmitter e, EmitterSpan s, float u, float v) {
    return nearEmitterPlanePoint(int(e.normal / 2u), emitterPlaneCoordinate(e),
                                 s.loA + u * (s.hiA - s.loA), s.loB + v * (s.hiB - s.loB));
}

// What a point x with axis-aligned face normal n picks a lamp by: its light there as from a
// small patch at the centre of its part in front of x, radiance x area cos_e cos_x / d^2, with
// d^2 + area for d^2 so that a lamp next to x stays finite (any weight keeps the estimator
// unbiased, the GGX rays taking alone what it leaves out; the exact contour integral costs 4
// arc tangents a lamp at every glossy pixel). 0: never picked (behind x, facing away).
// `s`: the lamp's part in front of x, emitterSpanInFront(x, n, e).
LUXEL_FUNC float glossyPickWeightOf(vec3 x, vec3 n, CascadeNearEmitter e, EmitterSpan s) {
    const float area = emitterSpanArea(s);
    if (!(area > 0.0f)) return 0.0f;
    const vec3 d = emitterSpanPoint(e, s, 0.5f, 0.5f) - x;
    const float towardsX = -dot(nearEmitterNormal(e.normal), d), fromX = dot(n, d);
    if (!(towardsX > 0.0f) || !(fromX > 0.0f)) return 0.0f;
    const float r2 = dot(d, d) + area;
    return max(e.r, max(e.g, e.b)) * area * towardsX * fromX / (r2 * r2);
}

LUXEL_FUNC float glossyPickWeight(vec3 x, vec3 n, CascadeNearEmitter e) {
    return glossyPickWeightOf(x, n, e, emitterSpanInFront(x, n, e));
}

// The density in solid angle, at x, of a uniform point y of the span: |y - x|^2 / (area cos_y);
// 0 when the span is empty or y lies on its plane's edge-on line.
LUXEL_FUNC float emitterSpanDensity(CascadeNearEmitter e, EmitterSpan s, vec3 x, vec3 y) {
    const float area = emitterSpanArea(s);
    const vec3 d = y - x;
    const float d2 = dot(d, d);
    const float cosY = abs(d[int(e.normal / 2u)]) / sqrt(d2);
    if (!(area > 0.0f) || !(cosY > 0.0f)) return 0.0f;
    return d2 / (area * cosY);
}

// The balance heuristic over nLight light samples of density lightPdf and nLobe lobe samples of
// density lobePdf, as the factor f cos L is multiplied by: 1 / (nLight lightPdf + nLobe lobePdf)
// (each strategy's estimate f cos L / (n p) times its weight n p / sum). A light sample takes it
// as it is; a GGX ray, whose sampling weight is f cos / lobePdf, times lobePdf.
LUXEL_FUNC float glossyBalance(float lightPdf, float lobePdf, float nLight, float nLobe) {
    const float sum = nLight * lightPdf + nLobe * lobePdf;
    return sum > 0.0f ? 1.0f / sum : 0.0f;
}

LUXEL_SHARED_END

#endif
