// Shared GLSL for the HRC passes: intervals, binary16 table entries, frame medium access.
#ifndef LUXEL_HRC_COMMON_GLSL
#define LUXEL_HRC_COMMON_GLSL

struct Interval {
    vec3 radiance;
    vec3 transmittance;
};

Interval emptyInterval() { return Interval(vec3(0.0), vec3(1.0)); }

Interval over(Interval near, Interval far) {
    return Interval(near.radiance + near.transmittance * far.radiance,
                    near.transmittance * far.transmittance);
}

// Entry layout: HrcTableEntry in src/gpu/shaders/shared/hrc_layout.h.
Interval unpackEntry(HrcTableEntry e) {
    const vec2 a = unpackHalf2x16(e.radianceRG), b = unpackHalf2x16(e.radianceBTransmittanceR),
               c = unpackHalf2x16(e.transmittanceGB);
    return Interval(vec3(a.x, a.y, b.x), vec3(b.y, c.x, c.y));
}

HrcTableEntry packEntry(Interval v) {
    return HrcTableEntry(packHalf2x16(v.radiance.xy),
                         packHalf2x16(vec2(v.radiance.z, v.transmittance.x)),
                         packHalf2x16(v.transmittance.yz));
}

// Entry (p, k, y) of T_level.
uint tableIndex(uint level, uint p, uint k, uint y, uint rows) {
    return (p * ((1u << level) + 1u) + k) * rows + y;
}

#endif
