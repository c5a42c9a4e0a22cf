// The path tracer's surface response (path_trace_bsdf.h). Fresnel and refraction are the ray
// caster's kernels (src/gpu/shaders/shared/optics.h); GGX's distribution and masking are
// evaluated in double in the form sin^2 + alpha^2 cos^2, which stays exact for the narrowest
// lobes (the float form 1 + cos^2 (alpha^2 - 1) cancels below alpha ~ 1e-3).
#include "voxel/path_trace_bsdf.h"

#include <algorithm>
#include <cmath>

#include "gpu/shaders/shared/face_frame.h"
#include "gpu/shaders/shared/optics.h"
#include "gpu/shaders/shared/path_bsdf.h"
#include "path_trace_surface.h"

namespace luxel::voxel {
namespace {

namespace shared = gpu::shared;

constexpr double kPi = 3.14159265358979323846;

Vec3d toDouble(Int3 v) {
    return {double(v.x), double(v.y), double(v.z)};
}
shared::vec3 v3(Vec3d v) {
    return {float(v.x), float(v.y), float(v.z)};
}
Vec3 toFloat(Vec3d v) {
    return {float(v.x), float(v.y), float(v.z)};
}
double mean(Rgb c) {
    return (double(c.r) + double(c.g) + double(c.b)) / 3.0;
}

// The face's tangents (shared/face_frame.h; any orthonormal pair would do: GGX is isotropic).
void faceFrame(Int3 normal, Vec3d& tu, Vec3d& tv) {
    const shared::vec3 u = shared::faceTangentU({normal.x, normal.y, normal.z});
    const shared::vec3 v = shared::faceTangentV({normal.x, normal.y, normal.z});
    tu = {u.x, u.y, u.z}, tv = {v.x, v.y, v.z};
}

// GGX D for the half vector's cosine (and sine squared) to the normal.
double ggxDistribution(double cosH, double sin2H, double alpha) {
    const double a2 = alpha * alpha;
    const double f = sin2H + a2 * cosH * cosH;
    return a2 / (kPi * f * f);
}

// Smith's masking G1 for GGX at cosine c: 2c / (c + sqrt(alpha^2 + (1 - alpha^2) c^2)).
double ggxMasking(double c, double alpha) {
    const double a2 = alpha * alpha;
    return 2.0 * c / (c + std::sqrt(a2 + (1.0 - a2) * c * c));
}

// D for the light direction l: the half vector's cosine to the normal and D there.
double ggxDistributionTowards(const PathBsdf& b, Vec3d l, double& cosH) {
    const Vec3d n = toDouble(b.normal);
    const Vec3d h = normalize(b.view + l);
    cosH = dot(n, h);
    const Vec3d across = h - n * cosH;
    return ggxDistribution(cosH, dot(across, across), b.alpha);
}

// G1(v) D / (4 cos_v) from D (ggxPdf's density, 0 where the half vector is below the face).
double ggxPdfOf(const PathBsdf& b, double cosH, double d) {
    if (!(cosH > 0.0)) return 0.0;
    return ggxMasking(b.cosView, b.alpha) * d / (4.0 * b.cosView);
}

// D * Vis (Vis = G2 / (4 cos_l cos_v), height-correlated, optics.h) for a light direction l,
// from D.
double ggxReflectanceOf(const PathBsdf& b, double d, double cosL) {
    return d * shared::ggxSmithVisibility(float(b.cosView), float(cosL), b.alpha);
}

// Density of the visible-normal sampling finding l: G1(v) D(h) / (4 cos_v).
double ggxPdf(const PathBsdf& b, Vec3d l) {
    double cosH;
    const double d = ggxDistributionTowards(b, l, cosH);
    return ggxPdfOf(b, cosH, d);
}

// What sampleGgx needs of the lobe alone, whatever numbers are drawn.
struct DoubleFrame {
    Vec3d tu, tv, n, vh, t1, t2;
};

DoubleFrame doubleFrameOf(const PathBsdf& b) {
    DoubleFrame f;
    faceFrame(b.normal, f.tu, f.tv);
    f.n = toDouble(b.normal);
    const double a = b.alpha;
    const Vec3d v{dot(b.view, f.tu), dot(b.view, f.tv), b.cosView};
    f.vh = normalize(Vec3d{a * v.x, a * v.y, v.z});
    const Vec3d& vh = f.vh;
    const double lensq = vh.x * vh.x + vh.y * vh.y;
    f.t1 = lensq > 0.0 ? Vec3d{-vh.y, vh.x, 0.0} / std::sqrt(lensq) : Vec3d{1, 0, 0};
    f.t2 = cross(vh, f.t1);
    return f;
}

}  // namespace

GgxSampler::Frame GgxSampler::frameOf(const PathBsdf& b) {
    // pathSampleBsdf's and pathGgxVisibleNormal's frame (path_surface.glsl, path_bsdf.h).
    Frame f;
    Vec3d tu, tv;
    faceFrame(b.normal, tu, tv);
    f.tu = toFloat(tu), f.tv = toFloat(tv), f.n = toFloat(toDouble(b.normal));
    f.view = toFloat(b.view);
    f.alpha = b.alpha;
    f.cosView = float(b.cosView);
    f.visible = shared::pathGgxVisibleFrame(
        shared::vec3(dot(f.view, f.tu), dot(f.view, f.tv), f.cosView), f.alpha);
    f.masking = shared::pathGgxMasking(f.cosView, f.alpha);
    return f;
}

namespace {

// A visible normal of GGX (Heitz 2018, "Sampling the GGX Distribution of Visible Normals") in
// the frame (tu, tv, n), and the view reflected about it.
Vec3d sampleGgx(const PathBsdf& b, const DoubleFrame& f, float u1, float u2) {
    const Vec3d &tu = f.tu, &tv = f.tv, &n = f.n, &vh = f.vh, &t1 = f.t1, &t2 = f.t2;
    const double a = b.alpha;
    const double r = std::sqrt(double(u1)), phi = 2.0 * kPi * double(u2);
    const double p1 = r * std::cos(phi);
    const double s = 0.5 * (1.0 + vh.z);
    const double p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * r * std::sin(phi);
    const Vec3d nh = t1 * p1 + t2 * p2 + vh * std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2));
    const Vec3d hLocal = normalize(Vec3d{a * nh.x, a * nh.y, std::max(0.0, nh.z)});
    const Vec3d h = tu * hLocal.x + tv * hLocal.y + n * hLocal.z;
    return normalize(h * (2.0 * dot(b.view, h)) - b.view);
}

