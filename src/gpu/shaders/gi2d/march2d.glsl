// The exact 2D DDA through the pixel medium that the GPU passes share (hrc_trace for the HRC base
// intervals, rc_cascade for the RC intervals): every crossed pixel contributes with its exact
// segment length, L += T E (1 - exp(-sigma l)), T *= exp(-sigma l). The CPU counterpart is
// RayMarcher (src/gi2d/ray_march.cpp), which skips uniform blocks; the parity tests of both passes
// bound the difference. Needs `medium[]` (MediumTexel) declared by the includer, and
// `uint mediumIndex(ivec2 cell, uint width)`, the element of medium[] that holds pixel `cell` of the
// width x height grid being marched.

struct Marched {
    vec3 radiance;
    vec3 transmittance;
};

// From `start` (inside the width x height medium) along the unit direction `dir` for `span`
// pixels, stopping at the medium's edge (empty beyond) or once every channel's transmittance is
// below `cutoff`. `depthScale` multiplies the length counted in every crossed pixel (RayMarcher's
// depthScale: HRC's cascade-0 rays).
Marched marchMedium(vec2 start, vec2 dir, float span, uint width, uint height, float cutoff,
                    float depthScale) {
    Marched s = Marched(vec3(0.0), vec3(1.0));
    ivec2 cell = min(ivec2(floor(start)), ivec2(width - 1u, height - 1u));
    const ivec2 stepDir = ivec2(dir.x > 0.0 ? 1 : -1, dir.y > 0.0 ? 1 : -1);
    const vec2 inv = vec2(dir.x != 0.0 ? 1.0 / abs(dir.x) : 1e30,
                          dir.y != 0.0 ? 1.0 / abs(dir.y) : 1e30);
    vec2 next;
    next.x = dir.x > 0.0 ? (float(cell.x + 1) - start.x) * inv.x
           : dir.x < 0.0 ? (start.x - float(cell.x)) * inv.x : 1e30;
    next.y = dir.y > 0.0 ? (float(cell.y + 1) - start.y) * inv.y
           : dir.y < 0.0 ? (start.y - float(cell.y)) * inv.y : 1e30;
    float t = 0.0;
    while (t < span) {
        if (cell.x < 0 || cell.y < 0 || cell.x >= int(width) || cell.y >= int(height)) break;
        if (max(s.transmittance.x, max(s.transmittance.y, s.transmittance.z)) < cutoff) break;
        const float exit = min(min(next.x, next.y), span);
        const MediumTexel m = medium[mediumIndex(cell, width)];
        const vec3 tr = exp(-mediumSigma(m) * ((exit - t) * depthScale));
        s.radiance += s.transmittance * mediumEmission(m) * (vec3(1.0) - tr);
        s.transmittance *= tr;
        t = exit;
        if (next.x <= next.y) {
            cell.x += stepDir.x;
            next.x += inv.x;
        } else {
            cell.y += stepDir.y;
            next.y += inv.y;
        }
    }
    return s;
}
