// One level of shadeSolverSurface (src/voxel/solver_surface.cpp) on the GPU: the material's
// lobes at a surface lit by the solver (emission, the diffuse lobe under the sun's disk and the
// cascades' irradiance, the GGX highlight of the sun), the transmission lobe followed through
// the medium, and the mirror or GGX reflection of the surroundings (split sum). Included once
// per level by cascades_picture.comp.glsl with
//   LUXEL_SOLVER_SHADE     the function to define:
//                          vec3 (hit, ray direction, E / pi, sun rays, specular rays,
//                                arrivedDelta, rng); arrivedDelta: the ray met this surface
//                                through delta lobes only (the camera's, a mirror's, glass's),
//                                so its delta rays may show the sun's disk
//   LUXEL_SOLVER_RADIANCE  the radiance along a ray leaving the surface (solver_reflected.glsl)
//   LUXEL_SOLVER_AIR_EXITS the medium's exits into the air whose refracted light is taken; the
//                          light reflected back inside after the last is dropped
//                          (SolverLight::mediumAirExits)
//   LUXEL_SOLVER_NEAR      (the camera's surface only) its near emitters' highlight
//                          light-sampled (nearEmitterHighlight), and pictureGlossyRay set while
//                          a GGX direction's radiance is taken, so that LUXEL_SOLVER_RADIANCE
//                          counts those emitters by the share the highlight leaves; and the
//                          lamps beyond light-sampled and weighed against the GGX rays that
//                          meet them (glossy_emitters.glsl)
// The rays leave in the CPU's order (the medium's exits, then the mirror or GGX directions) from
// one call site, so the level below is inlined once, and the random numbers are drawn in the
// same order as on the CPU.

// kMaxMediumExits (solver_surface.cpp).
#ifndef LUXEL_SOLVER_MEDIUM_EXITS
#define LUXEL_SOLVER_MEDIUM_EXITS 8
#endif

