// cascades::nearEmitterLight (src/voxel/cascades/cascade_near_emitters.cpp) on the GPU: the light
// of the emitters near a point of the picture taken exactly there, each by its nearEmitterWeight
// (shared/near_emitters.h), seen along four straight lines to the emitter (lineTransmittance).
// Needs solver_light.glsl and the buffers `nearOffset` and `nearEmitters`.

vec3 nearEmitterLight(Hit hit) {
    const int face = findFace(hit.voxel, normalIndex(hit.normal));
    if (face < 0) return vec3(0.0);
    const vec3 n = vec3(hit.normal);
    vec3 sum = vec3(0.0);
    for (uint i = nearOffset[face]; i < nearOffset[face + 1]; ++i) {
        const CascadeNearEmitter e = nearEmitters[i];
        const float weight = nearEmitterWeight(length(hit.point - nearEmitterPoint(e, -1)),
                                               LUXEL_NEAR_EMITTER_INNER, LUXEL_NEAR_EMITTER_OUTER);
        if (!(weight > 0.0)) continue;
        const float formFactor = nearEmitterFormFactor(hit.point, n, e);
        if (!(formFactor > 0.0)) continue;
        const ivec3 voxel = ivec3(e.x, e.y, e.z), normal = ivec3(nearEmitterNormal(e.normal));
        vec3 seen = vec3(0.0);
        for (int q = 0; q < 4; ++q) {
            const vec3 d = normalize(nearEmitterPoint(e, q) - hit.point);
            seen += lineTransmittance(hit.point, d, true, voxel, normal);
        }
        sum += vec3(e.r, e.g, e.b) * seen * (0.25 * weight * formFactor);
    }
    return sum;
}

// cascades::nearEmitterHighlight: the camera surface's glossy highlight of its near emitters,
// each quarter's grid of points delta lights of their cells' solid angles through `specular`
// (the specular-only lobe), dimmed by the quarter's visibility ray, times the emitter's weight.
// Needs path_surface.glsl.
vec3 nearEmitterHighlight(Hit hit, PathBsdf specular) {
    const int face = findFace(hit.voxel, normalIndex(hit.normal));
    if (face < 0) return vec3(0.0);
    vec3 sum = vec3(0.0);
    for (uint i = nearOffset[face]; i < nearOffset[face + 1]; ++i) {
        const CascadeNearEmitter e = nearEmitters[i];
        const vec3 centre = nearEmitterPoint(e, -1);
        const float distance = length(hit.point - centre);
        const float weight =
            nearEmitterWeight(distance, LUXEL_NEAR_EMITTER_INNER, LUXEL_NEAR_EMITTER_OUTER);
        if (!(weight > 0.0)) continue;
        const vec3 outward = nearEmitterNormal(e.normal);
        if (!(dot(outward, hit.point - centre) > 0.0)) continue;
        const ivec3 voxel = ivec3(e.x, e.y, e.z), normal = ivec3(outward);
        const int side = nearHighlightSide(distance, specular.alpha);
        vec3 seen = vec3(0.0);
        for (int q = 0; q < 4; ++q) {
            const vec3 d = normalize(nearEmitterPoint(e, q) - hit.point);
            const vec3 t = lineTransmittance(hit.point, d, true, voxel, normal);
            if (!(maxComponent(t) > 0.0)) continue;
            const vec3 radiance = vec3(e.r, e.g, e.b) * t;
            for (int k = 0; k < side * side; ++k) {
                const vec3 to = nearEmitterQuarterPoint(e, q, k, side) - hit.point;
                const vec3 l = normalize(to);
                const float solidAngle =
                    0.25 / float(side * side) * abs(dot(outward, l)) / dot(to, to);
                seen += pathBsdfLight(specular, l, radiance * solidAngle, 0.0);
            }
        }
        sum += seen * weight;
    }
    return sum;
}

// cascades::nearEmitterShare: the weight at `point` on face `face` (its id, -1 for none) of the
// emitting face (voxel, normal) when it is in that face's near list, else 0. The list is walked
// to its end, not left by a return inside the loop: on lavapipe (Mesa 22.3) the early return
// gave 0 to invocations that had found the emitter, in some groups (the same call made again in
// a branch of its own gave the weight), so the GGX rays counted the lamp in full.
float nearEmitterShare(int face, vec3 point, ivec3 voxel, ivec3 normal) {
    if (face < 0) return 0.0;
    const uint met = uint(normalIndex(normal));
    float share = 0.0;
    for (uint i = nearOffset[face]; i < nearOffset[face + 1]; ++i) {
        const CascadeNearEmitter e = nearEmitters[i];
        if (e.x == voxel.x && e.y == voxel.y && e.z == voxel.z && e.normal == met) {
            share = nearEmitterWeight(length(point - nearEmitterPoint(e, -1)),
                                      LUXEL_NEAR_EMITTER_INNER, LUXEL_NEAR_EMITTER_OUTER);
        }
    }
    return share;
}
