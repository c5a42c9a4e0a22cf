// Uploading an octree's arrays (octree_device_arrays.h).
#include "octree/octree_device_arrays.h"

#include <span>
#include <vector>

#include "luxel/core/memory.h"

namespace luxel::octree {
namespace {

Result<std::shared_ptr<gpu::Buffer>> uploadWords(gpu::Context& context,
                                                 std::span<const std::uint32_t> words) {
    auto buffer = context.createBuffer(words.size() * sizeof(std::uint32_t));
    if (!buffer) return buffer.error();
    if (Status s = context.upload(**buffer, std::as_bytes(words)); !s) return s.error();
    return std::move(*buffer);
}

}  // namespace

std::uint64_t octreeDeviceBytes(const Octree& tree) {
    const std::uint64_t colourWords = tree.hasColours() ? tree.colours.size() : 1;
    const std::uint64_t countWords = tree.leafOrder() ? tree.leafCounts.size() : 1;
    return (tree.nodes.size() + colourWords + countWords) * sizeof(std::uint32_t);
}

Result<OctreeDeviceArrays> uploadOctreeArrays(gpu::Context& context, const Octree& tree,
                                              std::uint64_t extraBytes) {
    const std::uint64_t bytes = octreeDeviceBytes(tree) + extraBytes;
    const std::uint64_t limit = context.device().deviceLocalBytes;
    if (limit > 0 && bytes > limit) {
        return Error("octree of " + formatBytes(bytes) + " does not fit the device's " +
                     formatBytes(limit));
    }
    OctreeDeviceArrays arrays;
    arrays.bytes = octreeDeviceBytes(tree);
    arrays.hasColours = tree.hasColours();
    arrays.leafOrder = tree.leafOrder();
    arrays.shape.depth = tree.depth;
    arrays.shape.size = tree.size;
    auto nodes = uploadWords(context, tree.nodes);
    if (!nodes) return nodes.error();
    arrays.nodes = std::move(*nodes);
    std::vector<std::uint32_t> packed(tree.hasColours() ? tree.colours.size() : 1, 0);
    for (std::size_t i = 0; i < tree.colours.size(); ++i) {
        const Colour& c = tree.colours[i];
        packed[i] = std::uint32_t{c.r} | std::uint32_t{c.g} << 8 | std::uint32_t{c.b} << 16 |
                    std::uint32_t{c.a} << 24;
    }
    auto colours = uploadWords(context, packed);
    if (!colours) return colours.error();
    arrays.colours = std::move(*colours);
    const std::vector<std::uint32_t> dummy(1, 0);
    auto counts = uploadWords(context, tree.leafOrder() ? std::span(tree.leafCounts)
                                                        : std::span<const std::uint32_t>(dummy));
    if (!counts) return counts.error();
    arrays.leafCounts = std::move(*counts);
    return arrays;
}

}  // namespace luxel::octree
