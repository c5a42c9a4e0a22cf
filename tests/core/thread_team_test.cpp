#include "luxel/core/thread_team.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <vector>

namespace luxel {
namespace {

// Each member writes its phase number, meets the others, and checks that every member wrote
// the same phase before anyone writes the next: a barrier that let a member through early (or
// one that mixed up phases) shows as a mismatch.
int mismatchesOverPhases(int members, int phases, bool oneSleeps) {
    std::vector<std::atomic<int>> written(static_cast<std::size_t>(members));
    std::atomic<int> mismatches{0};
    ThreadTeam::run(members, [&](int member, ThreadTeam& team) {
        for (int phase = 0; phase < phases; ++phase) {
            // The last member is late now and then, past any spin: the others must sleep and wake.
            if (oneSleeps && member == members - 1 && phase % 16 == 0) {
                std::this_thread::sleep_for(std::chrono::milliseconds(2));
            }
            written[static_cast<std::size_t>(member)].store(phase, std::memory_order_relaxed);
            team.sync();
            for (const std::atomic<int>& w : written) {
                if (w.load(std::memory_order_relaxed) != phase) ++mismatches;
            }
            team.sync();
        }
    });
    return mismatches.load();
}

TEST(ThreadTeam, NoMemberPassesABarrierBeforeAllArrive) {
    for (int members : {1, 2, 3, 4, 8}) {
        EXPECT_EQ(mismatchesOverPhases(members, 5000, false), 0) << members << " members";
    }
}

TEST(ThreadTeam, MembersThatSleepAtABarrierWakeWhenTheLastArrives) {
    for (int members : {2, 3}) {
        EXPECT_EQ(mismatchesOverPhases(members, 160, true), 0) << members << " members";
    }
}

}  // namespace
}  // namespace luxel
