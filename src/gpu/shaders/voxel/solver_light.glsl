// The real-time solvers' light on the GPU, the twin of src/voxel/solver_sun.cpp and the
// radiance cascades' face lookups (RadianceCascades::indirectIrradiance, faceDirectSun) in float:
// sun rays through glass, the sun's light on a face's lobes over the disk's fixed spiral, the
// disk behind a delta lobe, the faces' table, their interpolated irradiance and the GGX albedo
// table. Needs the buffers of shared/cascade_picture_layout.h (`light`, `faceSlots`,
// `ggxAlbedo`) and `emitterFar` (shared/near_emitters.h), `path` (CascadePicturePush),
// castToSurface, walkMedium, materials[] and the path tracer's surface code (path_surface.glsl).
// The straight line through glass and water is line_transmittance.glsl.

#define LUXEL_SOLVER_INV_PI 0.31830988618379067

vec3 sunAxis() {
    return vec3(path.sunX, path.sunY, path.sunZ);
}

vec3 sunIrradiance() {
    return vec3(path.sunIrradianceR, path.sunIrradianceG, path.sunIrradianceB);
}

// The straight line through glass and water (line_transmittance.glsl) with the solvers' switches.
bool lineMedia() {
    const uint mediaFlags = LUXEL_PICTURE_REFRACTION | LUXEL_PICTURE_TRANSMISSION;
    return (path.materialFlags & mediaFlags) == mediaFlags;
}

float lineTransmission(VoxelMaterial m) {
    return (path.materialFlags & LUXEL_PICTURE_REFRACTION) != 0u ? m.transmission : 0.0;
}

// dielectricFresnel (path_trace_bsdf.cpp): from the air into `ior`; 0 for ior 1.
float lineFresnel(float cosI, float ior) {
    return ior == 1.0 ? 0.0 : pathFresnel(cosI, 1.0, ior);
}

#include "voxel/line_transmittance.glsl"

// sunRayTransmittance (solver_sun.h): 1 open, 0 blocked, a colour through glass.
vec3 sunRayTransmittance(vec3 origin, vec3 direction) {
    return lineTransmittance(origin, direction, false, ivec3(0), ivec3(0));
}

// solverSunLobes (solver_sun.h): the diffuse lobe and, when `glossy`, the smooth lobes of
// `specular` lit by the sun's disk over `sunRays` rays of its spiral (one for a delta sun). The
// rays take the first one's transmittance where it passed glass or water (its shareMedia, which
// the cascades' picture sets; the followed surfaces cast one ray).
vec3 solverSunLobes(Hit hit, vec3 diffuse, bool glossy, PathBsdf specular, int sunRays) {
    const vec3 irradiance = sunIrradiance();
    if (!(maxComponent(irradiance) > 0.0)) return vec3(0.0);
    if (!(maxComponent(diffuse) > 0.0) && !glossy) return vec3(0.0);
    const bool delta = !(path.sunOneMinusCos > 0.0);
    const int rays = delta ? 1 : max(sunRays, 1);
    const vec3 perRay = irradiance * path.sunOverPdfScale * (1.0 / float(rays));
    const vec3 n = vec3(hit.normal);
    const vec3 tangent = vec3(path.sunTangentX, path.sunTangentY, path.sunTangentZ);
    const vec3 bitangent = vec3(path.sunBitangentX, path.sunBitangentY, path.sunBitangentZ);
    const float golden = LUXEL_PATH_PI * (3.0 - sqrt(5.0));
    vec3 cosines = vec3(0.0), light = vec3(0.0);
    // The first ray's transmittance through a medium, shared by the rays after it (negative:
    // none).
    vec3 throughMedia = vec3(-1.0);
    for (int i = 0; i < rays; ++i) {
        // SunDisk::spiral: area-uniform rings turned by the golden angle.
        const vec3 l = delta ? sunAxis()
                             : pathConeDirection(sunAxis(), tangent, bitangent,
                                                 (float(i) + 0.5) / float(rays) *
                                                     path.sunOneMinusCos,
                                                 golden * float(i));
        const float cosSun = dot(n, l);
        if (!(cosSun > 0.0)) continue;
        vec3 t = throughMedia;
        if (!(throughMedia.x >= 0.0)) {
            t = sunRayTransmittance(hit.point, l);
            if (i == 0 && maxComponent(t) > 0.0 && maxComponent(t) < 1.0) throughMedia = t;
        }
        if (!(maxComponent(t) > 0.0)) continue;
        cosines += t * cosSun;
        if (glossy) light += pathBsdfLight(specular, l, perRay, 0.0) * t;
    }
    return diffuse * perRay * cosines * LUXEL_SOLVER_INV_PI + light;
}

// sunDiskAlong (solver_sun.h): the disk's radiance along a direction leaving a delta lobe.
vec3 sunDiskAlong(vec3 direction) {
    return pathConeContains(sunAxis(), path.sunOneMinusCos, direction)
               ? sunIrradiance() * path.sunRadianceScale
               : vec3(0.0);
}

