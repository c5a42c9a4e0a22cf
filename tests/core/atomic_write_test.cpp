// Every writer replaces its target whole or not at all: a full disk, a failed partner file or a
// killed process leaves the old bytes in place and no temporary behind.
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "luxel/core/file_io.h"
#include "luxel/core/image_io.h"
#include "luxel/voxel/vox_import.h"
#include "support/run_command.h"
#include "support/temp_dir.h"

namespace luxel {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<std::string> listing(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

// Incompressible, so the encoded size is predictable.
Image noise(int width, int height, int channels, unsigned seed) {
    Image image(width, height, channels);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (std::size_t i = 0; i < image.size(); ++i) image.data()[i] = u(rng);
    return image;
}

class AtomicWrite : public test::TempDirTest {
  protected:
    // Unmounted here, before the test's folder is removed.
    void TearDown() override {
        if (mounted_) ::umount(small_.c_str());
    }
    // A 64 KiB tmpfs, so a write fails with ENOSPC part way; skips where mounting is not allowed.
    bool mountSmallDisk() {
        small_ = dir() / "small";
        fs::create_directories(small_);
        mounted_ = ::mount("tmpfs", small_.c_str(), "tmpfs", 0, "size=64k") == 0;
        return mounted_;
    }
    fs::path small_;
    bool mounted_ = false;
};

TEST_F(AtomicWrite, FullDiskKeepsTheOldFileByteForByte) {
    if (!mountSmallDisk()) GTEST_SKIP() << "cannot mount a tmpfs here";
    const fs::path bin = small_ / "data.bin", png = small_ / "a.png", exr = small_ / "a.exr";
    ASSERT_TRUE(writeFileAtomically(bin.string(), "old bytes", "test file").ok());
    ASSERT_TRUE(writePng(png.string(), noise(8, 8, 3, 1)).ok());
    ASSERT_TRUE(writeExr(exr.string(), noise(8, 8, 3, 2)).ok());
    const std::string oldBin = slurp(bin), oldPng = slurp(png), oldExr = slurp(exr);

    const Status big = writeFileAtomically(bin.string(), std::string(200000, 'x'), "test file");
    ASSERT_FALSE(big.ok());
    EXPECT_NE(big.error().message().find("cannot write test file '" + bin.string() +
                                         "': No space left on device"),
              std::string::npos)
        << big.error().message();
    const Status bigPng = writePng(png.string(), noise(200, 200, 3, 3));
    ASSERT_FALSE(bigPng.ok());
    EXPECT_NE(bigPng.error().message().find("cannot write PNG '" + png.string() + "'"),
              std::string::npos)
        << bigPng.error().message();
    const Status bigExr = writeExr(exr.string(), noise(200, 200, 3, 4));
    ASSERT_FALSE(bigExr.ok());
    EXPECT_NE(bigExr.error().message().find("cannot write EXR '" + exr.string() + "'"),
              std::string::npos)
        << bigExr.error().message();

    EXPECT_EQ(slurp(bin), oldBin);
    EXPECT_EQ(slurp(png), oldPng);
    EXPECT_EQ(slurp(exr), oldExr);
    EXPECT_EQ(listing(small_), (std::vector<std::string>{"a.exr", "a.png", "data.bin"}));
}

TEST_F(AtomicWrite, OverwritingLeavesOnlyTheNewContent) {
    const fs::path png = dir() / "a.png", exr = dir() / "a.exr", vox = dir() / "a.vox";
    for (unsigned seed : {1u, 2u}) {
        const Image image = noise(16, 12, 4, seed);
        ASSERT_TRUE(writePng(png.string(), image, PngEncoding::Linear).ok());
        ASSERT_TRUE(writeExr(exr.string(), image).ok());
        const Result<Image> readPngBack = readPng(png.string(), PngEncoding::Linear);
        const Result<Image> readExrBack = readExr(exr.string());
        ASSERT_TRUE(readPngBack.ok() && readExrBack.ok());
        for (std::size_t i = 0; i < image.size(); ++i) {
            ASSERT_NEAR(readPngBack->data()[i], image.data()[i], 0.5f / 255.0f + 1e-6f);
            ASSERT_EQ(readExrBack->data()[i], image.data()[i]);
        }
    }
    voxel::VoxelWorld world = voxel::VoxelWorld::create({4, 4, 4}, 4).value();
    ASSERT_TRUE(voxel::saveVox(world, vox.string()).ok());
    ASSERT_TRUE(voxel::saveVox(world, vox.string()).ok());
    EXPECT_EQ(listing(dir()), (std::vector<std::string>{"a.exr", "a.png", "a.vox"}));
}

TEST_F(AtomicWrite, ImagesThatBelongTogetherChangeTogether) {
    if (!mountSmallDisk()) GTEST_SKIP() << "cannot mount a tmpfs here";
    const fs::path out = dir() / "render.exr", preview = small_ / "preview.png";
    ASSERT_TRUE(writeExr(out.string(), noise(8, 8, 3, 5)).ok());
    const std::string oldOut = slurp(out);
    // The preview does not fit on the small disk, so the render must not change either.
    const Image radiance = noise(200, 200, 3, 6);
    const Status s = writeImages({{out.string(), &radiance}, {preview.string(), &radiance}});
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message().find(preview.string()), std::string::npos);
    EXPECT_EQ(slurp(out), oldOut);
    EXPECT_FALSE(fs::exists(preview));
    EXPECT_EQ(listing(dir()), (std::vector<std::string>{"render.exr", "small"}));
    EXPECT_TRUE(listing(small_).empty());
}

TEST_F(AtomicWrite, RenderCommandExitsOneAndKeepsBothFilesWhenThePreviewFails) {
    if (!mountSmallDisk()) GTEST_SKIP() << "cannot mount a tmpfs here";
    const fs::path out = dir() / "f.exr", preview = small_ / "f.png";
    ASSERT_TRUE(writeFileAtomically(out.string(), "old render", "test file").ok());
    // Fill the small disk so even a small preview cannot be written.
    {
        std::ofstream filler(small_ / "filler", std::ios::binary);
        filler << std::string(64 << 10, 'f');
    }
    const test::RunResult run =
        test::runCommand(std::string(LUXEL_CLI_PATH) + " render " + LUXEL_SOURCE_DIR +
                         "/scenes/2d/penumbra.json --size 30x20 --rays 4 --threads 1 --out " +
                         out.string() + " --png " + preview.string());
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("cannot write PNG '" + preview.string() + "'"), std::string::npos)
        << run.output;
    EXPECT_EQ(run.output.find("wrote"), std::string::npos) << run.output;
    EXPECT_EQ(slurp(out), "old render");
    EXPECT_FALSE(fs::exists(preview));
    EXPECT_EQ(listing(dir()), (std::vector<std::string>{"f.exr", "small"}));
}

