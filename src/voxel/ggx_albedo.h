// The single-scattering directional albedo of the path tracer's GGX lobe (Filament's D,
// height-correlated Smith visibility; path_trace_bsdf.h): E(cos_v, alpha) = the integral over the
// hemisphere of D Vis cos_l, what a GGX lobe of reflectance 1 reflects in all. The real-time
// solvers' split-sum specular scales by it (solver_surface.h).
#pragma once

namespace luxel::voxel {

// E from a 24 x 24 table over cosView and alpha in [0, 1] (both clamped), bilinear in between.
// The table is computed by quadrature on first use (about 10 ms on one core, once per process).
double directionalAlbedoGgx(double cosView, double alpha);

// E at one point by the table's quadrature: `phiNodes` Gauss-Legendre nodes per interval of the
// azimuth, `slopeNodes` per azimuth over the visible half vectors (tests compare finer rules).
double integrateDirectionalAlbedoGgx(double cosView, double alpha, int slopeNodes = 12,
                                     int phiNodes = 8);

}  // namespace luxel::voxel
