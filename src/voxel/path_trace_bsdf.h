// The path tracer's surface response (docs/algorithms/voxel-path-tracing.md): one BSDF per
// material with the meaning of every field the physical ray caster gives it
// (docs/algorithms/voxel-surfaces.md). At a hit seen with cosine cos_v, F = the dielectric
// Fresnel reflectance of `ior` (0 for ior 1: no interface) and c the surface colour, three
// lobes share what arrives:
//
//   specular      S = metallic Schlick(c, cos_v) + (1 - metallic) F   GGX (alpha = roughness^2)
//                                                                      or a mirror (alpha ~ 0)
//   transmission  T = (1 - metallic)(1 - F) transmission               refracts into the voxel
//   diffuse       D = (1 - metallic)(1 - F)(1 - transmission) c        Lambertian
//
// so S + T + D <= 1 for c <= 1; the GGX lobe loses what single scattering loses (masking).
// A path picks one lobe with probability proportional to its mean weight and samples it (cosine
// hemisphere, GGX visible normals, or the delta direction); next event estimation evaluates the
// smooth lobes and weights each against its own sampling (power heuristic).
#pragma once

#include "gpu/shaders/shared/path_bsdf.h"
#include "luxel/core/vec.h"
#include "luxel/voxel/material.h"
#include "luxel/voxel/path_trace_rng.h"
#include "luxel/voxel/shading.h"

namespace luxel::voxel {

// Below this GGX alpha (roughness 0.01) the lobe is a delta mirror.
inline constexpr float kMirrorAlpha = 1e-4f;

struct PathBsdf {
    Int3 normal;  // the hit face's outward normal
    Vec3d view;   // unit, from the hit back along the incoming ray
    double cosView = 0.0;
    Rgb specular, diffuse;   // lobe weights S and D
    float transmission = 0;  // lobe weight T
    float alpha = 0;         // GGX alpha; < kMirrorAlpha: a mirror
    float ior = 1;           // of the voxel behind the face (transmission)
    // Lobe selection probabilities, proportional to the lobes' mean weights (sum 1, or all 0
    // for a black surface).
    double pSpecular = 0, pTransmission = 0, pDiffuse = 0;

    bool mirror() const { return alpha < kMirrorAlpha; }
    // Whether a lobe can reflect light from a given direction (next event estimation applies).
    bool smooth() const { return pDiffuse > 0.0 || (pSpecular > 0.0 && !mirror()); }
};

// The Fresnel reflectance of light arriving from the air at cosine cosI on a dielectric of index
// `ior`, by the scene's model; 0 for ior 1 (no interface).
float dielectricFresnel(float cosI, float ior, ShadeOptions::FresnelModel model);

// The response of material `m` with surface colour `colour` (voxel colour x texel x procedural
// factor x albedo) at a face with outward normal `normal`, hit by a ray along unit `direction`.
// Transmission counts only when shading.refraction is on (else the material is opaque, as in
// the ray caster); Fresnel is exact or Schlick as shading.fresnel says.
PathBsdf pathBsdf(const Material& m, Rgb colour, Int3 normal, Vec3d direction,
                  const ShadeOptions& shading);
// The specular lobe of `b` alone, its S kept: no diffuse, no transmission (the sun's and the near
// emitters' highlights; the diffuse lobe is lit apart).
inline PathBsdf specularLobe(PathBsdf b) {
    b.diffuse = Rgb(0.0f);
    b.pDiffuse = 0.0;
    b.transmission = 0.0f;
    b.pTransmission = 0.0;
    return b;
}

struct BsdfSample {
    enum class Lobe { None, Diffuse, Specular, Transmission };
    Lobe lobe = Lobe::None;  // None: the path ends (black surface, or a GGX direction below)
    Vec3d direction;         // unit
    Rgb weight;              // f cos / (probability x density): what the throughput is scaled by
    double pdf = 0.0;        // probability x density in solid angle; 0 for the delta lobes
    bool delta = false;      // mirror or refraction: no light sample could find this direction
};

// Picks a lobe and samples its direction. Draws one number for the lobe when more than one lobe
// has a non-zero probability, then two for the direction when the lobe is diffuse or GGX.
// `density` false is the real-time solvers' form: a GGX sample's pdf is left 0 (their split sum
// reads only the direction and weight) and its direction and weight are computed in float, as
// the GPU computes them (src/gpu/shaders/shared/path_bsdf.h), within float rounding of the
// double ones the path tracer draws (docs/algorithms/voxel-radiance-cascades.md §5).
BsdfSample sampleBsdf(const PathBsdf& b, PathRng& rng, bool density = true);

// The real-time solvers' GGX directions of one lobe, drawn one after another: for a
// specular-only lobe (pSpecular 1, no other lobe, not a mirror) sampleBsdf(b, rng, false)'s
// directions and weights to the bit, with what depends on the lobe alone (its frame, the
// visible normals' hemisphere, the view's masking) made once instead of at every sample
// (docs/algorithms/voxel-radiance-cascades.md §5); any other lobe goes to sampleBsdf. `b` must
// outlive the sampler.
class GgxSampler {
  public:
    explicit GgxSampler(const PathBsdf& b);
    BsdfSample sample(PathRng& rng) const;

    // The lobe's frame in float: the face's tangents and normal, the view, the visible normals'
    // frame (shared/path_bsdf.h, as the GPU makes it) and G1 of the view.
    struct Frame {
        Vec3 tu, tv, n, view;
        gpu::shared::PathGgxVisibleFrame visible;
        float alpha = 0.0f, cosView = 0.0f, masking = 0.0f;
    };
    static Frame frameOf(const PathBsdf& b);

  private:
    const PathBsdf& b_;
    bool ggx_;
    Frame frame_;
};

// Light of `radiance` arriving from unit direction l that the smooth lobes send towards the
// view: f cos L / lightPdf, each lobe weighted by the power heuristic against the density with
// which its own sampling finds l. lightPdf = 0 is a delta light (no weights, no division).
Rgb bsdfLight(const PathBsdf& b, Vec3d l, Rgb radiance, double lightPdf);

// ggxDensity(b, l) and bsdfLight(b, l, radiance, 0) for one direction l, the half vector and GGX's
// D that both find made once (the same floats): a light sample of the glossy lamps asks for
// both (docs/algorithms/voxel-radiance-cascades.md §5). `b` must outlive it.
class GgxTowards {
  public:
    GgxTowards(const PathBsdf& b, Vec3d l);
    double density() const;
    Rgb deltaLight(Rgb radiance) const;

  private:
    const PathBsdf& b_;
    Vec3d l_;
    double cosH_ = 0.0, d_ = 0.0;  // n . h and D(h)
};

// The power heuristic's weight of a strategy of density `mine` against one of density `other`.
double powerHeuristic(double mine, double other);

// The density in solid angle with which GGX's visible normals (the specular lobe of `b`, not
// scaled by pSpecular) find the reflection direction l: G1(v) D(h) / (4 cos_v).
double ggxDensity(const PathBsdf& b, Vec3d l);

}  // namespace luxel::voxel
