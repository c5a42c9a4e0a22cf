// An independent Monte Carlo estimate of the bounce model's continuous counterpart, for tests:
// paths start at a pixel centre in a uniform direction and fly through the piecewise-constant
// pixel medium with free-flight sampling (exponential optical depth, exact per-pixel DDA). At a
// collision the path scores the pixel's emission E, then
//  - in a pixel with reflectance rho > 0 (a surface) it reflects with probability rho, diffusely
//    (cosine-distributed about the normal of the face it entered by), from the entry point;
//  - elsewhere it scatters isotropically with probability = the scattering albedo;
// and ends otherwise. A path that leaves the canvas scores the boundary radiance. The mean score
// is the mean radiance over directions at the start, the fluence of docs/conventions.md.
// Shares no code with the solvers.
#pragma once

#include <cmath>
#include <numbers>

#include "luxel/core/rng.h"
#include "luxel/gi2d/medium2d.h"

namespace luxel::gi2d::test {

class PathTracer2D {
  public:
    explicit PathTracer2D(const Medium2D& m) : m_(m) {}

    // Mean of `paths` path scores per channel from the centre of pixel (x, y).
    Rgb fluence(int x, int y, int paths, std::uint64_t seed) const {
        Pcg32 rng(hashSeed(seed, static_cast<std::uint64_t>(x), static_cast<std::uint64_t>(y)));
        Rgb sum;
        for (int c = 0; c < 3; ++c) {
            double total = 0;
            for (int i = 0; i < paths; ++i) total += path(x, y, c, rng);
            sum[c] = static_cast<float>(total / paths);
        }
        return sum;
    }

  private:
    double path(int ix, int iy, int c, Pcg32& rng) const {
        double px = ix + 0.5, py = iy + 0.5;
        double angle = 2 * std::numbers::pi * rng.nextDouble();
        double dx = std::cos(angle), dy = std::sin(angle);
        double score = 0;
        for (int bounce = 0; bounce < 100000; ++bounce) {
            double tau = -std::log(1.0 - rng.nextDouble());
            int prevX = ix, prevY = iy;
            double entryX = px, entryY = py;
            int faceAxis = -1;  // axis of the face the current pixel was entered by
            bool collided = false;
            while (true) {
                const double sigma = m_.absorption.at(ix, iy, c);
                const double tx = dx > 0 ? (ix + 1 - px) / dx : dx < 0 ? (ix - px) / dx : 1e30;
                const double ty = dy > 0 ? (iy + 1 - py) / dy : dy < 0 ? (iy - py) / dy : 1e30;
                const double t = std::min(tx, ty);
                if (sigma * t >= tau) {
                    const double s = tau / sigma;
                    px += dx * s;
                    py += dy * s;
                    collided = true;
                    break;
                }
                tau -= sigma * t;
                prevX = ix;
                prevY = iy;
                if (tx < ty) {
                    px = dx > 0 ? ix + 1 : ix;
                    py += dy * t;
                    ix += dx > 0 ? 1 : -1;
                    faceAxis = 0;
                } else {
                    py = dy > 0 ? iy + 1 : iy;
                    px += dx * t;
                    iy += dy > 0 ? 1 : -1;
                    faceAxis = 1;
                }
                entryX = px;
                entryY = py;
                if (!m_.emission.inside(ix, iy)) return score + m_.boundaryRadiance[c];
            }
            if (!collided) break;
            score += m_.emission.at(ix, iy, c);
            const float rho = m_.reflectance.empty() ? 0.0f : m_.reflectance.at(ix, iy, c);
            if (rho > 0 && faceAxis >= 0) {
                if (rng.nextDouble() >= rho) break;
                // Back to the entry point, into the pixel the path came from; the normal points
                // against the direction it entered by.
                const double nx = faceAxis == 0 ? (dx > 0 ? -1 : 1) : 0;
                const double ny = faceAxis == 1 ? (dy > 0 ? -1 : 1) : 0;
                const double sinT = 2 * rng.nextDouble() - 1, cosT = std::sqrt(1 - sinT * sinT);
                dx = nx * cosT - ny * sinT;
                dy = ny * cosT + nx * sinT;
                px = entryX;
                py = entryY;
                ix = prevX;
                iy = prevY;
                continue;
            }
            const float albedo = m_.scattering.empty() ? 0.0f : m_.scattering.at(ix, iy, c);
            if (rng.nextDouble() >= albedo) break;
            angle = 2 * std::numbers::pi * rng.nextDouble();
            dx = std::cos(angle);
            dy = std::sin(angle);
        }
        return score;
    }

    const Medium2D& m_;
};

}  // namespace luxel::gi2d::test
