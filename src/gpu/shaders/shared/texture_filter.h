// Filtered face textures, the math both backends run (TextureSet::sample in
// src/voxel/texture_set.cpp, sampleTexture in voxel/texture_sample.glsl): the ray-cone footprint
// on a face, mip chain sizes and offsets, level of detail, anisotropic probe placement and
// wrapped texel addressing. Docs: docs/algorithms/voxel-textures.md.
//
// Based on: Akenine-Moller et al., "Texture Level of Detail Strategies for Real-Time Ray
// Tracing" (Ray Tracing Gems ch. 20, 2019) for the footprint; the probes along the major axis at
// the minor axis' level are the classic hardware approximation of the footprint integral
// (Schilling et al. 1996, "Texram"; EXT_texture_filter_anisotropic).
#ifndef LUXEL_GPU_SHARED_TEXTURE_FILTER_H
#define LUXEL_GPU_SHARED_TEXTURE_FILTER_H

#include "glsl_compat.h"

// Cosine of the incidence below which the footprint stops growing (major / minor <= 10^4).
#define LUXEL_TEXTURE_MIN_COS 1e-4f

// TextureFilter (texture_set.h) as numbers.
#define LUXEL_TEXTURE_NEAREST 0
#define LUXEL_TEXTURE_TRILINEAR 1
#define LUXEL_TEXTURE_ANISOTROPIC 2

LUXEL_SHARED_BEGIN

// The footprint ellipse's half-axes in face coordinates (one voxel face spans [0, 1)^2).
struct TexelFootprint {
    float majorU, majorV;
    float minorU, minorV;
};

// The footprint of a cone of width `width` arriving along `d` on the face with axis-aligned
// `normal`: the cone's circular cross-section projected along the ray onto the face plane, an
// ellipse with minor half-axis width / 2 and major half-axis (width / 2) / |cos(incidence)| along
// d projected on the face. (u, v) axes per face as voxelSurface (voxel_walk.h): x faces (z, y),
// y faces (x, z), z faces (x, y). Zero for a zero normal or width.
LUXEL_FUNC TexelFootprint textureFootprint(float width, vec3 d, ivec3 normal) {
    TexelFootprint f = TexelFootprint(0.0f, 0.0f, 0.0f, 0.0f);
    const int axis = normal.x != 0 ? 0 : (normal.y != 0 ? 1 : (normal.z != 0 ? 2 : -1));
    const float len = sqrt(dot(d, d));
    if (axis < 0 || !(width > 0.0f) || !(len > 0.0f)) return f;
    const int uAxis = axis == 0 ? 2 : 0;
    const int vAxis = axis == 1 ? 2 : 1;
    const float r = 0.5f * width;
    const float c = max(abs(d[axis]) / len, LUXEL_TEXTURE_MIN_COS);
    float pu = d[uAxis] / len;
    float pv = d[vAxis] / len;
    const float pl = sqrt(pu * pu + pv * pv);
    if (pl < 1e-6f) {  // head-on: a circle, axes along u and v
        f.majorU = r;
        f.minorV = r;
        return f;
    }
    pu /= pl;
    pv /= pl;
    const float m = r / c;
    f.majorU = m * pu;
    f.majorV = m * pv;
    f.minorU = -r * pv;
    f.minorV = r * pu;
    return f;
}

// Mip chains: level l of a side-s texture has max(1, s >> l) texels (box 2x2, exact area
// weights for odd sides), levels until both sides are 1.
LUXEL_FUNC int textureLevelCount(int width, int height) {
    return findMSB(max(max(width, height), 1)) + 1;
}
LUXEL_FUNC int textureLevelSide(int side, int level) {
    return max(side >> level, 1);
}
// First texel of `level` in a chain stored level after level, rows top to bottom.
LUXEL_FUNC uint textureLevelOffset(int width, int height, int level) {
    uint offset = 0u;
    for (int l = 0; l < level; ++l) {
        offset += uint(textureLevelSide(width, l)) * uint(textureLevelSide(height, l));
    }
    return offset;
}
LUXEL_FUNC uint textureChainTexels(int width, int height) {
    return textureLevelOffset(width, height, textureLevelCount(width, height));
}

// A half-axis (au, av) in face units as a length in level-0 texels.
LUXEL_FUNC float textureAxisTexels(float au, float av, int width, int height) {
    const float x = au * float(width);
    const float y = av * float(height);
    return sqrt(x * x + y * y);
}

// Level of detail of a filter footprint `diameter` level-0 texels across: log2(diameter), so a
// footprint one texel wide reads level 0 (not clamped: callers clamp to their chain).
LUXEL_FUNC float textureLod(float diameter) {
    return log(max(diameter, 1e-20f)) * 1.4426950408889634f;
}

// Anisotropic probes: N = min(ceil(major / minor), maxAnisotropy), at least 1.
LUXEL_FUNC int textureProbeCount(float major, float minor, int maxAnisotropy) {
    const int cap = max(maxAnisotropy, 1);
    if (!(major > 0.0f)) return 1;
    if (!(minor > 0.0f)) return cap;
    const float ratio = min(major / minor, float(cap));
    return clamp(int(ceil(ratio - 1e-4f)), 1, cap);
}

// Where probe i of n sits along the major axis, in units of the major half-axis: the centres of
// n equal segments of [-1, 1].
LUXEL_FUNC float textureProbeOffset(int i, int n) {
    return (2.0f * float(i) + 1.0f) / float(n) - 1.0f;
}

// Index i wrapped into [0, n): faces tile their texture, so a footprint crossing a face edge
// reads the texture's opposite edge (what a neighbour with the same texture shows).
LUXEL_FUNC int textureWrap(int i, int n) {
    const int m = i % n;
    return m < 0 ? m + n : m;
}

LUXEL_SHARED_END

#endif
