// Scene albedo -> Medium2D::scattering / reflectance, called by rasterize() when the scene has any
// albedo (docs/algorithms/scattering-2d.md). The scene is rasterised twice more with each
// material's albedo in place of its emission, so coverage follows the same rule as emission: once
// with the opaque materials' albedo (-> reflectance), once with the others' and the background's
// (-> scattering). Image layers count as scattering.
#pragma once

#include "luxel/core/error.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/scene2d.h"

namespace luxel::gi2d::detail {

Status rasterizeAlbedo(const Scene2D& scene, const RasterOptions& options, Medium2D& medium);

}  // namespace luxel::gi2d::detail