// sampleGgx in float (the GPU's pathGgxVisibleNormal, its frame made once): the real-time
// solvers' GGX rays (docs/algorithms/voxel-radiance-cascades.md §5). A sample is one long chain
// of dependent square roots and divisions, so the half vector is not normalised: the view is
// reflected about it as 2 (v.h) h / (h.h) - v, which is unit as it stands (one division where
// two normalisations took two square roots and six divisions; within float rounding of them).
Vec3 sampleGgxFloat(const GgxSampler::Frame& f, float u1, float u2) {
    const shared::vec3 hl = shared::pathGgxVisibleNormalUnnormalised(f.visible, f.alpha, u1, u2);
    const Vec3 h = f.tu * hl.x + f.tv * hl.y + f.n * hl.z;
    return h * (2.0f * dot(f.view, h) / dot(h, h)) - f.view;
}

// The solvers' GGX sample of lobe `b` (its specular lobe picked) in the float frame `f`: the
// direction and f cos / (probability x density) = S 4 cos_v cos_l Vis / (G1(v) pSpecular); no
// pdf. Lobe None when the direction falls below the face.
BsdfSample sampleGgxSolver(const PathBsdf& b, const GgxSampler::Frame& f, PathRng& rng) {
    BsdfSample out;
    const float u1 = rng.next(), u2 = rng.next();
    const Vec3 l = sampleGgxFloat(f, u1, u2);
    const float cosL = dot(f.n, l);
    if (!(cosL > 0.0f) || !(f.cosView > 0.0f)) return out;
    out.lobe = BsdfSample::Lobe::Specular;
    out.direction = {l.x, l.y, l.z};
    const float vis = shared::ggxSmithVisibility(f.cosView, cosL, f.alpha);
    out.weight = b.specular * (4.0f * f.cosView * cosL * vis / (f.masking * float(b.pSpecular)));
    return out;
}

}  // namespace

