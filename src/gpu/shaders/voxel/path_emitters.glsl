// Emissive voxels as lights on the GPU: the twin of PathEmitters::sample and ::pdf
// (src/voxel/path_trace_emitters.cpp) in float. Needs `emitters[]` (binding 15) and `path`
// (PathTracePush: the emitter count).

// The faces of `voxel` whose outward side holds `point`: up to three outward normals.
int pathFacingFaces(vec3 point, ivec3 voxel, out ivec3 faces[3]) {
    int count = 0;
    for (int a = 0; a < 3; ++a) {
        ivec3 n = ivec3(0);
        if (point[a] > float(voxel[a]) + 1.0) {
            n[a] = 1;
        } else if (point[a] < float(voxel[a])) {
            n[a] = -1;
        } else {
            continue;
        }
        faces[count++] = n;
    }
    return count;
}

int pathAxisOf(ivec3 normal) {
    return normal.x != 0 ? 0 : normal.y != 0 ? 1 : 2;
}

struct PathLightSample {
    ivec3 voxel;
    ivec3 normal;    // the face's outward normal
    vec3 direction;  // unit, from the shading point to the sampled point
    float pdf;       // solid angle density; 0: no face of the voxel faces the point
};

// An emitter chosen uniformly, one of its faces that face `point` uniformly, a uniform point on
// that face.
PathLightSample pathSampleEmitter(vec3 point, float u0, float u1, float u2, float u3) {
    PathLightSample s = PathLightSample(ivec3(0), ivec3(0), vec3(0.0), 0.0);
    const int n = int(path.emitters);
    const PathEmitterVoxel e = emitters[min(int(u0 * float(n)), n - 1)];
    s.voxel = ivec3(e.x, e.y, e.z);
    ivec3 faces[3];
    const int k = pathFacingFaces(point, s.voxel, faces);
    if (k == 0) return s;
    s.normal = faces[min(int(u1 * float(k)), k - 1)];
    const int a = pathAxisOf(s.normal), b = (a + 1) % 3, c = (a + 2) % 3;
    vec3 q;
    q[a] = float(s.voxel[a]) + (s.normal[a] > 0 ? 1.0 : 0.0);
    q[b] = float(s.voxel[b]) + u2;
    q[c] = float(s.voxel[c]) + u3;
    const vec3 d = q - point;
    const float distance = length(d);
    if (!(distance > 0.0)) return s;
    s.direction = d / distance;
    const float cosLight = abs(s.direction[a]);
    if (!(cosLight > 0.0)) return s;
    s.pdf = distance * distance / (cosLight * float(n) * float(k));
    return s;
}

// The density pathSampleEmitter gives, from `point`, to the point `hit` on face `normal` of
// `voxel`.
float pathEmitterPdf(vec3 point, ivec3 voxel, ivec3 normal, vec3 hit) {
    ivec3 faces[3];
    const int k = pathFacingFaces(point, voxel, faces);
    bool facing = false;
    for (int i = 0; i < k; ++i) facing = facing || faces[i] == normal;
    if (!facing) return 0.0;
    const vec3 d = hit - point;
    const float d2 = dot(d, d);
    const float cosLight = abs(d[pathAxisOf(normal)]) / sqrt(d2);
    if (!(cosLight > 0.0)) return 0.0;
    return d2 / (cosLight * float(path.emitters) * float(k));
}
