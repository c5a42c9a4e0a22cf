// The luxel-view end-to-end fixture: runs the viewer under a virtual X display (Debian xvfb) from
// a private folder, and measures the screenshots it writes. Shared by the viewer's Xvfb tests.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

#include "luxel/core/image_io.h"
#include "support/run_command.h"
#include "support/temp_dir.h"

namespace luxel::test {

namespace fs = std::filesystem;

// Sanitizer builds: SDL's video subsystem leaves libdbus allocations behind at exit, and libdbus
// (built without frame pointers) gives them stacks LeakSanitizer cannot match to a suppression.
// Leak checks stay on for the viewer's logic, which the unit tests link; only the windowed
// process runs without them.
#ifdef __SANITIZE_ADDRESS__
constexpr const char* kViewerSanitizerOptions = "ASAN_OPTIONS=detect_leaks=0 ";
#else
constexpr const char* kViewerSanitizerOptions = "";
#endif

inline RunResult run(const std::string& command) {
    return runCommand(command);
}

// Mean of the first three channels over the square of half-side r around (cx, cy).
inline double regionMean(const Image& image, int cx, int cy, int r) {
    double sum = 0;
    int n = 0;
    for (int y = cy - r; y <= cy + r; ++y) {
        for (int x = cx - r; x <= cx + r; ++x) {
            if (!image.inside(x, y)) continue;
            const Rgb c = image.rgb(x, y);
            sum += (c.r + c.g + c.b) / 3.0;
            ++n;
        }
    }
    return n ? sum / n : 0.0;
}

inline double stddev(const Image& image) {
    const double mean = regionMean(image, image.width() / 2, image.height() / 2,
                                   std::max(image.width(), image.height()));
    double sq = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const Rgb c = image.rgb(x, y);
            const double v = (c.r + c.g + c.b) / 3.0 - mean;
            sq += v * v;
        }
    }
    return std::sqrt(sq / static_cast<double>(image.pixelCount()));
}

inline double meanAbsDiff(const Image& a, const Image& b) {
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += std::fabs(a.data()[i] - b.data()[i]);
    return sum / static_cast<double>(a.size());
}

class ViewerXvfb : public TempDirTest {
  protected:
    void SetUp() override {
        ASSERT_EQ(run("command -v xvfb-run").exitCode, 0)
            << "xvfb-run is missing: install the Debian package xvfb (deps/debian-packages.txt, "
               "scripts/setup.sh); the viewer tests need a virtual display";
    }
    // Screenshots stay for a look when a test fails or LUXEL_KEEP_VIEW_OUTPUT is set; an empty
    // folder (the viewer never ran) goes.
    void TearDown() override {
        if ((HasFailure() || std::getenv("LUXEL_KEEP_VIEW_OUTPUT")) && !fs::is_empty(dir())) {
            tempDir().keep();
            std::cout << "luxel-view output kept in " << dir().string() << "\n";
        }
    }

    // Runs the viewer on a private virtual display, from the test's folder.
    RunResult view(const std::string& args) {
        // Distinct starting display numbers keep parallel tests from racing for one server.
        static int serial = 0;
        const int server = 100 + (getpid() % 400) * 4 + (serial++ % 4);
        const std::string command = "cd '" + dir().string() + "' && SDL_RENDER_DRIVER=software " +
                                    kViewerSanitizerOptions + "timeout 120 xvfb-run -a -n " +
                                    std::to_string(server) + " -s '-screen 0 1024x768x24' " +
                                    LUXEL_VIEW_PATH + " " + args;
        return run(command);
    }

    Image png(const std::string& name) {
        auto image = luxel::readPng(path(name));
        EXPECT_TRUE(image) << (image ? "" : image.error().message());
        return image ? *image : Image(1, 1, 3);
    }
};

}  // namespace luxel::test
