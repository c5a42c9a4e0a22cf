// The voxel path tracer's surface response on the GPU, the twin of src/voxel/path_trace_bsdf.cpp
// in float: what a hit face reflects and emits, its three lobes (GGX or mirror specular, delta
// transmission, Fresnel-weighted diffuse), the bounce sample and the light a smooth lobe sends
// towards the eye from a light sample, weighted per lobe by the power heuristic. The float
// kernels are shared/path_bsdf.h. Needs castToSurface's SurfaceHit, albedo(), textureFactor(),
// materials[] and materialIndex() (voxel_shading.glsl, voxel_physical.glsl), `path`
// (PathTracePush) and pathRngNext (shared/path_rng.h).
#include "shared/face_frame.h"

struct PathSurface {
    vec3 albedo;
    vec3 emission;
    int material;  // index into materials[]
};

// pathSurfaceAt (path_trace.cpp): voxel colour x material albedo x texel x procedural texture.
PathSurface pathSurfaceAt(SurfaceHit s) {
    const uint packed = voxelValue(s.hit.voxel);
    const int index = materialIndex(packed);
    const VoxelMaterial m = materials[index];
    vec3 colour = albedo(packed) * vec3(m.albedoR, m.albedoG, m.albedoB);
    if (s.slot >= 0) colour = colour * s.texel.rgb;
    const bool own = (m.flags & LUXEL_VOXEL_MATERIAL_OWN) != 0u;
    const bool procedural = (m.flags & LUXEL_VOXEL_MATERIAL_PROCEDURAL) != 0u;
    if ((params.flags & LUXEL_VOXEL_PROCEDURAL_TEXTURE) != 0u &&
        (s.slot < 0 ? !own || procedural : own && procedural)) {
        colour = colour * textureFactor(s.hit);
    }
    return PathSurface(colour, vec3(m.emissionR, m.emissionG, m.emissionB), index);
}

// The dielectric Fresnel reflectance from index nI into nT, exact or Schlick as the options say.
float pathFresnel(float cosI, float nI, float nT) {
    return (path.materialFlags & LUXEL_PATH_FRESNEL_EXACT) != 0u
               ? fresnelDielectricExact(cosI, nI, nT)
               : fresnelDielectricSchlick(cosI, nI, nT);
}

// PathBsdf (path_trace_bsdf.h): the lobe weights and their selection probabilities.
struct PathBsdf {
    ivec3 normal;
    vec3 view;  // unit, from the hit back along the incoming ray
    float cosView;
    vec3 specular;
    vec3 diffuse;
    float transmission;
    float alpha;  // GGX alpha; < LUXEL_PATH_MIRROR_ALPHA: a mirror
    float ior;
    float pSpecular, pTransmission, pDiffuse;
};

bool pathMirror(PathBsdf b) {
    return b.alpha < LUXEL_PATH_MIRROR_ALPHA;
}

// Whether a lobe can reflect light from a given direction (next event estimation applies).
bool pathSmooth(PathBsdf b) {
    return b.pDiffuse > 0.0 || (b.pSpecular > 0.0 && !pathMirror(b));
}

// pathBsdf (path_trace_bsdf.cpp) for the surface `s` hit along unit `direction`.
PathBsdf pathBsdfAt(PathSurface s, ivec3 normal, vec3 direction) {
    const VoxelMaterial m = materials[s.material];
    PathBsdf b;
    b.normal = normal;
    b.view = -direction;
    b.cosView = clamp(dot(vec3(normal), b.view), 0.0, 1.0);
    b.alpha = m.roughness * m.roughness;
    b.ior = m.ior;
    // No index contrast, no interface to reflect.
    const float fresnel = m.ior == 1.0 ? 0.0 : pathFresnel(b.cosView, 1.0, m.ior);
    const float dielectric = 1.0 - m.metallic;
    const float transmission =
        (path.materialFlags & LUXEL_PATH_REFRACTION) != 0u ? m.transmission : 0.0;
    b.specular = fresnelSchlickRgb(s.albedo, b.cosView) * m.metallic + vec3(dielectric * fresnel);
    b.transmission = dielectric * (1.0 - fresnel) * transmission;
    b.diffuse = s.albedo * (dielectric * (1.0 - fresnel) * (1.0 - transmission));
    const float sMean = (b.specular.x + b.specular.y + b.specular.z) / 3.0;
    const float dMean = (b.diffuse.x + b.diffuse.y + b.diffuse.z) / 3.0;
    const float total = sMean + b.transmission + dMean;
    b.pSpecular = 0.0;
    b.pTransmission = 0.0;
    b.pDiffuse = 0.0;
    if (total > 0.0) {
        b.pSpecular = sMean / total;
        b.pTransmission = b.transmission / total;
        b.pDiffuse = dMean / total;
    }
    return b;
}

