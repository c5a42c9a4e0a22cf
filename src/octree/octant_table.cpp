#include "octant_table.h"

#include <cstring>

namespace luxel::octree {
namespace {

// 64x64 -> 128-bit multiply folded to 64 bits (the mixing step of wyhash): two words per
// multiply, and the four products of an octant are independent, so they overlap in the pipeline.
__extension__ using Wide = unsigned __int128;
std::uint64_t fold(std::uint64_t a, std::uint64_t b) {
    const Wide p = static_cast<Wide>(a) * b;
    return static_cast<std::uint64_t>(p) ^ static_cast<std::uint64_t>(p >> 64);
}

std::uint64_t load64(const void* p) {
    std::uint64_t v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// Hash of 32 bytes (8 entries or 8 colours) seeded with h.
std::uint64_t hash32Bytes(const void* data, std::uint64_t h) {
    const auto* p = static_cast<const unsigned char*>(data);
    constexpr std::uint64_t k0 = 0xa0761d6478bd642full, k1 = 0xe7037ed1a0b428dbull,
                            k2 = 0x8ebc6af09c88c6e3ull, k3 = 0x589965cc75374cc3ull;
    const std::uint64_t a = fold(load64(p) ^ k0, load64(p + 8) ^ k1 ^ h);
    const std::uint64_t b = fold(load64(p + 16) ^ k2, load64(p + 24) ^ k3 ^ h);
    return fold(a ^ k1, b ^ k0);
}

constexpr std::uint64_t kOctantMask = 0xffffffffull;

}  // namespace

OctantTable::OctantTable(Octree& tree) : tree_(tree) {
    reindex();
}

void OctantTable::reindex() {
    const std::uint64_t octants = tree_.nodes.size() / 8;
    std::uint64_t capacity = 1024;
    while (capacity < 2 * octants) capacity *= 2;
    slots_.assign(capacity, 0);
    used_ = 0;
    const std::uint64_t mask = slots_.size() - 1;
    for (std::uint64_t o = 1; o < octants; ++o) {
        const auto base = static_cast<std::uint32_t>(o * 8);
        const Colour* colours = perEntry() ? &tree_.colours[base] : nullptr;
        const std::uint64_t h = hashOf(&tree_.nodes[base], colours);
        const auto tag = static_cast<std::uint32_t>(h >> 32);
        // Keep the first of duplicate octants (an input array may hold copies).
        bool present = false;
        for (std::uint64_t i = tag & mask; slots_[i] != 0; i = (i + 1) & mask) {
            if ((slots_[i] >> 32) == tag &&
                equalAt(static_cast<std::uint32_t>(slots_[i] & kOctantMask) * 8, &tree_.nodes[base],
                        colours)) {
                present = true;
                break;
            }
        }
        if (!present) insert(static_cast<std::uint32_t>(o), tag);
    }
}

std::uint64_t OctantTable::hashOf(const std::uint32_t* entries, const Colour* colours) const {
    static_assert(sizeof(Colour) == 4, "colours hash as 32 bytes per octant");
    std::uint64_t h = hash32Bytes(entries, 0x51ed270b27e1c3a5ull);
    if (colours) h = hash32Bytes(colours, h);
    return h;
}

bool OctantTable::equalAt(std::uint32_t base, const std::uint32_t* entries,
                          const Colour* colours) const {
    if (std::memcmp(&tree_.nodes[base], entries, 8 * sizeof(std::uint32_t)) != 0) return false;
    if (!colours) return true;
    return std::memcmp(&tree_.colours[base], colours, 8 * sizeof(Colour)) == 0;
}

// An octant's home slot is picked by its tag (the hash's high 32 bits), so growing needs only the
// tags the slots keep.
void OctantTable::insert(std::uint32_t octant, std::uint32_t tag) {
    const std::uint64_t mask = slots_.size() - 1;
    std::uint64_t i = tag & mask;
    while (slots_[i] != 0) i = (i + 1) & mask;
    slots_[i] = static_cast<std::uint64_t>(tag) << 32 | octant;
    ++used_;
}

void OctantTable::grow() {
    std::vector<std::uint64_t> old;
    old.swap(slots_);
    slots_.assign(old.size() * 2, 0);
    used_ = 0;
    for (std::uint64_t slot : old) {
        if (slot != 0)
            insert(static_cast<std::uint32_t>(slot & kOctantMask),
                   static_cast<std::uint32_t>(slot >> 32));
    }
}

std::uint32_t OctantTable::intern(const std::uint32_t* entries, const Colour* colours) {
    return intern(entries, colours, hash(entries, colours));
}

std::uint32_t OctantTable::intern(const std::uint32_t* entries, const Colour* colours,
                                  std::uint64_t hash) {
    if (!perEntry()) colours = nullptr;
    const auto tag = static_cast<std::uint32_t>(hash >> 32);
    const std::uint64_t mask = slots_.size() - 1;
    std::uint64_t i = tag & mask;
    for (; slots_[i] != 0; i = (i + 1) & mask) {
        if ((slots_[i] >> 32) != tag) continue;
        const auto base = static_cast<std::uint32_t>(slots_[i] & kOctantMask) * 8;
        if (equalAt(base, entries, colours)) return base;
    }
    if (tree_.nodes.size() + 8 > kMaxEntries) return 0;
    const auto base = static_cast<std::uint32_t>(tree_.nodes.size());
    tree_.nodes.insert(tree_.nodes.end(), entries, entries + 8);
    if (perEntry()) {
        if (colours) {
            tree_.colours.insert(tree_.colours.end(), colours, colours + 8);
        } else {
            tree_.colours.resize(tree_.colours.size() + 8);
        }
    }
    slots_[i] = static_cast<std::uint64_t>(tag) << 32 | (base / 8);
    ++used_;
    if (2 * used_ > slots_.size()) grow();
    return base;
}

}  // namespace luxel::octree
