// Command-line tests on scenes/voxel/thin-walls.json, the sealed room beside full sun: a small CPU
// render of it with extra flags, read back, and the mean of an image.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "luxel/core/image_io.h"
#include "support/cli_fixture.h"

namespace luxel::test {

class ThinWallsCli : public CliFixture {
  protected:
    // `luxel render` of thin-walls at 64x36 on the CPU with `flags`, written to `name` in the
    // test's folder and read back (empty, with a failed expectation, if either step fails).
    Image render(const std::string& name, const std::string& flags) {
        const RunResult r = runLuxel("render " + kThinWalls + " --backend cpu --size 64x36 " +
                                     flags + " --out " + path(name));
        EXPECT_EQ(r.exitCode, 0) << r.output;
        auto image = readExr(path(name));
        EXPECT_TRUE(image.ok()) << name;
        return image.ok() ? *image : Image{};
    }

    const std::string kThinWalls = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/thin-walls.json";
};

inline double meanOf(const Image& image) {
    double sum = 0.0;
    for (std::size_t i = 0; i < image.size(); ++i) sum += image.data()[i];
    return image.size() ? sum / double(image.size()) : 0.0;
}

}  // namespace luxel::test
