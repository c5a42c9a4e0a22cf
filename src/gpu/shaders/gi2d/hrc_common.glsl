// GLSL glue of the HRC passes: binary16 table entries and cones (the interval arithmetic is shared
// with the CPU in shared/hrc_kernels.h).
#ifndef LUXEL_HRC_COMMON_GLSL
#define LUXEL_HRC_COMMON_GLSL

#include "shared/hrc_kernels.h"

// Entry layout: HrcTableEntry in src/gpu/shaders/shared/hrc_layout.h.
HrcInterval unpackEntry(HrcTableEntry e) {
    const vec2 a = unpackHalf2x16(e.radianceRG), b = unpackHalf2x16(e.radianceBTransmittanceR),
               c = unpackHalf2x16(e.transmittanceGB);
    return HrcInterval(vec3(a.x, a.y, b.x), vec3(b.y, c.x, c.y));
}

HrcTableEntry packEntry(HrcInterval v) {
    return HrcTableEntry(packHalf2x16(v.radiance.xy),
                         packHalf2x16(vec2(v.radiance.z, v.transmittance.x)),
                         packHalf2x16(v.transmittance.yz));
}

// Entry (p, k, y) of T_level.
uint tableIndex(uint level, uint p, uint k, uint y, uint rows) {
    return (p * ((1u << level) + 1u) + k) * rows + y;
}

// Binary16 value `index` of a buffer of 32-bit words, given the word that holds it (even indices
// in the low half: the cone layout of shared/hrc_layout.h).
float halfOfWord(uint word, uint index) {
    const vec2 both = unpackHalf2x16(word);
    return (index & 1u) == 0u ? both.x : both.y;
}

#endif