float dielectricFresnel(float cosI, float ior, ShadeOptions::FresnelModel model) {
    if (ior == 1.0f) return 0.0f;  // no index contrast: no interface to reflect
    return model == ShadeOptions::FresnelModel::Exact
               ? shared::fresnelDielectricExact(cosI, 1.0f, ior)
               : shared::fresnelDielectricSchlick(cosI, 1.0f, ior);
}

double powerHeuristic(double mine, double other) {
    const double a = mine * mine, b = other * other;
    return a + b > 0.0 ? a / (a + b) : 0.0;
}

PathBsdf pathBsdf(const Material& m, Rgb colour, Int3 normal, Vec3d direction,
                  const ShadeOptions& o) {
    PathBsdf b;
    b.normal = normal;
    b.view = -direction;
    b.cosView = std::clamp(dot(toDouble(normal), b.view), 0.0, 1.0);
    b.alpha = m.roughness * m.roughness;
    b.ior = m.ior;
    const float cosV = float(b.cosView);
    const float fresnel = dielectricFresnel(cosV, m.ior, o.fresnel);
    const float dielectric = 1.0f - m.metallic;
    const float transmission = o.refraction ? m.transmission : 0.0f;
    // A dielectric's metal term is 0 x a finite Schlick: left out, the sum is the same float.
    b.specular = Rgb(dielectric * fresnel);
    if (m.metallic != 0.0f) {
        const shared::vec3 metal =
            shared::fresnelSchlickRgb(v3(Vec3d{colour.r, colour.g, colour.b}), cosV);
        b.specular = Rgb(metal.x, metal.y, metal.z) * m.metallic + b.specular;
    }
    b.transmission = dielectric * (1.0f - fresnel) * transmission;
    b.diffuse = colour * (dielectric * (1.0f - fresnel) * (1.0f - transmission));
    const double s = mean(b.specular), t = b.transmission, d = mean(b.diffuse);
    const double total = s + t + d;
    if (total > 0.0) {
        b.pSpecular = s / total;
        b.pTransmission = t / total;
        b.pDiffuse = d / total;
    }
    return b;
}

BsdfSample sampleBsdf(const PathBsdf& b, PathRng& rng, bool density) {
    using Lobe = BsdfSample::Lobe;
    BsdfSample out;
    const int lobes = (b.pSpecular > 0.0) + (b.pTransmission > 0.0) + (b.pDiffuse > 0.0);
    if (lobes == 0) return out;
    Lobe lobe = b.pDiffuse > 0.0    ? Lobe::Diffuse
                : b.pSpecular > 0.0 ? Lobe::Specular
                                    : Lobe::Transmission;
    if (lobes > 1) {
        const double u = rng.next();
        lobe = u < b.pSpecular                     ? Lobe::Specular
               : u < b.pSpecular + b.pTransmission ? Lobe::Transmission
                                                   : Lobe::Diffuse;
    }
    const Vec3d n = toDouble(b.normal);
    const Vec3d d = -b.view;
    out.lobe = lobe;
    if (lobe == Lobe::Diffuse) {
        // Cosine sampling: f cos / pdf = D.
        const float u1 = rng.next(), u2 = rng.next();
        out.direction = cosineDirection(b.normal, u1, u2);
        out.weight = b.diffuse * float(1.0 / b.pDiffuse);
        out.pdf = b.pDiffuse * (dot(n, out.direction) / kPi);
        return out;
    }
    if (lobe == Lobe::Transmission) {
        // Entering the denser medium: never total reflection (eta < 1).
        const shared::vec3 nIn = v3(n), dir = v3(d);
        const float cosI = -dot(nIn, dir), eta = 1.0f / b.ior;
        const float k = shared::opticsRefractK(cosI, eta);
        const shared::vec3 t = shared::opticsRefract(dir, nIn, eta, cosI, std::max(k, 0.0f));
        out.direction = normalize(Vec3d{t.x, t.y, t.z});
        out.weight = Rgb(float(b.transmission / b.pTransmission));
        out.delta = true;
        return out;
    }
    if (b.mirror()) {
        out.direction = d - n * (2.0 * dot(n, d));
        out.weight = b.specular * float(1.0 / b.pSpecular);
        out.delta = true;
        return out;
    }
    if (!density) return sampleGgxSolver(b, GgxSampler::frameOf(b), rng);
    const float u1 = rng.next(), u2 = rng.next();
    out.direction = sampleGgx(b, doubleFrameOf(b), u1, u2);
    const double cosL = dot(n, out.direction);
    if (!(cosL > 0.0) || !(b.cosView > 0.0)) {  // below the face: lost (single scattering)
        out.lobe = Lobe::None;
        return out;
    }
    // f cos / pdf = S D Vis cos_l / (G1(v) D / (4 cos_v)) = S 4 cos_v cos_l Vis / G1(v).
    const double vis = shared::ggxSmithVisibility(float(b.cosView), float(cosL), b.alpha);
    out.weight = b.specular * float(4.0 * b.cosView * cosL * vis /
                                    (ggxMasking(b.cosView, b.alpha) * b.pSpecular));
    out.pdf = b.pSpecular * ggxPdf(b, out.direction);
    return out;
}

