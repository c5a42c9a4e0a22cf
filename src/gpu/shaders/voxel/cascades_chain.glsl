// Voxel radiance cascades: following a segment's passages through glass and water
// (src/voxel/cascades/cascade_passages.h; CPU: chainRadiance in
// src/voxel/cascades/cascade_state.h). The includer declares `codes` (uint, the passages at its
// start) and `light` (RgbTexel, the faces' sections).

// Adds what the glass faces of the passages from `code` send, each times the transmittance
// before it, to `sum`; multiplies `through` by the passages' transmittance; returns the plain
// code the chain ends in.
uint cascadeFollowPassages(uint code, uint faces, inout vec3 sum, inout vec3 through) {
    for (uint i = 0u; i < LUXEL_CASCADE_MAX_PASSAGES; ++i) {
        if (code < LUXEL_CASCADE_PASSAGE || code >= LUXEL_CASCADE_VOID) break;
        const uint at = (code - LUXEL_CASCADE_PASSAGE) * LUXEL_CASCADE_PASSAGE_WORDS;
        const uint face = codes[at];
        if (face < LUXEL_CASCADE_PASSAGE) {
            sum += through * texelRgb(light[LUXEL_FACE_OUTGOING * faces + face]);
        }
        through *= vec3(uintBitsToFloat(codes[at + 2u]), uintBitsToFloat(codes[at + 3u]),
                        uintBitsToFloat(codes[at + 4u]));
        code = codes[at + 1u];
    }
    return code;
}
