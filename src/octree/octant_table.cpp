#include "octant_table.h"

#include <cstring>

namespace luxel::octree {
namespace {

std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
    h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h *= 0xff51afd7ed558ccdull;
    return h ^ (h >> 32);
}

std::uint32_t packed(const Colour& c) {
    return static_cast<std::uint32_t>(c.r) | static_cast<std::uint32_t>(c.g) << 8 |
           static_cast<std::uint32_t>(c.b) << 16 | static_cast<std::uint32_t>(c.a) << 24;
}

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
    for (std::uint64_t o = 1; o < octants; ++o) {
        const auto base = static_cast<std::uint32_t>(o * 8);
        const Colour* colours = perEntry() ? &tree_.colours[base] : nullptr;
        const std::uint64_t h = hashOf(&tree_.nodes[base], colours);
        // Keep the first of duplicate octants (an input array may hold copies).
        bool present = false;
        for (std::uint64_t i = h & (slots_.size() - 1);; i = (i + 1) & (slots_.size() - 1)) {
            if (slots_[i] == 0) break;
            if (equalAt(slots_[i] * 8, &tree_.nodes[base], colours)) {
                present = true;
                break;
            }
        }
        if (!present) insert(base, h);
    }
}

std::uint64_t OctantTable::hashOf(const std::uint32_t* entries, const Colour* colours) const {
    std::uint64_t h = 0x51ed270b27e1c3a5ull;
    for (int i = 0; i < 8; ++i) h = mix(h, entries[i]);
    if (colours) {
        for (int i = 0; i < 8; ++i) h = mix(h, packed(colours[i]));
    }
    return h;
}

bool OctantTable::equalAt(std::uint32_t base, const std::uint32_t* entries,
                          const Colour* colours) const {
    if (std::memcmp(&tree_.nodes[base], entries, 8 * sizeof(std::uint32_t)) != 0) return false;
    if (!colours) return true;
    for (int i = 0; i < 8; ++i) {
        if (!(tree_.colours[base + i] == colours[i])) return false;
    }
    return true;
}

void OctantTable::insert(std::uint32_t base, std::uint64_t hash) {
    std::uint64_t i = hash & (slots_.size() - 1);
    while (slots_[i] != 0) i = (i + 1) & (slots_.size() - 1);
    slots_[i] = base / 8;
    ++used_;
}

void OctantTable::grow() {
    std::vector<std::uint32_t> old;
    old.swap(slots_);
    slots_.assign(old.size() * 2, 0);
    used_ = 0;
    for (std::uint32_t octant : old) {
        if (octant == 0) continue;
        const std::uint32_t base = octant * 8;
        const Colour* colours = perEntry() ? &tree_.colours[base] : nullptr;
        insert(base, hashOf(&tree_.nodes[base], colours));
    }
}

std::uint32_t OctantTable::intern(const std::uint32_t* entries, const Colour* colours) {
    if (!perEntry()) colours = nullptr;
    const std::uint64_t h = hashOf(entries, colours);
    std::uint64_t i = h & (slots_.size() - 1);
    for (; slots_[i] != 0; i = (i + 1) & (slots_.size() - 1)) {
        if (equalAt(slots_[i] * 8, entries, colours)) return slots_[i] * 8;
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
    slots_[i] = base / 8;
    ++used_;
    if (2 * used_ > slots_.size()) grow();
    return base;
}

}  // namespace luxel::octree
