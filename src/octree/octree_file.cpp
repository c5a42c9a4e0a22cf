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
    std::string out;
    out.reserve(kOctreeHeaderBytes + tree.nodes.size() * 4 + tree.colours.size() * 4);
    out.append(kOctreeMagic);
    put<std::uint32_t>(out, kOctreeFileVersion);
    put<std::uint32_t>(out, static_cast<std::uint32_t>(tree.depth));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(tree.size.x));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(tree.size.y));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(tree.size.z));
    put<std::uint32_t>(out, tree.hasColours() ? kColoursFlag : 0);
    put<std::uint64_t>(out, tree.nodes.size());
    for (std::uint32_t v : tree.nodes) put<std::uint32_t>(out, v);
    for (const Colour& c : tree.colours) {
        const char rgba[4] = {static_cast<char>(c.r), static_cast<char>(c.g),
                              static_cast<char>(c.b), static_cast<char>(c.a)};
        out.append(rgba, 4);
    }
    return out;
}

Result<Octree> parseOctree(std::string_view bytes, const std::string& name) {
    auto fail = [&](const std::string& problem) { return Error(name + ": " + problem); };
    if (bytes.size() < kOctreeHeaderBytes || bytes.substr(0, 8) != kOctreeMagic) {
        return fail("not a luxel octree file (it does not start with \"LXOCTREE\")");
    }
    const auto version = get<std::uint32_t>(bytes, 8);
    if (version != kOctreeFileVersion) {
        return fail("octree file version " + std::to_string(version) +
                    " is not supported (this luxel reads version " +
                    std::to_string(kOctreeFileVersion) + ")");
    }
    const auto depth = get<std::uint32_t>(bytes, 12);
    Int3 size;
    for (int a = 0; a < 3; ++a) {
        const auto v = get<std::uint32_t>(bytes, 16 + 4 * a);
        if (v > (1u << kMaxDepth)) return fail("size " + std::to_string(v) + " is too large");
        size[a] = static_cast<int>(v);
    }
    const auto flags = get<std::uint32_t>(bytes, 28);
    const auto count = get<std::uint64_t>(bytes, 32);
    if ((flags & ~kColoursFlag) != 0) {
        return fail("unknown flags " + std::to_string(flags) + " in the header");
    }
    if (depth < 1 || depth > static_cast<std::uint32_t>(kMaxDepth)) {
        return fail("depth " + std::to_string(depth) + " is outside 1.." +
                    std::to_string(kMaxDepth));
    }
    const bool colours = (flags & kColoursFlag) != 0;
    const std::uint64_t payload = bytes.size() - kOctreeHeaderBytes;
    const std::uint64_t perEntry = colours ? 8 : 4;
    // Compare before multiplying: a hostile count must not overflow or allocate.
    if (count > payload / perEntry || count * perEntry != payload) {
        return fail("the header says " + std::to_string(count) + " entries" +
                    (colours ? " with colours" : "") + " but " + std::to_string(payload) +
                    " bytes follow it (" + std::to_string(perEntry) + " per entry)");
    }
    if (Status s = checkMemory(count * perEntry, "octree " + name); !s) return s.error();
    Octree tree;
    tree.depth = static_cast<int>(depth);
    tree.size = size;
    tree.nodes.resize(count);
    for (std::uint64_t i = 0; i < count; ++i) {
        tree.nodes[i] = get<std::uint32_t>(bytes, kOctreeHeaderBytes + 4 * i);
    }
    if (colours) {
        tree.colours.resize(count);
        const std::size_t at = kOctreeHeaderBytes + 4 * count;
        for (std::uint64_t i = 0; i < count; ++i) {
            const auto* c = reinterpret_cast<const unsigned char*>(bytes.data() + at + 4 * i);
            tree.colours[i] = Colour{c[0], c[1], c[2], c[3]};
        }
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
