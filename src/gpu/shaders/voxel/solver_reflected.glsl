// One level of RadianceCascades::reflectedLight (src/voxel/cascades/cascade_picture.cpp) on the
// GPU: the radiance arriving along a reflection or transmission ray. GLSL has no recursion, so
// cascades_picture.comp.glsl includes this file once per level with
//   LUXEL_SOLVER_REFLECTED  the function to define: vec3 (origin, direction, delta, rng)
//   LUXEL_SOLVER_FOLLOW     (only above the deepest level) the shading of the next level
//                           (solver_shade.glsl) for glass and polished metal met by the ray
//   LUXEL_SOLVER_ROUGH_LAMBERTIAN (the camera surface's level) a GGX direction of a rough
//                           camera surface (pictureGlossyRay and pictureRoughLobe) follows no
//                           such face: it takes it as Lambertian
//   LUXEL_SOLVER_NEAR       (the camera surface's level) while pictureGlossyRay, an emitter of
//                           pictureNearFace's near list counts its emission times 1 - its near
//                           weight at pictureNearPoint (nearEmitterShare), and a lamp the
//                           surface's light samples could pick is handed back in
//                           pictureLampEmission and pictureLampDensity instead
// Needs solver_light.glsl.

vec3 LUXEL_SOLVER_REFLECTED(vec3 origin, vec3 direction, bool delta, inout uvec2 rng) {
    const SurfaceHit s = castToSurface(origin, direction);
    if (!s.hit.hit) {
        return skyColor(direction) + (delta ? sunDiskAlong(direction) : vec3(0.0));
    }
    if (s.hit.normal == ivec3(0)) return vec3(0.0);
    const vec3 irradiance = indirectIrradiance(s.hit);
#ifdef LUXEL_SOLVER_FOLLOW
    // Glass or polished metal: shaded with its material, what lies behind it or what it
    // reflects followed one level deeper.
#ifdef LUXEL_SOLVER_ROUGH_LAMBERTIAN
    const bool follows = solverFollows(s) && !(pictureGlossyRay && pictureRoughLobe);
#else
    const bool follows = solverFollows(s);
#endif
    if (follows) {
        return LUXEL_SOLVER_FOLLOW(s, direction, irradiance * LUXEL_SOLVER_INV_PI, 1, 1, delta,
                                   rng);
    }
#endif
    // The face met, Lambertian: its emission, the sun its face's rays found when the cascades
    // were lit, and the cascades' irradiance.
    const PathSurface surface = pathSurfaceAt(s);
    const int face = findFace(s.hit.voxel, normalIndex(s.hit.normal));
    const vec3 sun = face >= 0 ? faceLight(LUXEL_FACE_DIRECT, face) : vec3(0.0);
    vec3 emission = surface.emission;
#ifdef LUXEL_SOLVER_NEAR
    if (pictureGlossyRay && maxComponent(emission) > 0.0) {
        emission = emission * (1.0 - nearEmitterShare(pictureNearFace, pictureNearPoint,
                                                       s.hit.voxel, s.hit.normal));
        // A lamp the surface's light samples could have found: handed back for the balance
        // heuristic (glossy_emitters.glsl), out of the split sum.
        const float density = glossyLampDensity(s.hit.voxel, s.hit.normal, s.hit.point);
        if (density > 0.0) {
            pictureLampEmission = emission;
            pictureLampDensity = density;
            emission = vec3(0.0);
        }
    }
#endif
    return emission + surface.albedo * (sun + irradiance) * LUXEL_SOLVER_INV_PI;
}
