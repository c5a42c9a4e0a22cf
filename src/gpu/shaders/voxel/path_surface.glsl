// The voxel path tracer's surface response on the GPU: what a hit face reflects and emits, what
// it reflects towards the eye from a light direction (next event estimation), its bounce density
// (multiple importance sampling) and its bounce sample. Every material is Lambertian for now, as
// on the CPU (src/voxel/path_trace.cpp, path_trace_surface.h); other materials change these
// functions alone. Needs castToSurface's SurfaceHit, albedo(), textureFactor() and materials[]
// (voxel_shading.glsl, voxel_physical.glsl's materialIndex).

const float kPathPi = 3.14159265358979323846;

struct PathSurface {
    vec3 albedo;
    vec3 emission;
};

// pathSurfaceAt (path_trace.cpp): voxel colour x material albedo x texel x procedural texture.
PathSurface pathSurfaceAt(SurfaceHit s) {
    const uint packed = voxelValue(s.hit.voxel);
    const VoxelMaterial m = materials[materialIndex(packed)];
    vec3 colour = albedo(packed) * vec3(m.albedoR, m.albedoG, m.albedoB);
    if (s.slot >= 0) colour = colour * s.texel.rgb;
    const bool own = (m.flags & LUXEL_VOXEL_MATERIAL_OWN) != 0u;
    const bool procedural = (m.flags & LUXEL_VOXEL_MATERIAL_PROCEDURAL) != 0u;
    if ((params.flags & LUXEL_VOXEL_PROCEDURAL_TEXTURE) != 0u &&
        (s.slot < 0 ? !own || procedural : own && procedural)) {
        colour = colour * textureFactor(s.hit);
    }
    return PathSurface(colour, vec3(m.emissionR, m.emissionG, m.emissionB));
}

// f cos: the radiance reflected towards `towardsEye` per unit irradiance arriving square to
// `towardsLight` (both unit, leaving the face); 0 below the face.
vec3 pathSurfaceReflect(PathSurface s, ivec3 normal, vec3 towardsEye, vec3 towardsLight) {
    const float cosLight = dot(vec3(normal), towardsLight);
    return cosLight > 0.0 ? s.albedo * (cosLight / kPathPi) : vec3(0.0);
}

// The solid-angle density with which pathSurfaceBounce picks `towardsLight`.
float pathSurfacePdf(PathSurface s, ivec3 normal, vec3 towardsEye, vec3 towardsLight) {
    return max(dot(vec3(normal), towardsLight), 0.0) / kPathPi;
}

struct PathBounce {
    vec3 direction;  // unit, leaving the face
    vec3 weight;     // f cos / pdf
    float pdf;       // solid angle density
};

// A bounce direction from two uniform numbers in [0, 1): cosine-weighted about the normal
// (cosineDirection in path_trace.cpp), so f cos / pdf = albedo.
PathBounce pathSurfaceBounce(PathSurface s, ivec3 normal, vec3 towardsEye, float u1, float u2) {
    const vec3 n = vec3(normal);
    vec3 tu = vec3(0.0, 0.0, 1.0), tv = vec3(0.0, 1.0, 0.0);
    if (normal.y != 0) {
        tu = vec3(1.0, 0.0, 0.0);
        tv = vec3(0.0, 0.0, 1.0);
    } else if (normal.z != 0) {
        tu = vec3(1.0, 0.0, 0.0);
        tv = vec3(0.0, 1.0, 0.0);
    }
    const float r = sqrt(u1), phi = 2.0 * kPathPi * u2;
    const float z = sqrt(1.0 - u1);  // u1 < 1: the ray leaves the face
    const vec3 d = tu * (r * cos(phi)) + tv * (r * sin(phi)) + n * z;
    return PathBounce(d, s.albedo, dot(n, d) / kPathPi);
}
