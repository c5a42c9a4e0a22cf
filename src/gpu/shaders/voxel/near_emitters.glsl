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
