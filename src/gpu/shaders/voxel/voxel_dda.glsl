// Amanatides & Woo traversal with exact empty-chunk jumps, in float: a line-by-line port of
// castRay (src/voxel/dda.cpp), same start-cell, tie, normal and chunk-jump rules. Needs
// `params` (VoxelRenderParams), `voxels[]` and `chunkSolid[]` declared by the includer.

const float kInfinity = 1.0 / 0.0;
const float kBelowOne = 0.99999994039535522;  // nextafter(1, 0) = 1 - 2^-24

struct Hit {
    bool hit;
    ivec3 voxel;
    ivec3 normal;
    float t;
    vec3 point;
    float u, v;
};

Hit missHit() {
    return Hit(false, ivec3(0), ivec3(0), kInfinity, vec3(0.0), 0.0, 0.0);
}

ivec3 worldSize() {
    return ivec3(params.sizeX, params.sizeY, params.sizeZ);
}

uint chunkIndex(ivec3 cell) {
    const int shift = int(params.chunkShift);
    return (uint(cell.z >> shift) * params.chunksY + uint(cell.y >> shift)) * params.chunksX +
           uint(cell.x >> shift);
}

// The packed voxel at a cell inside the world (VoxelWorld::index).
uint voxelAt(ivec3 cell) {
    const int shift = int(params.chunkShift);
    const int mask = (1 << shift) - 1;
    const uint side = 1u << shift;
    const uint local = (uint(cell.z & mask) * side + uint(cell.y & mask)) * side + uint(cell.x & mask);
    return (chunkIndex(cell) << (3 * shift)) + local;
}

uint voxelValue(ivec3 cell) {
    return voxels[voxelAt(cell)];
}

// t at which the ray leaves `cell` on one axis; the one formula for every boundary (dda.cpp).
float exitT(int cell, int stp, float o, float d) {
    float t = (float(cell + (stp > 0 ? 1 : 0)) - o) / d;
    return t;
}

float fraction(float p, int cell) {
    return clamp(p - float(cell), 0.0, kBelowOne);
}

Hit makeHit(vec3 o, vec3 d, ivec3 cell, float t, int axis, ivec3 stp) {
    Hit h = missHit();
    h.hit = true;
    h.voxel = cell;
    h.t = t;
    for (int a = 0; a < 3; ++a) {
        float p = t == 0.0 ? o[a] : o[a] + t * d[a];
        h.point[a] = clamp(p, float(cell[a]), float(cell[a]) + 1.0);
    }
    if (axis >= 0) {
        h.normal[axis] = -stp[axis];
        h.point[axis] = float(cell[axis] + (stp[axis] > 0 ? 0 : 1));
    }
    int uAxis = 0, vAxis = 2;
    if (axis == 0) uAxis = 2, vAxis = 1;
    if (axis == 2) uAxis = 0, vAxis = 1;
    h.u = fraction(h.point[uAxis], cell[uAxis]);
    h.v = fraction(h.point[vAxis], cell[vAxis]);
    return h;
}

bool finite3(vec3 v) {
    return !any(isnan(v)) && !any(isinf(v));
}