// The density with which the visible-normal sampling finds l: G1(v) D(h) / (4 cos_v). The
// half vector's sin^2 is its tangential part squared (exact for an axis-aligned normal).
float pathGgxPdf(PathBsdf b, vec3 l) {
    const vec3 n = vec3(b.normal);
    const vec3 h = normalize(b.view + l);
    const float cosH = dot(n, h);
    if (!(cosH > 0.0)) return 0.0;
    const vec3 across = h - n * cosH;
    return pathGgxMasking(b.cosView, b.alpha) * pathGgxD(cosH, dot(across, across), b.alpha) /
           (4.0 * b.cosView);
}

// bsdfLight (path_trace_bsdf.cpp): light of `radiance` from unit l that the smooth lobes send
// towards the view, f cos L / lightPdf, each lobe weighted by the power heuristic against its
// own sampling; lightPdf = 0 is a delta light.
vec3 pathBsdfLight(PathBsdf b, vec3 l, vec3 radiance, float lightPdf) {
    const vec3 n = vec3(b.normal);
    const float cosL = dot(n, l);
    if (!(cosL > 0.0)) return vec3(0.0);
    const bool deltaLight = !(lightPdf > 0.0);
    const float divide = deltaLight ? 1.0 : lightPdf;
    vec3 result = vec3(0.0);
    if (b.pDiffuse > 0.0) {
        const float w =
            deltaLight ? 1.0 : pathPowerHeuristic(lightPdf, b.pDiffuse * (cosL / LUXEL_PATH_PI));
        result = b.diffuse * radiance * (cosL / LUXEL_PATH_PI * w / divide);
    }
    if (b.pSpecular > 0.0 && !pathMirror(b) && b.cosView > 0.0) {
        const float w = deltaLight ? 1.0 : pathPowerHeuristic(lightPdf, b.pSpecular * pathGgxPdf(b, l));
        const float reflectance = pathGgxReflectance(n, b.view, l, b.cosView, cosL, b.alpha);
        result += b.specular * radiance * (reflectance * cosL * w / divide);
    }
    return result;
}

// The face's tangents (cosineDirection's and the GGX frame of path_trace_bsdf.cpp).
void pathFaceFrame(ivec3 normal, out vec3 tu, out vec3 tv) {
    tu = faceTangentU(normal);
    tv = faceTangentV(normal);
}

#define LUXEL_PATH_LOBE_NONE 0
#define LUXEL_PATH_LOBE_DIFFUSE 1
#define LUXEL_PATH_LOBE_SPECULAR 2
#define LUXEL_PATH_LOBE_TRANSMISSION 3

struct PathBounce {
    int lobe;        // LUXEL_PATH_LOBE_*; NONE: the path ends
    vec3 direction;  // unit
    vec3 weight;     // f cos / (probability x density)
    float pdf;       // probability x density in solid angle; 0 for the delta lobes
};

