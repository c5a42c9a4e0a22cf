// cascades::GlossyLampChoice (src/voxel/cascades/glossy_emitters.cpp) on the GPU: the lamps the
// camera surface's glossy lobe light-samples, picked among its grid cell's by their unoccluded
// light at the hit, and their density where a GGX ray meets one (shared/glossy_emitters.h;
// docs/algorithms/voxel-radiance-cascades.md §4.2, "Far lamps in the glossy lobe"), the CPU's
// float arithmetic. Needs path_surface.glsl, near_emitters.glsl (nearEmitterShare), the buffers
// glossyPicks and glossyLamps, and pictureNearFace and pictureNearPoint.

// The camera surface's choice (glossyLampsChoose): its normal, the lamps it may pick, their
// weights and the weights' sum.
vec3 pictureLampNormal;
int pictureLampCount;
uint pictureLampIndex[LUXEL_GLOSSY_PICKS];
float pictureLampWeight[LUXEL_GLOSSY_PICKS];
float pictureLampTotal;
// What the GGX ray being followed met of them (reflectedLight0): the lamp's emission times 1 -
// its near weight, and the light samples' density there (0: none, the emission stayed in the
// split sum).
vec3 pictureLampEmission;
float pictureLampDensity;

// GlossyLampChoice::choose at the camera surface's hit (no picks without the lamps' grid). The
// cell's list is read to its end, a flag ending it, rather than left by `break`, as
// nearEmitterShare walks its list (near_emitters.glsl).
void glossyLampsChoose(Hit hit) {
    pictureLampNormal = vec3(hit.normal);
    pictureLampCount = 0;
    pictureLampTotal = 0.0;
    if (path.lampCellsX == 0u) return;
    const int cell = emitterCellIndex(hit.point,
                                      ivec3(path.lampCellsX, path.lampCellsY, path.lampCellsZ));
    bool listed = true;
    for (int k = 0; k < LUXEL_GLOSSY_PICKS; ++k) {
        const uint i = glossyPicks[cell * LUXEL_GLOSSY_PICKS + k];
        if (i == LUXEL_GLOSSY_NO_PICK) listed = false;
        if (!listed) continue;
        const float w = glossyPickWeight(hit.point, pictureLampNormal, glossyLamps[i]);
        if (!(w > 0.0)) continue;
        pictureLampIndex[pictureLampCount] = i;
        pictureLampWeight[pictureLampCount] = w;
        pictureLampTotal += w;
        ++pictureLampCount;
    }
}

// GlossyLampChoice::density: the light samples' density in solid angle at the camera surface's
// point towards y on face (voxel, normal); 0 when no pick holds it (the rectangles do not
// overlap, so at most one does).
float glossyLampDensity(ivec3 voxel, ivec3 normal, vec3 y) {
    const uint met = uint(normalIndex(normal));
    float density = 0.0;
    for (int k = 0; k < pictureLampCount; ++k) {
        const CascadeNearEmitter e = glossyLamps[pictureLampIndex[k]];
        if (e.normal == met &&
            emitterRectHolds(ivec3(e.x, e.y, e.z), int(met / 2u), e.extent, voxel)) {
            const EmitterSpan span = emitterSpanInFront(pictureNearPoint, pictureLampNormal, e);
            density = pictureLampWeight[k] / pictureLampTotal *
                      emitterSpanDensity(e, span, pictureNearPoint, y);
        }
    }
    return density;
}

// GlossyLampChoice::sample: LUXEL_GLOSSY_LIGHT_SAMPLES light samples through `specular` (the
// specular-only lobe with its S), each weighed by the balance heuristic against lobeRays GGX
// rays; a sample counts when its shadow ray first meets the rectangle it aimed at.
vec3 glossyLampLight(Hit hit, PathBsdf specular, int lobeRays, inout uvec2 rng) {
    vec3 sum = vec3(0.0);
    if (pictureLampCount == 0) return sum;
    for (int n = 0; n < LUXEL_GLOSSY_LIGHT_SAMPLES; ++n) {
        const float u0 = pathRngNext(rng);
        const float u1 = pathRngNext(rng);
        const float u2 = pathRngNext(rng);
        const float target = u0 * pictureLampTotal;
        float below = 0.0;
        int k = -1;
        for (int j = 0; j < pictureLampCount; ++j) {
            below += pictureLampWeight[j];
            if (k < 0 && target < below) k = j;
        }
        if (k < 0) k = pictureLampCount - 1;
        const CascadeNearEmitter e = glossyLamps[pictureLampIndex[k]];
        const EmitterSpan span = emitterSpanInFront(hit.point, pictureLampNormal, e);
        const vec3 y = emitterSpanPoint(e, span, u1, u2);
        const float lightPdf = pictureLampWeight[k] / pictureLampTotal *
                               emitterSpanDensity(e, span, hit.point, y);
        if (!(lightPdf > 0.0)) continue;
        const vec3 l = normalize(y - hit.point);
        const ivec3 outward = ivec3(nearEmitterNormal(e.normal));
        const SurfaceHit seen = castToSurface(hit.point, l);
        if (!seen.hit.hit || seen.hit.normal != outward ||
            !emitterRectHolds(ivec3(e.x, e.y, e.z), int(e.normal / 2u), e.extent,
                              seen.hit.voxel)) {
            continue;
        }
        const float share =
            1.0 - nearEmitterShare(pictureNearFace, pictureNearPoint, seen.hit.voxel, outward);
        if (!(share > 0.0)) continue;
        const float lobePdf = pathGgxPdf(specular, l);
        const float balance = glossyBalance(lightPdf, lobePdf, float(LUXEL_GLOSSY_LIGHT_SAMPLES),
                                            float(lobeRays));
        sum += pathBsdfLight(specular, l, vec3(e.r, e.g, e.b) * (share * balance), 0.0);
    }
    return sum;
}
