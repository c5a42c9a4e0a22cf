// Hash-consing of octants: every octant with the same 8 entries (and, in a tree with per-entry
// colours, the same 8 leaf colours; LeafOrder trees share on the entries alone) is stored once,
// which turns the octree into a DAG (SVDAG sharing, Kämpe, Sintorn and Assarsson 2013). An
// open-addressing table (linear probing) of octant bases into the tree's own arrays. Each slot also
// keeps 32 bits of the octant's hash, so a probe compares octants only when those bits match and
// growing never reads the arrays again: the arrays are far larger than the cache, and a read of
// them is a cache miss.
#pragma once

#include <cstdint>
#include <vector>

#include "luxel/octree/octree.h"

namespace luxel::octree {

class OctantTable {
  public:
    // Octants are appended to `tree` (entries 0-7, the root, are never shared or returned).
    explicit OctantTable(Octree& tree);

    // The base of the octant with these entries (and colours, in a PerEntry tree; may be null
    // otherwise), appended when new. 0 when the array would exceed kMaxEntries.
    std::uint32_t intern(const std::uint32_t* entries, const Colour* colours);
    // The same with the octant's hash() computed earlier: a caller interning many octants can
    // prefetch() the slot of one while interning those before it, so the table's cache misses
    // overlap instead of following one another.
    std::uint32_t intern(const std::uint32_t* entries, const Colour* colours, std::uint64_t hash);
    std::uint64_t hash(const std::uint32_t* entries, const Colour* colours) const {
        return hashOf(entries, perEntry() ? colours : nullptr);
    }
    void prefetch(std::uint64_t hash) const {
        __builtin_prefetch(&slots_[(hash >> 32) & (slots_.size() - 1)]);
    }

    // Forgets everything and indexes the tree's octants again (after the tree was replaced).
    void reindex();

    // Most entries an array may hold: branch values (index + 248) must fit in a uint32.
    static constexpr std::uint64_t kMaxEntries = (std::uint64_t{1} << 32) - 256;

  private:
    std::uint64_t hashOf(const std::uint32_t* entries, const Colour* colours) const;
    bool equalAt(std::uint32_t base, const std::uint32_t* entries, const Colour* colours) const;
    void insert(std::uint32_t octant, std::uint32_t tag);
    void grow();
    bool perEntry() const { return tree_.attributes() == AttributeLayout::PerEntry; }

    Octree& tree_;
    // Per slot: the octant number (base / 8; 0 = free) in the low half, 32 bits of its hash in
    // the high half.
    std::vector<std::uint64_t> slots_;
    std::uint64_t used_ = 0;
};

}  // namespace luxel::octree
