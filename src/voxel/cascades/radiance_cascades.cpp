// The voxel radiance cascades' public face (radiance_cascades.h): the plan and its memory,
// building, lighting passes, the interpolated irradiance.
#include "luxel/voxel/radiance_cascades.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "cascade_passages.h"
#include "cascade_state.h"
#include "luxel/core/memory.h"
#include "luxel/voxel/path_trace.h"

namespace luxel::voxel {

using namespace cascades;

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::uint64_t memoryLimit(const CascadeOptions& options) {
    if (options.memoryLimit > 0) return options.memoryLimit;
    const std::uint64_t cap = std::uint64_t(2) << 30, available = availableMemoryBytes();
    return available > 0 ? std::min(cap, available) : cap;
}

}  // namespace

CascadeEstimate estimateCascades(const VoxelWorld& world, const CascadeOptions& options) {
    CascadeEstimate e;
    e.limit = memoryLimit(options);
    e.faces = FaceTable::countExposed(world);
    int binsPerFace = 0;
    for (const auto& seen : DirectionBins::build(kFaceBinSide).cosine) {
        binsPerFace = std::max(binsPerFace, int(seen.bin.size()));
    }
    e.spacing = options.spacing > 0 ? options.spacing : 2;
    std::vector<Level> levels = planLevels(world.size(), e.spacing);
    while (options.spacing == 0 && e.spacing < kMaxCascadeSpacing &&
           cascadeBytes(levels, e.faces, binsPerFace) > e.limit) {
        e.spacing *= 2;
        levels = planLevels(world.size(), e.spacing);
    }
    e.levels = int(levels.size());
    for (const Level& level : levels) e.probes += level.probeCount();
    e.bytes = cascadeBytes(levels, e.faces, binsPerFace);
    e.fits = e.bytes <= e.limit;
    return e;
}

Status validateCascades(const CascadeOptions& o) {
    if (o.spacing != 0 &&
        (o.spacing < 1 || o.spacing > kMaxCascadeSpacing || (o.spacing & (o.spacing - 1)) != 0)) {
        return Error("cascade spacing must be a power of two in 1.." +
                     std::to_string(kMaxCascadeSpacing) + " (or 0 for automatic), got " +
                     std::to_string(o.spacing));
    }
    if (o.bounces < 0 || o.bounces > kMaxCascadeBounces) {
        return Error("cascade bounces must be in 0.." + std::to_string(kMaxCascadeBounces) +
                     " (0: until converged), got " + std::to_string(o.bounces));
    }
    if (!(o.tolerance > 0.0 && o.tolerance < 1.0)) {
        std::ostringstream s;
        s << o.tolerance;
        return Error("cascade tolerance must be in (0, 1), got " + s.str());
    }
    return Ok{};
}

RadianceCascades::RadianceCascades(std::unique_ptr<State> state) : state_(std::move(state)) {}
RadianceCascades::RadianceCascades(RadianceCascades&&) noexcept = default;
RadianceCascades& RadianceCascades::operator=(RadianceCascades&&) noexcept = default;
RadianceCascades::~RadianceCascades() = default;

Result<RadianceCascades> RadianceCascades::create(const VoxelWorld& world,
                                                  const TextureSet* textures,
                                                  const ShadeOptions& shading,
                                                  const CascadeOptions& options) {
    if (Status s = validateCascades(options); !s) return s.error();
    if (Status s = validatePathTrace(shading, PathTraceOptions{}); !s) return s.error();
    const auto start = std::chrono::steady_clock::now();
    const CascadeEstimate estimate = estimateCascades(world, options);
    if (Status s = checkEstimate(estimate); !s) return s.error();
    if (Status s = checkMemory(estimate.bytes, "radiance cascades"); !s) return s.error();

    auto state = std::make_unique<State>();
    state->world = &world;
    state->textures = textures;
    state->shading = shading;
    state->options = options;
    state->memoryLimit = estimate.limit;
    state->faces.bins = DirectionBins::build(kFaceBinSide);
    if (Status s = buildSegments(*state); !s) return s.error();
    updateFaceLight(*state);
    updateStats(*state);
    state->stats.buildSeconds = secondsSince(start);
    return RadianceCascades(std::move(state));
}

