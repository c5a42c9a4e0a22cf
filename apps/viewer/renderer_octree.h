// The octree frame producer on the render thread: owns the tree, renders the posted view through
// an OctreeFrameSource and tone maps. When a full frame is slow (volume scattering on the CPU can
// take seconds), a changed view is first drawn at a quarter of each side so dragging stays
// responsive, then refined to the full internal resolution.
#pragma once

#include <memory>

#include "frame.h"
#include "luxel/octree/octree.h"
#include "octree_controls.h"
#include "octree_frame_source.h"

namespace luxel::viewer {

// Full frames slower than this get a preview first (the UI shows ~6 previews a second).
inline constexpr double kOctreePreviewAboveMs = 150.0;
inline constexpr int kOctreePreviewDivisor = 4;

class RendererOctree {
  public:
    using State = OctreeViewState;
    RendererOctree(std::shared_ptr<const octree::Octree> tree,
                   std::unique_ptr<OctreeFrameSource> source);

    void setState(OctreeViewState&& state);
    bool hasMoreWork() const { return dirty_; }
    // A preview (converged false) or the full frame; both at the state's internal size.
    Frame step();

  private:
    Frame render(int width, int height);

    std::shared_ptr<const octree::Octree> tree_;
    std::unique_ptr<OctreeFrameSource> source_;
    OctreeViewState state_;
    bool dirty_ = false;
    bool previewDue_ = false;
    double lastFullMs_ = 0.0;  // 0 until a full frame was timed
};

}  // namespace luxel::viewer