// solverFollows (solver_surface.h): glass and water (refraction on) and polished metal.
bool solverFollows(SurfaceHit s) {
    const VoxelMaterial m = materials[materialIndex(voxelValue(s.hit.voxel))];
    const bool passes = (path.materialFlags & LUXEL_PICTURE_REFRACTION) != 0u &&
                        m.transmission > 0.0 && m.metallic < 1.0;
    return passes || (m.metallic > 0.0 && m.roughness <= LUXEL_PICTURE_FOLLOW_ROUGHNESS);
}

// solverRoughLobe (src/voxel/solver_surface.h): the met voxel's GGX lobe is rough, its
// roughness above that of the metals followed.
bool solverRoughLobe(SurfaceHit s) {
    return materials[materialIndex(voxelValue(s.hit.voxel))].roughness >
           LUXEL_PICTURE_FOLLOW_ROUGHNESS;
}

int normalIndex(ivec3 n) {
    if (n.x != 0) return n.x > 0 ? 0 : 1;
    if (n.y != 0) return n.y > 0 ? 2 : 3;
    return n.z > 0 ? 4 : 5;
}

// FaceTable::find: the face's id, or -1.
int findFace(ivec3 voxel, int normal) {
    if (voxel.x < 0 || voxel.y < 0 || voxel.z < 0 || voxel.x >= int(params.sizeX) ||
        voxel.y >= int(params.sizeY) || voxel.z >= int(params.sizeZ)) {
        return -1;
    }
    const uint keyLow = cascadeFaceKeyLow(voxel.x, voxel.y, normal), keyHigh = uint(voxel.z);
    uint slot = cascadeFaceHash(keyLow, keyHigh) & path.slotMask;
    for (uint probe = 0u; probe <= path.slotMask; ++probe) {
        const CascadeFaceSlot s = faceSlots[slot];
        if (s.id == LUXEL_PICTURE_EMPTY_SLOT) return -1;
        if (s.keyLow == keyLow && s.keyHigh == keyHigh) return int(s.id);
        slot = (slot + 1u) & path.slotMask;
    }
    return -1;
}

vec3 faceLight(uint section, int face) {
    return texelRgb(light[section * path.faces + uint(face)]);
}

// interpolatedIrradiance (RadianceCascades::indirectIrradiance): the faces' irradiance plus their
// emitter irradiance (`far`: its far share, `emitterFar`, for the picture's own surface),
// bilinear between the centres of this face and its open neighbours in the plane (a diagonal one
// only through an open side neighbour).
vec3 interpolatedIrradiance(Hit hit, bool far) {
    const int n = normalIndex(hit.normal), axis = n / 2, a = (axis + 1) % 3, b = (axis + 2) % 3;
    const float fa = hit.point[a] - float(hit.voxel[a]) - 0.5;
    const float fb = hit.point[b] - float(hit.voxel[b]) - 0.5;
    const int da = fa < 0.0 ? -1 : 1, db = fb < 0.0 ? -1 : 1;
    const float wa = abs(fa), wb = abs(fb);
    ivec3 va = hit.voxel, vb = hit.voxel;
    va[a] += da;
    vb[b] += db;
    ivec3 vab = va;
    vab[b] += db;
    const int self = findFace(hit.voxel, n), sideA = findFace(va, n), sideB = findFace(vb, n);
    const int diagonal = (sideA >= 0 || sideB >= 0) ? findFace(vab, n) : -1;
    const int ids[4] = int[4](self, sideA, sideB, diagonal);
    const float weights[4] =
        float[4]((1.0 - wa) * (1.0 - wb), wa * (1.0 - wb), (1.0 - wa) * wb, wa * wb);
    vec3 sum = vec3(0.0);
    float total = 0.0;
    for (int i = 0; i < 4; ++i) {
        if (ids[i] < 0) continue;
        const vec3 emitter = far ? texelRgb(emitterFar[ids[i]])
                                 : faceLight(LUXEL_FACE_EMITTER, ids[i]);
        sum += (faceLight(LUXEL_FACE_IRRADIANCE, ids[i]) + emitter) * weights[i];
        total += weights[i];
    }
    return total > 0.0 ? sum * (1.0 / total) : vec3(0.0);
}

vec3 indirectIrradiance(Hit hit) {
    return interpolatedIrradiance(hit, false);
}

// directionalAlbedoGgx (ggx_albedo.h): the table bilinear over cosView and alpha in [0, 1].
float directionalAlbedoGgx(float cosView, float alpha) {
    const int side = LUXEL_PICTURE_ALBEDO_SIDE;
    const float x = clamp(cosView, 0.0, 1.0) * float(side - 1);
    const float y = clamp(alpha, 0.0, 1.0) * float(side - 1);
    const int i = min(int(x), side - 2), j = min(int(y), side - 2);
    const float fx = x - float(i), fy = y - float(j);
    const float a = ggxAlbedo[i * side + j], b = ggxAlbedo[i * side + j + 1];
    const float c = ggxAlbedo[(i + 1) * side + j], d = ggxAlbedo[(i + 1) * side + j + 1];
    return (a * (1.0 - fy) + b * fy) * (1.0 - fx) + (c * (1.0 - fy) + d * fy) * fx;
}