Status RadianceCascades::setLight(const ShadeOptions& shading) {
    if (Status s = validatePathTrace(shading, PathTraceOptions{}); !s) return s.error();
    state_->shading = shading;
    // Which voxels the segments pass, and what passes, depends on the glass's materials.
    // A cast refused before is tried again (the new light may let less through).
    Status cast = Ok{};
    const bool rebuild =
        !state_->castComplete || cascades::mediaSignature(shading) != state_->castMedia;
    if (rebuild) {
        state_->faces.clearEmitterLight();  // their light through glass is found again
        cast = cascades::buildSegments(*state_);
    }
    // Even when the cast is refused the faces' light stays consistent with the codes it left.
    updateFaceLight(*state_);
    if (rebuild) cascades::updateStats(*state_);  // with the sun rays' map made for this light
    return cast;
}

double RadianceCascades::iterate() {
    ++state_->stats.bounces;
    return lightingPass(*state_);
}

int RadianceCascades::solve() {
    const int limit = state_->options.bounces > 0 ? state_->options.bounces : kMaxCascadeBounces;
    int passes = 0;
    while (passes < limit) {
        const double change = iterate();
        ++passes;
        if (state_->options.bounces == 0 && change < state_->options.tolerance) break;
    }
    return passes;
}

Rgb RadianceCascades::indirectIrradiance(Int3 voxel, Int3 normal, Vec3d point) const {
    return interpolatedIrradiance(state_->faces, state_->faces.emitterIrradiance, voxel, normal,
                                  point);
}

Rgb cascades::interpolatedIrradiance(const FaceData& faces, const std::vector<Rgb>& emitter,
                                     Int3 voxel, Int3 normal, Vec3d point, int* face) {
    const int n = normalIndex(normal), axis = n / 2, a = (axis + 1) % 3, b = (axis + 2) % 3;
    // Bilinear between the centres of this face and its neighbours in the plane; a neighbour
    // counts when it is an open face too, and a diagonal one only through an open side neighbour
    // (so light does not cross the corner of a wall).
    const double fa = point[a] - voxel[a] - 0.5, fb = point[b] - voxel[b] - 0.5;
    const int da = fa < 0.0 ? -1 : 1, db = fb < 0.0 ? -1 : 1;
    const double wa = std::abs(fa), wb = std::abs(fb);
    const FaceTable& table = faces.table;
    const int self = table.find(voxel, n);
    int sideA, sideB, diagonal;
    if (self >= 0) {  // its neighbours found when the table was built
        sideA = table.neighbour(self, da, 0), sideB = table.neighbour(self, 0, db);
        diagonal = (sideA >= 0 || sideB >= 0) ? table.neighbour(self, da, db) : -1;
    } else {
        Int3 va = voxel, vb = voxel, vab = voxel;
        va[a] += da, vb[b] += db, vab[a] += da, vab[b] += db;
        sideA = table.find(va, n), sideB = table.find(vb, n);
        diagonal = (sideA >= 0 || sideB >= 0) ? table.find(vab, n) : -1;
    }
    if (face) *face = self;
    const int ids[4] = {self, sideA, sideB, diagonal};
    const double weights[4] = {(1 - wa) * (1 - wb), wa * (1 - wb), (1 - wa) * wb, wa * wb};
    Rgb sum;
    double total = 0.0;
    for (int i = 0; i < 4; ++i) {
        if (ids[i] < 0) continue;
        sum += (faces.irradiance[ids[i]] + emitter[ids[i]]) * float(weights[i]);
        total += weights[i];
    }
    return total > 0.0 ? sum * float(1.0 / total) : Rgb{};
}

CascadeStats RadianceCascades::stats() const {
    return state_->stats;
}

Result<CascadeImage> cascades::renderCascadesWith(
    const VoxelWorld& world, const Camera& camera, const ShadeOptions& shading,
    const CascadeOptions& options, const TextureSet* textures,
    const std::function<Status(RadianceCascades&)>& solve) {
    Result<RadianceCascades> cascades = RadianceCascades::create(world, textures, shading, options);
    if (!cascades) return cascades.error();
    CascadeImage out;
    auto start = std::chrono::steady_clock::now();
    if (Status s = solve(*cascades); !s) return s.error();
    out.lightSeconds = secondsSince(start);
    start = std::chrono::steady_clock::now();
    Result<Image> image = cascades->render(camera, &out.refinedPixels);
    if (!image) return image.error();
    out.renderSeconds = secondsSince(start);
    out.radiance = std::move(*image);
    out.stats = cascades->stats();
    return out;
}

Result<CascadeImage> renderRadianceCascades(const VoxelWorld& world, const Camera& camera,
                                            const ShadeOptions& shading,
                                            const CascadeOptions& options,
                                            const TextureSet* textures) {
    return renderCascadesWith(world, camera, shading, options, textures,
                              [](RadianceCascades& cascades) -> Status {
                                  cascades.solve();
                                  return Ok{};
                              });
}

}  // namespace luxel::voxel
