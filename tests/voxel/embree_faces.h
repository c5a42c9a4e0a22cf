// Test and benchmark helper: a voxel world's exposed faces as Embree quads (the outside oracle
// for the voxel DDA, and its speed yardstick). The tests build the BVH at Embree's default quality;
// the benchmark asks for RTC_BUILD_QUALITY_HIGH (spatial splits, the slowest build and fastest
// traversal), so luxel is measured against Embree's best.
#pragma once

#include <embree3/rtcore.h>

#include <algorithm>
#include <limits>
#include <vector>

#include "luxel/voxel/dda.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

// Every solid voxel face that borders empty space (or the world's outside) as an Embree quad.
class FaceScene {
  public:
    explicit FaceScene(const VoxelWorld& world,
                       RTCBuildQuality quality = RTC_BUILD_QUALITY_MEDIUM) {
        device_ = rtcNewDevice(nullptr);
        scene_ = rtcNewScene(device_);
        rtcSetSceneBuildQuality(scene_, quality);
        std::vector<float> vertices;
        std::vector<unsigned> quads;
        const Int3 size = world.size();
        const Int3 normals[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                 {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
        for (int z = 0; z < size.z; ++z) {
            for (int y = 0; y < size.y; ++y) {
                for (int x = 0; x < size.x; ++x) {
                    if (!world.solid(x, y, z)) continue;
                    for (const Int3& n : normals) {
                        if (world.solid(x + n.x, y + n.y, z + n.z)) continue;
                        addFace(vertices, quads, {x, y, z}, n);
                    }
                }
            }
        }
        RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_QUAD);
        rtcSetGeometryBuildQuality(geometry, quality);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                              RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                              vertices.size() / 3));
        std::copy(vertices.begin(), vertices.end(), v);
        auto* q = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4,
                                    4 * sizeof(unsigned), quads.size() / 4));
        std::copy(quads.begin(), quads.end(), q);
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene_, geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(scene_);
    }
    FaceScene(const FaceScene&) = delete;
    FaceScene& operator=(const FaceScene&) = delete;
    ~FaceScene() {
        rtcReleaseScene(scene_);
        rtcReleaseDevice(device_);
    }

    struct OracleHit {
        bool hit;
        Int3 voxel;
        double t;
    };

    OracleHit cast(const Ray& ray) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh{};
        rh.ray.org_x = static_cast<float>(ray.origin.x);
        rh.ray.org_y = static_cast<float>(ray.origin.y);
        rh.ray.org_z = static_cast<float>(ray.origin.z);
        rh.ray.dir_x = static_cast<float>(ray.direction.x);
        rh.ray.dir_y = static_cast<float>(ray.direction.y);
        rh.ray.dir_z = static_cast<float>(ray.direction.z);
        rh.ray.tnear = 0.0f;
        rh.ray.tfar = std::numeric_limits<float>::infinity();
        rh.ray.mask = ~0u;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_, &context, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {false, {}, 0};
        return {true, faceVoxel_[rh.hit.primID], rh.ray.tfar};
    }

    // Whether anything lies along the ray within [0, tMax]: rtcOccluded1, which stops at the first
    // quad found (any hit, not the nearest).
    bool occluded(const Ray& ray, double tMax = kInfinity) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay r{};
        r.org_x = static_cast<float>(ray.origin.x);
        r.org_y = static_cast<float>(ray.origin.y);
        r.org_z = static_cast<float>(ray.origin.z);
        r.dir_x = static_cast<float>(ray.direction.x);
        r.dir_y = static_cast<float>(ray.direction.y);
        r.dir_z = static_cast<float>(ray.direction.z);
        r.tnear = 0.0f;
        r.tfar = static_cast<float>(tMax);
        r.mask = ~0u;
        rtcOccluded1(scene_, &context, &r);
        return r.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
    }

    std::size_t faces() const { return faceVoxel_.size(); }

  private:
    void addFace(std::vector<float>& vertices, std::vector<unsigned>& quads, Int3 voxel, Int3 n) {
        // The face plane and its two in-plane axes.
        const int axis = n.x != 0 ? 0 : (n.y != 0 ? 1 : 2);
        const int u = (axis + 1) % 3, w = (axis + 2) % 3;
        Int3 corner = voxel;
        if (n[axis] > 0) corner[axis] += 1;
        const unsigned base = static_cast<unsigned>(vertices.size() / 3);
        const int du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
        for (int i = 0; i < 4; ++i) {
            Int3 p = corner;
            p[u] += du[i];
            p[w] += dw[i];
            vertices.insert(vertices.end(), {static_cast<float>(p.x), static_cast<float>(p.y),
                                             static_cast<float>(p.z)});
        }
        quads.insert(quads.end(), {base, base + 1, base + 2, base + 3});
        faceVoxel_.push_back(voxel);
    }

    RTCDevice device_;
    RTCScene scene_;
    std::vector<Int3> faceVoxel_;
};

}  // namespace luxel::voxel
