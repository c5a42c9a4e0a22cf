// Scene albedo -> Medium2D::scattering / reflectance, for media whose rasteriser left them empty.
//
// Interim: the rasteriser is meant to fill these images itself; until it does, the CLI and the
// viewer call this after rasterize(). It rasterises the scene twice more with each material's
// albedo in place of its emission (so coverage follows the same rule as emission): once with the
// opaque materials' albedo (-> reflectance), once with the others' and the background's
// (-> scattering). Image layers count as scattering. Does nothing when the medium already has
// bounce images or the scene has no albedo.
#pragma once

#include "luxel/core/error.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/scene2d.h"

namespace luxel::gi2d {

// Whether any material, the background or an image layer has a non-zero albedo.
bool sceneBounces(const Scene2D& scene);

Status fillBounceImages(const Scene2D& scene, const RasterOptions& options, Medium2D& medium);

}  // namespace luxel::gi2d