Hit castRay(vec3 o, vec3 d) {
    Hit miss = missHit();
    const ivec3 size = worldSize();
    if (!finite3(o) || !finite3(d) || (d.x == 0.0 && d.y == 0.0 && d.z == 0.0)) return miss;
    const int cap = int(params.stepCap);

    float tEnter = -kInfinity, tExit = kInfinity;
    int enterAxis = -1;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0) {
            if (!(o[a] >= 0.0 && o[a] < float(size[a]))) return miss;
            continue;
        }
        float ta = (0.0 - o[a]) / d[a];
        float tb = (float(size[a]) - o[a]) / d[a];
        if (ta > tb) {
            const float swap = ta;
            ta = tb;
            tb = swap;
        }
        if (ta >= tEnter) {
            tEnter = ta;
            enterAxis = a;
        }
        tExit = min(tExit, tb);
    }
    const float t0 = max(tEnter, 0.0);
    if (tEnter > tExit || tExit < t0 || (tExit == t0 && tEnter < t0)) return miss;

    ivec3 stp;
    ivec3 cell;
    const bool fromOutside = tEnter >= 0.0;
    for (int a = 0; a < 3; ++a) {
        stp[a] = d[a] > 0.0 ? 1 : (d[a] < 0.0 ? -1 : 0);
        if (fromOutside && a == enterAxis) {
            cell[a] = stp[a] > 0 ? 0 : size[a] - 1;
            continue;
        }
        float p = t0 == 0.0 ? o[a] : o[a] + t0 * d[a];
        float f = floor(p);
        if (p == f && stp[a] < 0) f -= 1.0;
        cell[a] = int(clamp(f, 0.0, float(size[a] - 1)));
    }

    int axis = -1;
    if (fromOutside) {
        axis = enterAxis;
    } else {
        float best = -kInfinity;
        for (int a = 0; a < 3; ++a) {
            if (stp[a] == 0) continue;
            const float te = exitT(cell[a], -stp[a], o[a], d[a]);
            if (te >= best) {
                best = te;
                axis = a;
            }
        }
        if (!(best >= 0.0)) axis = -1;
    }

    vec3 next;
    for (int a = 0; a < 3; ++a) next[a] = stp[a] != 0 ? exitT(cell[a], stp[a], o[a], d[a]) : kInfinity;

    const int shift = int(params.chunkShift);
    float t = t0;
    int steps = 0;
    for (;;) {
        if (steps >= cap) return miss;
        ++steps;
        if (chunkSolid[chunkIndex(cell)] == 0u) {
            // Jump to where the plain traversal leaves this empty chunk (dda.cpp).
            int a = -1;
            float tJump = kInfinity;
            ivec3 chunkLo, chunkHi;
            for (int b = 0; b < 3; ++b) {
                const int lo = (cell[b] >> shift) << shift;
                const int hi = min(lo + (1 << shift), size[b]) - 1;
                chunkLo[b] = lo;
                chunkHi[b] = hi;
                if (stp[b] == 0) continue;
                const float tb = exitT(stp[b] > 0 ? hi : lo, stp[b], o[b], d[b]);
                if (tb < tJump) {
                    tJump = tb;
                    a = b;
                }
            }
            if (a < 0 || tJump == kInfinity) return miss;
            for (int b = 0; b < 3; ++b) {
                if (b == a || stp[b] == 0) continue;
                const int first = cell[b];
                const int last = stp[b] > 0 ? chunkHi[b] : chunkLo[b];
                const float p = o[b] + tJump * d[b];
                int c = int(clamp(floor(p), -1.0, float(size[b]) + 1.0));
                c = stp[b] > 0 ? clamp(c, first, last) : clamp(c, last, first);
                // crossed(tb) = tb < tJump || (tb == tJump && b < a)
                for (;;) {
                    if (c == first) break;
                    const float tb = exitT(c - stp[b], stp[b], o[b], d[b]);
                    if (tb < tJump || (tb == tJump && b < a)) break;
                    c -= stp[b];
                }
                for (;;) {
                    if (c == last) break;
                    const float tb = exitT(c, stp[b], o[b], d[b]);
                    if (!(tb < tJump || (tb == tJump && b < a))) break;
                    c += stp[b];
                }
                cell[b] = c;
                next[b] = exitT(c, stp[b], o[b], d[b]);
            }
            t = tJump;
            cell[a] = stp[a] > 0 ? chunkHi[a] + 1 : chunkLo[a] - 1;
            axis = a;
            if (cell[a] < 0 || cell[a] >= size[a]) return miss;
            next[a] = exitT(cell[a], stp[a], o[a], d[a]);
            continue;
        }
        if ((voxelValue(cell) >> 24) != 0u) return makeHit(o, d, cell, t, axis, stp);
        const int a = next[0] <= next[1] ? (next[0] <= next[2] ? 0 : 2) : (next[1] <= next[2] ? 1 : 2);
        if (next[a] == kInfinity) return miss;
        t = next[a];
        cell[a] += stp[a];
        axis = a;
        if (cell[a] < 0 || cell[a] >= size[a]) return miss;
        next[a] = exitT(cell[a], stp[a], o[a], d[a]);
    }
    return miss;
}
