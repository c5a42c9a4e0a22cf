// The peak resident memory of `luxel render`: writing the images (tone-mapped --out PNG, --png
// display, --exposure auto) makes no copy the size of the image, so the solve stays the peak and
// the render fits the estimate `luxel info` prints (docs/performance.md, HRC).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "luxel/core/image.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/medium2d.h"
#include "support/cli_fixture.h"

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

// Peak resident bytes of `luxel args...` (its own, from wait4), or 0 when it fails.
std::uint64_t peakResidentBytes(const std::vector<std::string>& args) {
    std::vector<std::string> all = {LUXEL_CLI_PATH};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int null = ::open("/dev/null", O_WRONLY);
        ::dup2(null, 1);
        ::dup2(null, 2);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    int status = 0;
    rusage usage{};
    if (pid < 0 || ::wait4(pid, &status, 0, &usage) != pid) return 0;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return 0;
    return static_cast<std::uint64_t>(usage.ru_maxrss) * 1024;  // ru_maxrss is in KiB
}

class CliRenderPeakMemory : public luxel::test::CliFixture {
  protected:
    void SetUp() override {
        if (kSanitized) GTEST_SKIP() << "ASan's shadow memory makes resident sizes meaningless";
        CliFixture::SetUp();
    }
    // The growth of the peak from a 16x16 render to a size x size one (the program and its
    // libraries are the same in both).
    double growthInImages(int size, const std::vector<std::string>& options) {
        const std::string scene = std::string(LUXEL_SOURCE_DIR) + "/scenes/2d/room.json";
        auto run = [&](int side) {
            std::vector<std::string> args = {
                "render",     scene,
                "--size",     std::to_string(side) + "x" + std::to_string(side),
                "--backend",  "cpu",
                "--out",      path("f.png"),
                "--png",      path("d.png"),
                "--exposure", "auto"};
            args.insert(args.end(), options.begin(), options.end());
            return peakResidentBytes(args);
        };
        const std::uint64_t small = run(16), large = run(size);
        EXPECT_GT(small, 0u);
        EXPECT_GT(large, 0u);
        const double image = static_cast<double>(luxel::imageBytes(size, size, 3));
        const double growth = (static_cast<double>(large) - static_cast<double>(small)) / image;
        std::printf("%dx%d: peak %.1f MiB, %.1f MiB at 16x16: %.2f RGB float images more\n", size,
                    size, static_cast<double>(large) / (1 << 20),
                    static_cast<double>(small) / (1 << 20), growth);
        return growth;
    }
};

TEST_F(CliRenderPeakMemory, WritingAddsNoWholeImageCopies) {
    // No solve: the medium (2 images) and the black fluence (1), then only the light sources and
    // the fluence while the files are written strip by strip. A summed display image, tone-mapped
    // copies and an 8-bit copy would add 3 to 4 images.
    EXPECT_LT(growthInImages(1024, {"--view", "nogi"}), 3.5);
}

TEST_F(CliRenderPeakMemory, HrcRenderStaysWithinTheSolveEstimate) {
    // The solve is the peak: the medium and the solver's buffers, as `luxel info` estimates them.
    const int size = 1024;
    const double image = static_cast<double>(luxel::imageBytes(size, size, 3));
    const double estimate = static_cast<double>(luxel::gi2d::estimateHrcMemory(size, size).total() +
                                                luxel::gi2d::mediumBytes(size, size)) /
                            image;
    EXPECT_LT(growthInImages(size, {"--solver", "hrc"}), estimate + 0.5);
}

}  // namespace