vec3 LUXEL_SOLVER_SHADE(SurfaceHit s, vec3 rayDirection, vec3 diffuseRadiance, int sunRays,
                        int specularRays, bool arrivedDelta, inout uvec2 rng) {
    const PathSurface surface = pathSurfaceAt(s);
    const vec3 direction = normalize(rayDirection);
    const PathBsdf b = pathBsdfAt(surface, s.hit.normal, direction);
    const bool glossy = b.pSpecular > 0.0 && b.cosView > 0.0;
    const bool mirror = pathMirror(b);
    // The specular lobe alone, for the sun's highlight (the diffuse lobe is lit apart).
    PathBsdf specular = b;
    specular.diffuse = vec3(0.0);
    specular.pDiffuse = 0.0;
    specular.transmission = 0.0;
    specular.pTransmission = 0.0;
    vec3 result = surface.emission +
                  solverSunLobes(s.hit, b.diffuse, glossy && !mirror, specular, sunRays) +
                  b.diffuse * diffuseRadiance;

    // The transmission lobe: the camera ray refracted in (a delta lobe, no numbers drawn) and
    // walked through the medium; each exit's refracted part brings the light along it.
    bool inMedium = b.transmission > 0.0 && b.cosView > 0.0;
    vec3 weight = vec3(b.transmission), mediumOrigin = s.hit.point, mediumDirection = vec3(0.0);
    ivec3 cell = s.hit.voxel;
    int exits = 0, airExits = 0;
    if (inMedium) {
        PathBsdf entering = b;
        entering.pSpecular = 0.0;
        entering.pDiffuse = 0.0;
        entering.pTransmission = 1.0;
        mediumDirection = pathSampleBsdf(entering, rng).direction;
    }
#ifdef LUXEL_SOLVER_NEAR
    const vec3 nearHighlight = glossy && !mirror ? nearEmitterHighlight(s.hit, specular)
                                                 : vec3(0.0);
    // The lamps beyond: the surface's choice among its cell's, and the lobe with its S for
    // their light samples; what the GGX rays meet of them (glossy_emitters.glsl).
    const PathBsdf lobe = specular;
    if (glossy && !mirror) glossyLampsChoose(s.hit);
    vec3 lamps = vec3(0.0);
    // A sharp lobe takes no light samples: its GGX direction finds a lamp alone (as the CPU).
    const bool lampSamples = !(b.alpha <= LUXEL_PICTURE_SHARP_ALPHA);
#endif
    // Then the reflection: one mirror ray, or GGX directions weighted by their sampling weights.
    specular.specular = vec3(1.0);
    specular.pSpecular = 1.0;
    // A sharp or a very rough lobe takes one GGX direction (kSolverSharpAlpha, kSolverRoughAlpha,
    // SolverLight::sharpLobeOneRay and roughLobeOneRay: the picture sets them at the camera's
    // surface, whose level alone casts more than one).
    const int lobeRays =
        b.alpha <= LUXEL_PICTURE_SHARP_ALPHA || b.alpha >= LUXEL_PICTURE_ROUGH_ALPHA
            ? min(specularRays, 1)
            : specularRays;
    int reflections = glossy ? (mirror ? 1 : lobeRays) : 0;
    const vec3 n = vec3(s.hit.normal);
    vec3 weighted = vec3(0.0);
    float weights = 0.0;
    const int rounds = LUXEL_SOLVER_MEDIUM_EXITS + 2 + max(specularRays, 1);
    for (int round = 0; round < rounds; ++round) {
        vec3 rayOrigin = s.hit.point, ray = vec3(0.0), scale = vec3(0.0);
        bool delta = true;
        float ggxWeight = 0.0;
        if (inMedium) {
            if (!(exits < LUXEL_SOLVER_MEDIUM_EXITS && maxComponent(weight) > 1e-4)) {
                inMedium = false;
                continue;
            }
            const VoxelMaterial m = materials[materialIndex(voxelValue(cell))];
            const MediumExit e = walkMedium(cell, mediumOrigin, mediumDirection);
            weight = weight * voxelTransmittance(vec3(m.absorptionR, m.absorptionG, m.absorptionB),
                                                 e.distance);
            if (e.intoSolid) {  // another solid behind the medium: seen directly
                rayOrigin = e.point;
                ray = mediumDirection;
                scale = weight;
                inMedium = false;
            } else {
                // splitAtExit (shading_physical.cpp): total reflection or a Fresnel split.
                const vec3 nIn = -vec3(e.outward);
                const float cosI = -dot(nIn, mediumDirection);
                const float k = opticsRefractK(cosI, m.ior);
                const vec3 reflected = normalize(opticsReflect(mediumDirection, nIn));
                ++exits;
                if (k < 0.0) {
                    mediumOrigin = e.point;
                    mediumDirection = reflected;
                    cell = e.cell;
                    continue;
                }
                const float reflectance = pathFresnel(cosI, m.ior, 1.0);
                rayOrigin = e.point;
                ray = normalize(opticsRefract(mediumDirection, nIn, m.ior, cosI, k));
                scale = weight * (1.0 - reflectance);
                weight = weight * reflectance;
                // The last exit taken: what is reflected inside is dropped.
                if (++airExits >= LUXEL_SOLVER_AIR_EXITS) weight = vec3(0.0);
                mediumOrigin = e.point;
                mediumDirection = reflected;
                cell = e.cell;
            }
        } else {
            if (reflections == 0) break;
            --reflections;
            if (mirror) {
                ray = direction - n * (2.0 * dot(n, direction));
                scale = b.specular;
            } else {
                const PathBounce drawn = pathSampleBsdf(specular, rng);
                if (drawn.lobe != LUXEL_PATH_LOBE_SPECULAR) continue;
                ray = drawn.direction;
                ggxWeight = drawn.weight.x;
                delta = false;
            }
        }
#ifdef LUXEL_SOLVER_NEAR
        pictureGlossyRay = !delta;
        pictureLampDensity = 0.0;
#endif
        const vec3 arriving = LUXEL_SOLVER_RADIANCE(rayOrigin, ray, delta && arrivedDelta, rng);
        if (delta) {
            result += scale * arriving;
        } else {
            weighted += arriving * ggxWeight;
            weights += ggxWeight;
#ifdef LUXEL_SOLVER_NEAR
            if (pictureLampDensity > 0.0) {
                // f cos L / (n_l p_l + n_b p_b), the weight being f cos / (S p_b).
                const float lobePdf = pathGgxPdf(specular, ray);
                lamps += pictureLampEmission * ggxWeight *
                         (lobePdf * glossyBalance(pictureLampDensity, lobePdf,
                                                  lampSamples ? float(LUXEL_GLOSSY_LIGHT_SAMPLES)
                                                              : 0.0,
                                                  float(lobeRays)));
            }
#endif
        }
    }
#ifdef LUXEL_SOLVER_NEAR
    if (glossy && !mirror) {
        result += nearHighlight;
        if (lampSamples) result += glossyLampLight(s.hit, lobe, lobeRays, rng);
        result += b.specular * lamps;
    }
#endif
    // One direction of a rough lobe, unbiased: S (A C + w (L - C)), C = E / pi
    // (shadeSolverSurface).
    if (lobeRays == 1 && b.alpha >= LUXEL_PICTURE_ROUGH_ALPHA) {
        const float albedo = directionalAlbedoGgx(b.cosView, b.alpha);
        return result +
               b.specular * (diffuseRadiance * albedo + weighted - diffuseRadiance * weights);
    }
    if (!(weights > 0.0)) return result;
    // Split sum: S A(cos_v, alpha) times the weighted mean radiance of the GGX directions.
    return result + b.specular * weighted * (directionalAlbedoGgx(b.cosView, b.alpha) / weights);
}
