// The five HRC GPU passes as units (shaders src/gpu/shaders/gi2d/hrc_*.comp.glsl): one dispatch
// builder per pass, used by solveHrcOnGpu, and one single-pass entry per pass with the inputs and
// outputs of its CPU twin, so tests compare the passes one by one:
//   hrc_trace   traceLevelOnGpu     CPU twin traceLevel     (ray_tables.h)
//   hrc_extend  extendLevelOnGpu    CPU twin extendLevel    (ray_tables.h)
//   hrc_merge   mergeCascadeOnGpu   CPU twin mergeCascade   (cone_merge.h)
//   hrc_readout readOutOnGpu        CPU twin readOut        (readout.h)
//   hrc_finish  finishOnGpu         CPU twin finishFluence  (finish.h)
// and hrc_near_field (CPU twin gatherNearFieldInPlace, near_field.h), compared through the whole
// solve.
// Every single-pass entry uploads its inputs, runs the pass, reads the output back and returns the
// pass's GPU time in milliseconds.
#pragma once

#include <string>

#include "gi2d/hrc/cone_merge.h"
#include "gi2d/hrc/frustum_frame.h"
#include "gi2d/hrc/ray_tables.h"
#include "luxel/core/image.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gpu/context.h"

namespace luxel::gi2d::hrc {

// Dispatch builders: buffers in the order the shader binds them.
// The trace pass reads the canvas medium through `frame` (hrcFrameToCanvas): `medium` is the
// row-major canvas medium for the +-y frustums and the transposed one for +-x
// (traceReadsTransposed).
gpu::Dispatch makeTraceDispatch(gpu::Program* program, gpu::Buffer* medium, gpu::Buffer* table,
                                int n, const FrustumFrame& frame, int planes, float depthScale);
bool traceReadsTransposed(const FrustumFrame& frame);
gpu::Dispatch makeExtendDispatch(gpu::Program* program, gpu::Buffer* below, gpu::Buffer* table,
                                 int n, int rows, int planesBelow, int planes);
// `upper` null at the top cascade; `nearLights` (the NearLightMask's bytes, read at cascade 0 in
// `frame`) null for none.
gpu::Dispatch makeMergeDispatch(gpu::Program* program, gpu::Buffer* table, gpu::Buffer* upper,
                                gpu::Buffer* out, gpu::Buffer* weights, gpu::Buffer* nearLights,
                                int n, const FrustumFrame& frame, int planes, int upperPlanes,
                                Rgb sky);
gpu::Dispatch makeReadoutDispatch(gpu::Program* program, gpu::Buffer* cones, gpu::Buffer* beyond,
                                  const FrustumFrame& frame, Rgb sky);
// The medium's column-major copy from its row-major one (medium_transpose.comp.glsl).
gpu::Dispatch makeTransposeDispatch(gpu::Program* program, gpu::Buffer* rows, gpu::Buffer* columns,
                                    int width, int height);
gpu::Dispatch makeFinishDispatch(gpu::Program* program, gpu::Buffer* canvasMedium,
                                 gpu::Buffer* beyond, gpu::Buffer* fluence, int width, int height,
                                 int frustums, bool blur);
// The exact near field (§12.3, hrc_near_field.comp.glsl) over `count` listed pixels of `fluence`.
gpu::Dispatch makeNearFieldDispatch(gpu::Program* program, gpu::Buffer* canvasMedium,
                                    gpu::Buffer* pixels, gpu::Buffer* fluence, int width,
                                    int height, std::uint32_t count, Rgb sky, float reach);

// T_n of `tables` marched through `medium` seen in `frame`, the optical depth times `depthScale`
// (CPU twin: traceLevel on frameMedium(medium, frame)).
Result<double> traceLevelOnGpu(gpu::Context& context, const Medium2D& medium,
                               const FrustumFrame& frame, RayTables& tables, int n,
                               float depthScale = 1.0f);
// T_n from T_{n-1}.
Result<double> extendLevelOnGpu(gpu::Context& context, RayTables& tables, int n);
// R_n into `out` from T_n, T_{n+1} weights and `upper` (null at the top), cascade 0 weighed by
// `nearLights` where it has a mask.
Result<double> mergeCascadeOnGpu(gpu::Context& context, const RayTables& tables, int n,
                                 const ConeBuffer* upper, Rgb sky, ConeBuffer& out,
                                 const MergeNearLights& nearLights = {});
// Adds R_0 (`cones`) at each pixel's read-out plane into `beyondSum`.
Result<double> readOutOnGpu(gpu::Context& context, const FrustumFrame& frame,
                            const ConeBuffer& cones, Rgb sky, Image& beyondSum);
// The finished fluence from `beyond`.
Result<double> finishOnGpu(gpu::Context& context, const Medium2D& medium, const Image& beyond,
                           int frustums, bool blur, Image& fluence);

}  // namespace luxel::gi2d::hrc