// A process killed part way through a large write leaves the old or the complete new file.
TEST_F(AtomicWrite, KilledWriterLeavesOldOrNewFileNeverPart) {
    const fs::path target = dir() / "big.exr", oldCopy = dir() / "old.exr",
                   newCopy = dir() / "new.exr";
    const Image newImage = noise(512, 512, 4, 8);
    ASSERT_TRUE(writeExr(oldCopy.string(), noise(64, 64, 4, 7)).ok());
    ASSERT_TRUE(writeExr(newCopy.string(), newImage).ok());
    const std::string oldBytes = slurp(oldCopy), newBytes = slurp(newCopy);
    int sawOld = 0, sawNew = 0;
    for (int delayMs : {1, 5, 15, 40}) {
        fs::copy_file(oldCopy, target, fs::copy_options::overwrite_existing);
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            for (;;) {
                if (!writeExr(target.string(), newImage)) ::_exit(1);
            }
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(delayMs));
        ::kill(child, SIGKILL);
        int status = 0;
        ::waitpid(child, &status, 0);
        const std::string bytes = slurp(target);
        ASSERT_TRUE(bytes == oldBytes || bytes == newBytes)
            << "after " << delayMs << " ms the target has " << bytes.size() << " bytes";
        (bytes == oldBytes ? sawOld : sawNew) += 1;
        // Only the killed writer's temporary may remain.
        for (const std::string& name : listing(dir())) {
            if (name.find(".tmp-") != std::string::npos) fs::remove(dir() / name);
        }
    }
    EXPECT_EQ(sawOld + sawNew, 4);
}

}  // namespace
}  // namespace luxel