namespace {

// bsdfLight, D found by `distribution` when the specular lobe asks for it.
template <class Distribution>
Rgb bsdfLightWith(const PathBsdf& b, Vec3d l, Rgb radiance, double lightPdf,
                  const Distribution& distribution) {
    const double cosL = dot(toDouble(b.normal), l);
    if (!(cosL > 0.0)) return {};
    const bool deltaLight = !(lightPdf > 0.0);
    const double divide = deltaLight ? 1.0 : lightPdf;
    Rgb out;
    if (b.pDiffuse > 0.0) {
        const double w = deltaLight ? 1.0 : powerHeuristic(lightPdf, b.pDiffuse * (cosL / kPi));
        out = b.diffuse * radiance * float(cosL / kPi * w / divide);
    }
    if (b.pSpecular > 0.0 && !b.mirror() && b.cosView > 0.0) {
        const double w = deltaLight ? 1.0 : powerHeuristic(lightPdf, b.pSpecular * ggxPdf(b, l));
        out += b.specular * radiance *
               float(ggxReflectanceOf(b, distribution(), cosL) * cosL * w / divide);
    }
    return out;
}

}  // namespace

Rgb bsdfLight(const PathBsdf& b, Vec3d l, Rgb radiance, double lightPdf) {
    return bsdfLightWith(b, l, radiance, lightPdf, [&] {
        double cosH;
        return ggxDistributionTowards(b, l, cosH);
    });
}

GgxTowards::GgxTowards(const PathBsdf& b, Vec3d l) : b_(b), l_(l) {
    d_ = ggxDistributionTowards(b, l, cosH_);
}

double GgxTowards::density() const {
    return ggxPdfOf(b_, cosH_, d_);
}

Rgb GgxTowards::deltaLight(Rgb radiance) const {
    return bsdfLightWith(b_, l_, radiance, 0.0, [&] { return d_; });
}

double ggxDensity(const PathBsdf& b, Vec3d l) {
    return ggxPdf(b, l);
}

GgxSampler::GgxSampler(const PathBsdf& b)
    : b_(b),
      ggx_(b.pSpecular == 1.0 && b.pTransmission == 0.0 && b.pDiffuse == 0.0 && !b.mirror()) {
    if (ggx_) frame_ = frameOf(b);
}

BsdfSample GgxSampler::sample(PathRng& rng) const {
    // sampleBsdf(b, rng, false)'s GGX branch for one lobe (no number drawn for the lobe).
    return ggx_ ? sampleGgxSolver(b_, frame_, rng) : sampleBsdf(b_, rng, false);
}

}  // namespace luxel::voxel
