// Buffer reads shared by the post passes: `src` is the image being sampled (RGB floats).
vec3 srcTexel(int x, int y) {
    const uint i = (uint(y) * params.srcWidth + uint(x)) * 3u;
    return vec3(src[i], src[i + 1u], src[i + 2u]);
}

vec3 srcBilinear(vec2 p) {
    const PostBilinear b = postBilinearAt(p, int(params.srcWidth), int(params.srcHeight));
    const vec3 top = mix(srcTexel(b.x0, b.y0), srcTexel(b.x1, b.y0), b.tx);
    const vec3 bottom = mix(srcTexel(b.x0, b.y1), srcTexel(b.x1, b.y1), b.tx);
    return mix(top, bottom, b.ty);
}

void storeDst(int x, int y, vec3 c) {
    const uint i = (uint(y) * params.dstWidth + uint(x)) * 3u;
    dst[i] = c.x;
    dst[i + 1u] = c.y;
    dst[i + 2u] = c.z;
}
