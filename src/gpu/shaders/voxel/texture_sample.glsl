// Filtered face textures on the GPU: the twin of TextureSet::sample / normalAt
// (src/voxel/texture_set.cpp), with the shared formulas of shared/texture_filter.h (footprint,
// levels, probes, wrapping). Needs the `textureInfo` and `texels` buffers (voxel_layout.h) and
// `params` (VoxelRenderParams: textureFilter, maxAnisotropy).
#include "shared/texture_filter.h"
#include "shared/voxel_shading.h"

// Texel (column, row from the bottom) of one level of a chain, wrapped.
vec4 chainTexel(uint base, int w, int h, int column, int rowFromBottom) {
    const int c = textureWrap(column, w);
    const int r = h - 1 - textureWrap(rowFromBottom, h);
    return texels[base + uint(r * w + c)];
}

vec4 chainBilinear(uint chain, int width, int height, int level, float u, float v) {
    const int w = textureLevelSide(width, level), h = textureLevelSide(height, level);
    const uint base = chain + textureLevelOffset(width, height, level);
    const float x = u * float(w) - 0.5, y = v * float(h) - 0.5;
    const float fx0 = floor(x), fy0 = floor(y);
    const int x0 = int(fx0), y0 = int(fy0);
    const float ax = x - fx0, ay = y - fy0;
    vec4 r = chainTexel(base, w, h, x0, y0) * ((1.0 - ax) * (1.0 - ay));
    r += chainTexel(base, w, h, x0 + 1, y0) * (ax * (1.0 - ay));
    r += chainTexel(base, w, h, x0, y0 + 1) * ((1.0 - ax) * ay);
    r += chainTexel(base, w, h, x0 + 1, y0 + 1) * (ax * ay);
    return r;
}

vec4 chainTrilinear(uint chain, int width, int height, int levels, float u, float v, float lod) {
    const float l = clamp(lod, 0.0, float(levels - 1));
    const int l0 = int(floor(l));
    const int l1 = min(l0 + 1, levels - 1);
    const float f = l - float(l0);
    vec4 a = chainBilinear(chain, width, height, l0, u, v);
    if (f <= 0.0 || l1 == l0) return a;
    return a * (1.0 - f) + chainBilinear(chain, width, height, l1, u, v) * f;
}

// filterChain in texture_set.cpp: trilinear at the major axis' level, or probes along it.
vec4 filterChain(uint chain, int width, int height, int levels, float u, float v,
                 TexelFootprint fp, int mode, int maxAnisotropy) {
    float major = textureAxisTexels(fp.majorU, fp.majorV, width, height);
    float minor = textureAxisTexels(fp.minorU, fp.minorV, width, height);
    float mu = fp.majorU, mv = fp.majorV;
    if (minor > major) {
        const float t = major;
        major = minor;
        minor = t;
        mu = fp.minorU;
        mv = fp.minorV;
    }
    if (mode == LUXEL_TEXTURE_TRILINEAR) {
        return chainTrilinear(chain, width, height, levels, u, v, textureLod(2.0 * major));
    }
    const int n = textureProbeCount(major, minor, maxAnisotropy);
    const float lod = textureLod(2.0 * max(minor, major / float(n)));
    vec4 sum = vec4(0.0);
    for (int i = 0; i < n; ++i) {
        const float s = textureProbeOffset(i, n);
        sum += chainTrilinear(chain, width, height, levels, u + s * mu, v + s * mv, lod);
    }
    return sum * (1.0 / float(n));
}

// The nearest texel (TextureSet::lookup): cutout decisions always read this one.
vec4 nearestTexel(int slot, float u, float v) {
    const VoxelTextureInfo info = textureInfo[slot];
    const int w = int(info.width), h = int(info.height);
    const int row = h - 1 - voxelTexelIndex(v, h);
    return texels[info.texelOffset + uint(row * w + voxelTexelIndex(u, w))];
}

// TextureSet::sample with an explicit filter mode (LUXEL_TEXTURE_*).
vec4 sampleTextureWith(int slot, float u, float v, TexelFootprint fp, int mode,
                       int maxAnisotropy) {
    if (mode == LUXEL_TEXTURE_NEAREST) return nearestTexel(slot, u, v);
    const VoxelTextureInfo info = textureInfo[slot];
    const vec4 p = filterChain(info.mipOffset, int(info.width), int(info.height),
                               int(info.levels), u, v, fp, mode, maxAnisotropy);
    if (!(p.w > 1e-6)) return nearestTexel(slot, u, v);
    return vec4(p.x / p.w, p.y / p.w, p.z / p.w, min(p.w, 1.0));
}

// The render's mode (params.textureFilter, params.maxAnisotropy).
vec4 sampleTexture(int slot, float u, float v, TexelFootprint fp) {
    return sampleTextureWith(slot, u, v, fp, int(params.textureFilter),
                             int(params.maxAnisotropy));
}

// TextureSet::normalAt: tangent-space unit normal, (0, 0, 1) without a normal map.
vec3 sampleNormalWith(int slot, float u, float v, TexelFootprint fp, int mode,
                      int maxAnisotropy) {
    const VoxelTextureInfo info = textureInfo[slot];
    if (info.hasNormalMap == 0u) return vec3(0.0, 0.0, 1.0);
    const int w = int(info.width), h = int(info.height);
    vec4 n;
    if (mode == LUXEL_TEXTURE_NEAREST) {
        n = chainTexel(info.normalOffset, w, h, voxelTexelIndex(u, w), voxelTexelIndex(v, h));
    } else {
        n = filterChain(info.normalOffset, w, h, int(info.levels), u, v, fp, mode,
                        maxAnisotropy);
    }
    const vec3 m = vec3(n.x, n.y, n.z);
    const float len = length(m);
    return len > 1e-6 ? m / len : vec3(0.0, 0.0, 1.0);
}

vec3 sampleNormal(int slot, float u, float v, TexelFootprint fp) {
    return sampleNormalWith(slot, u, v, fp, int(params.textureFilter), int(params.maxAnisotropy));
}