// sampleBsdf (path_trace_bsdf.cpp): one number for the lobe when more than one lobe can be
// picked, then two for the direction of a diffuse or GGX lobe.
PathBounce pathSampleBsdf(PathBsdf b, inout uvec2 rng) {
    PathBounce out_ = PathBounce(LUXEL_PATH_LOBE_NONE, vec3(0.0), vec3(0.0), 0.0);
    const int lobes = int(b.pSpecular > 0.0) + int(b.pTransmission > 0.0) + int(b.pDiffuse > 0.0);
    if (lobes == 0) return out_;
    int lobe = b.pDiffuse > 0.0    ? LUXEL_PATH_LOBE_DIFFUSE
               : b.pSpecular > 0.0 ? LUXEL_PATH_LOBE_SPECULAR
                                   : LUXEL_PATH_LOBE_TRANSMISSION;
    if (lobes > 1) {
        const float u = pathRngNext(rng);
        lobe = u < b.pSpecular                     ? LUXEL_PATH_LOBE_SPECULAR
               : u < b.pSpecular + b.pTransmission ? LUXEL_PATH_LOBE_TRANSMISSION
                                                   : LUXEL_PATH_LOBE_DIFFUSE;
    }
    const vec3 n = vec3(b.normal);
    const vec3 d = -b.view;
    out_.lobe = lobe;
    vec3 tu, tv;
    pathFaceFrame(b.normal, tu, tv);
    if (lobe == LUXEL_PATH_LOBE_DIFFUSE) {
        // Cosine sampling (cosineDirection): f cos / pdf = D.
        const float u1 = pathRngNext(rng), u2 = pathRngNext(rng);
        const float r = sqrt(u1), phi = 2.0 * LUXEL_PATH_PI * u2;
        const float z = sqrt(1.0 - u1);  // u1 < 1: the ray leaves the face
        out_.direction = tu * (r * cos(phi)) + tv * (r * sin(phi)) + n * z;
        out_.weight = b.diffuse * (1.0 / b.pDiffuse);
        out_.pdf = b.pDiffuse * (dot(n, out_.direction) / LUXEL_PATH_PI);
        return out_;
    }
    if (lobe == LUXEL_PATH_LOBE_TRANSMISSION) {
        // Entering the denser medium: never total reflection (eta < 1).
        const float cosI = -dot(n, d), eta = 1.0 / b.ior;
        const float k = opticsRefractK(cosI, eta);
        out_.direction = normalize(opticsRefract(d, n, eta, cosI, max(k, 0.0)));
        out_.weight = vec3(b.transmission / b.pTransmission);
        return out_;
    }
    if (pathMirror(b)) {
        out_.direction = d - n * (2.0 * dot(n, d));
        out_.weight = b.specular * (1.0 / b.pSpecular);
        return out_;
    }
    const float u1 = pathRngNext(rng), u2 = pathRngNext(rng);
    const vec3 v = vec3(dot(b.view, tu), dot(b.view, tv), b.cosView);
    const vec3 hLocal = pathGgxVisibleNormal(v, b.alpha, u1, u2);
    const vec3 h = tu * hLocal.x + tv * hLocal.y + n * hLocal.z;
    out_.direction = normalize(h * (2.0 * dot(b.view, h)) - b.view);
    const float cosL = dot(n, out_.direction);
    if (!(cosL > 0.0) || !(b.cosView > 0.0)) {  // below the face: lost (single scattering)
        out_.lobe = LUXEL_PATH_LOBE_NONE;
        return out_;
    }
    // f cos / pdf = S 4 cos_v cos_l Vis / G1(v); the density from the sampled half vector
    // itself (its tangential part exact), which equals the CPU's from the direction.
    const float g1 = pathGgxMasking(b.cosView, b.alpha);
    const float vis = ggxSmithVisibility(b.cosView, cosL, b.alpha);
    out_.weight = b.specular * (4.0 * b.cosView * cosL * vis / (g1 * b.pSpecular));
    const float sin2H = hLocal.x * hLocal.x + hLocal.y * hLocal.y;
    out_.pdf = b.pSpecular * g1 * pathGgxD(hLocal.z, sin2H, b.alpha) / (4.0 * b.cosView);
    return out_;
}
