#include "luxel/octree/octree_file.h"

#include <cstring>

#include "luxel/core/file_io.h"
#include "luxel/core/memory.h"
#include "luxel/octree/octree_validate.h"

namespace luxel::octree {
namespace {

constexpr std::uint32_t kColoursFlag = 1;

template <typename T>
void put(std::string& out, T value) {
    unsigned char bytes[sizeof(T)];
    for (std::size_t i = 0; i < sizeof(T); ++i) {
        bytes[i] =
            static_cast<unsigned char>((static_cast<std::uint64_t>(value) >> (8 * i)) & 0xff);
    }
    out.append(reinterpret_cast<const char*>(bytes), sizeof(T));
}

template <typename T>
T get(std::string_view bytes, std::size_t offset) {
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i) {
        v |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[offset + i])) << (8 * i);
    }
    return static_cast<T>(v);
}

}  // namespace

std::string serializeOctree(const Octree& tree) {
    const AttributeLayout layout = tree.attributes();
    const bool leafOrder = layout == AttributeLayout::LeafOrder;
    std::string out;
    out.reserve(kOctreeHeaderBytes + tree.nodes.size() * 4 + tree.colours.size() * 4 +
                (leafOrder ? tree.leafCounts.size() * 4 : 0));
    out.append(kOctreeMagic);
    put<std::uint32_t>(out, kOctreeFileVersion);
    put<std::uint32_t>(out, static_cast<std::uint32_t>(tree.depth));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(tree.size.x));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(tree.size.y));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(tree.size.z));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(layout));
    put<std::uint64_t>(out, tree.nodes.size());
    put<std::uint64_t>(out, tree.colours.size());
    for (std::uint32_t v : tree.nodes) put<std::uint32_t>(out, v);
    if (leafOrder) {
        for (std::uint32_t v : tree.leafCounts) put<std::uint32_t>(out, v);
    }
    for (const Colour& c : tree.colours) {
        const char rgba[4] = {static_cast<char>(c.r), static_cast<char>(c.g),
                              static_cast<char>(c.b), static_cast<char>(c.a)};
        out.append(rgba, 4);
    }
    return out;
}

Result<Octree> parseOctree(std::string_view bytes, const std::string& name) {
    auto fail = [&](const std::string& problem) { return Error(name + ": " + problem); };
    if (bytes.size() < kOctreeHeaderBytesV1 || bytes.substr(0, 8) != kOctreeMagic) {
        return fail("not a luxel octree file (it does not start with \"LXOCTREE\")");
    }
    const auto version = get<std::uint32_t>(bytes, 8);
    if (version != 1 && version != kOctreeFileVersion) {
        return fail("octree file version " + std::to_string(version) +
                    " is not supported (this luxel reads versions 1 and " +
                    std::to_string(kOctreeFileVersion) + ")");
    }
    const std::size_t header = version == 1 ? kOctreeHeaderBytesV1 : kOctreeHeaderBytes;
    if (bytes.size() < header) return fail("the header is cut short");
    const auto depth = get<std::uint32_t>(bytes, 12);
    Int3 size;
    for (int a = 0; a < 3; ++a) {
        const auto v = get<std::uint32_t>(bytes, 16 + 4 * a);
        if (v > (1u << kMaxDepth)) return fail("size " + std::to_string(v) + " is too large");
        size[a] = static_cast<int>(v);
    }
    const auto field = get<std::uint32_t>(bytes, 28);
    const auto count = get<std::uint64_t>(bytes, 32);
    AttributeLayout layout = AttributeLayout::None;
    if (version == 1) {
        if ((field & ~kColoursFlag) != 0) {
            return fail("unknown flags " + std::to_string(field) + " in the header");
        }
        if (field & kColoursFlag) layout = AttributeLayout::PerEntry;
    } else {
        if (field > static_cast<std::uint32_t>(AttributeLayout::LeafOrder)) {
            return fail("unknown attribute layout " + std::to_string(field) +
                        " in the header (0 none, 1 per-entry, 2 leaf-order)");
        }
        layout = static_cast<AttributeLayout>(field);
    }
    if (depth < 1 || depth > static_cast<std::uint32_t>(kMaxDepth)) {
        return fail("depth " + std::to_string(depth) + " is outside 1.." +
                    std::to_string(kMaxDepth));
    }
    const std::uint64_t payload = bytes.size() - header;
    const bool leafOrder = layout == AttributeLayout::LeafOrder;
    std::uint64_t colourCount = 0;
    if (version == 1) {
        colourCount = layout == AttributeLayout::PerEntry ? count : 0;
    } else {
        colourCount = get<std::uint64_t>(bytes, 40);
        if (layout == AttributeLayout::None && colourCount != 0) {
            return fail("the header says " + std::to_string(colourCount) +
                        " colours but no attribute layout");
        }
        if (layout == AttributeLayout::PerEntry && colourCount != count) {
            return fail("the header says " + std::to_string(colourCount) + " colours for " +
                        std::to_string(count) + " entries; per-entry colours need one each");
        }
    }
    // Compare before multiplying: hostile counts must not overflow or allocate.
    const std::uint64_t words = payload / 4;
    const std::uint64_t indexWords = leafOrder ? count / 8 : 0;
    if (count > words || colourCount > words || count + indexWords + colourCount != words ||
        payload % 4 != 0) {
        return fail("the header says " + std::to_string(count) + " entries and " +
                    std::to_string(colourCount) + " colours but " + std::to_string(payload) +
                    " bytes follow it");
    }
    if (Status s = checkMemory(payload, "octree " + name); !s) return s.error();
    Octree tree;
    tree.depth = static_cast<int>(depth);
    tree.size = size;
    tree.layout = layout == AttributeLayout::None ? AttributeLayout::PerEntry : layout;
    tree.nodes.resize(count);
    std::size_t at = header;
    for (std::uint64_t i = 0; i < count; ++i, at += 4)
        tree.nodes[i] = get<std::uint32_t>(bytes, at);
    if (leafOrder) {
        tree.leafCounts.resize(indexWords);
        for (std::uint64_t i = 0; i < indexWords; ++i, at += 4) {
            tree.leafCounts[i] = get<std::uint32_t>(bytes, at);
        }
    }
    tree.colours.resize(colourCount);
    for (std::uint64_t i = 0; i < colourCount; ++i, at += 4) {
        const auto* c = reinterpret_cast<const unsigned char*>(bytes.data() + at);
        tree.colours[i] = Colour{c[0], c[1], c[2], c[3]};
    }
    if (Status s = validateOctree(tree); !s) return fail(s.error().message());
    return tree;
}

Result<Octree> readOctreeFile(const std::string& path) {
    // Up to the machine's memory: the header check refuses before allocating the tree.
    auto bytes = readFileBytes(path, "octree", availableMemoryBytes() / 2);
    if (!bytes) return bytes.error();
    return parseOctree(*bytes, path);
}

Status writeOctreeFile(const std::string& path, const Octree& tree) {
    if (Status s = validateOctree(tree); !s) return s;
    return writeFileAtomically(path, serializeOctree(tree), "octree");
}

}  // namespace luxel::octree
