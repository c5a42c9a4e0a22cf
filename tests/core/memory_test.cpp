// availableMemoryBytes honours the soft RLIMIT_AS and RLIMIT_DATA (less what the process already
// maps), checkMemory refuses in one line what does not fit, and huge-page advice changes no byte.
// Limits are lowered in a forked child (support/memory_limit.h), so the test process keeps its own.
#include "luxel/core/memory.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "luxel/core/image.h"
#include "support/memory_limit.h"

namespace {

constexpr std::uint64_t kMiB = 1024 * 1024;

// 0 when availableMemoryBytes and checkMemory see `headroom`, else the failed expectation.
int expectHeadroom(std::uint64_t headroom) {
    const std::uint64_t available = luxel::availableMemoryBytes();
    // Reading the status again may find a few MiB more mapped, or a few pages fewer (freed since).
    if (available == 0 || available > headroom + kMiB) return 1;
    if (available + 32 * kMiB < headroom) return 2;
    const luxel::Status refused = luxel::checkMemory(headroom + 64 * kMiB, "rendering 9x9");
    if (refused.ok()) return 3;
    const std::string message = refused.error().message();
    if (message.rfind("rendering 9x9 needs ", 0) != 0) return 4;
    if (message.find(", only ") == std::string::npos) return 5;
    if (!luxel::checkMemory(headroom / 4, "a small buffer").ok()) return 6;
    return 0;
}

TEST(Memory, AddressSpaceLimitCapsAvailableMemory) {
    EXPECT_EQ(
        luxel::test::runUnderMemoryLimit(256 * kMiB, [] { return expectHeadroom(256 * kMiB); }), 0);
}

TEST(Memory, DataLimitCapsAvailableMemory) {
    EXPECT_EQ(luxel::test::runUnderMemoryLimit(
                  256 * kMiB, [] { return expectHeadroom(256 * kMiB); }, RLIMIT_DATA),
              0);
}

TEST(Memory, WithoutLimitsTheMachineCounts) {
    // No rlimit in the way: what /proc/meminfo (or a cgroup) says, far above the 256 MiB above.
    EXPECT_GT(luxel::availableMemoryBytes(), 256 * kMiB);
}

TEST(Memory, FormatBytes) {
    EXPECT_EQ(luxel::formatBytes(12), "12 B");
    EXPECT_EQ(luxel::formatBytes(1536), "1.5 KiB");
    EXPECT_EQ(luxel::formatBytes(48ull << 30), "48.0 GiB");
}

}  // namespace

namespace {

// Huge-page advice is only advice: null, small, unaligned and odd-sized ranges are taken without
// complaint, and the memory reads back what was written whatever the kernel decided.
TEST(Memory, HugePageAdviceKeepsTheMemoryAsItIs) {
    luxel::adviseHugePages(nullptr, 64 * kMiB);
    std::vector<float> small(100, 1.0f);
    luxel::adviseHugePages(small.data(), small.size() * sizeof(float));
    EXPECT_EQ(small[99], 1.0f);
    // An unaligned start and an odd length, advised before the first write (as Image does).
    std::vector<std::uint8_t> big;
    big.reserve(9 * kMiB + 3);
    luxel::adviseHugePages(big.data() + 1, 9 * kMiB + 1);
    big.assign(9 * kMiB + 3, 0);
    for (std::size_t i = 0; i < big.size(); i += 4093) big[i] = static_cast<std::uint8_t>(i % 251);
    for (std::size_t i = 0; i < big.size(); i += 4093) {
        ASSERT_EQ(big[i], static_cast<std::uint8_t>(i % 251)) << i;
    }
    // An image big enough to be advised is zeros, as every image starts.
    const luxel::Image image(1024, 1024, 3);
    double sum = 0.0;
    for (std::size_t i = 0; i < image.size(); ++i) sum += image.data()[i];
    EXPECT_EQ(sum, 0.0);
}

}  // namespace
