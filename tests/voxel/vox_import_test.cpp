// MagicaVoxel .vox reader/writer: round trips, the shipped sample, and hostile inputs.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "luxel/voxel/generators.h"
#include "luxel/voxel/vox_import.h"
#include "support/temp_dir.h"

namespace luxel::voxel {
namespace {

using Bytes = std::vector<std::uint8_t>;

void putI32(Bytes& b, std::int64_t v) {
    const auto u = static_cast<std::uint32_t>(v);
    for (int i = 0; i < 4; ++i) b.push_back(static_cast<std::uint8_t>(u >> (8 * i)));
}

// A chunk: id, content size, children size, then content and children.
Bytes chunk(const char* id, const Bytes& content, const Bytes& children = {}) {
    Bytes b(id, id + 4);
    putI32(b, static_cast<std::int64_t>(content.size()));
    putI32(b, static_cast<std::int64_t>(children.size()));
    b.insert(b.end(), content.begin(), content.end());
    b.insert(b.end(), children.begin(), children.end());
    return b;
}

Bytes ints(std::initializer_list<std::int64_t> values) {
    Bytes b;
    for (std::int64_t v : values) putI32(b, v);
    return b;
}

Bytes cat(std::initializer_list<Bytes> parts) {
    Bytes b;
    for (const Bytes& p : parts) b.insert(b.end(), p.begin(), p.end());
    return b;
}

Bytes voxFile(const Bytes& mainChildren, std::int64_t version = 150) {
    Bytes b = {'V', 'O', 'X', ' '};
    putI32(b, version);
    return cat({b, chunk("MAIN", {}, mainChildren)});
}

Bytes xyzi(std::initializer_list<std::array<std::uint8_t, 4>> voxels) {
    Bytes b;
    putI32(b, static_cast<std::int64_t>(voxels.size()));
    for (const auto& v : voxels) b.insert(b.end(), v.begin(), v.end());
    return chunk("XYZI", b);
}

// Parses and expects an error containing `text`.
void expectError(const Bytes& bytes, const std::string& text) {
    const Result<VoxelWorld> r = parseVox(bytes, "model.vox");
    ASSERT_FALSE(r.ok()) << "expected: " << text;
    EXPECT_NE(r.error().message().find(text), std::string::npos) << r.error().message();
    EXPECT_EQ(r.error().message().rfind("model.vox: ", 0), 0u) << r.error().message();
}

TEST(VoxImport, MinimalFileWithZUpMapping) {
    // Model 2 wide (x), 3 deep (vox y), 4 tall (vox z); one voxel at vox (1, 2, 3), index 1.
    const Bytes file = voxFile(cat({chunk("SIZE", ints({2, 3, 4})), xyzi({{1, 2, 3, 1}})}));
    Result<VoxelWorld> r = parseVox(file, "mini.vox", 4);
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_EQ(r->size(), (Int3{2, 4, 3}));  // luxel (x, y up, z) = vox (x, z, y)
    EXPECT_EQ(r->solidCount(), 1u);
    EXPECT_TRUE(r->solid(1, 3, 2));
    // No RGBA chunk: the default palette; index 1 is white.
    EXPECT_EQ(r->get(1, 3, 2), (Voxel{255, 255, 255, 255}));
    EXPECT_EQ(defaultVoxPalette()[1], (Voxel{255, 255, 255, 255}));
    EXPECT_EQ(defaultVoxPalette()[255], (Voxel{0x11, 0x11, 0x11, 255}));
}

TEST(VoxImport, PaletteIgnoredChunksAndVersion200) {
    Bytes rgba(1024, 0);
    rgba[0] = 10, rgba[1] = 20, rgba[2] = 30, rgba[3] = 255;  // colour index 1
    rgba[4 * 6] = 200, rgba[4 * 6 + 3] = 0;  // index 7, alpha 0: invisible (palette alpha)
    const Bytes file = voxFile(cat({chunk("PACK", ints({1})), chunk("SIZE", ints({3, 3, 3})),
                                    xyzi({{0, 0, 0, 1}, {2, 2, 2, 7}, {1, 1, 1, 0}}),
                                    chunk("NOTE", ints({0})), chunk("RGBA", rgba)}),
                               200);
    Result<VoxImport> r = readVox(file, "p.vox", {4});
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_EQ(r->world.solidCount(), 1u);  // colour index 0 and the alpha-0 colour are left out
    EXPECT_EQ(r->world.get(0, 0, 0), (Voxel{10, 20, 30, 255}));
    ASSERT_EQ(r->warnings.size(), 2u);
    EXPECT_EQ(r->warnings[0], "p.vox: chunk NOTE (palette notes) ignored");
    EXPECT_EQ(r->warnings[1],
              "p.vox: palette index 7: alpha 0: its voxels are left out (invisible)");
}

TEST(VoxImport, ModelsSideBySide) {
    const Bytes file =
        voxFile(cat({chunk("PACK", ints({2})), chunk("SIZE", ints({2, 2, 2})), xyzi({{1, 0, 0, 1}}),
                     chunk("SIZE", ints({3, 5, 4})), xyzi({{0, 4, 3, 2}})}));
    Result<VoxelWorld> r = parseVox(file, "two.vox", 4);
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_EQ(r->size(), (Int3{5, 4, 5}));
    EXPECT_TRUE(r->solid(1, 0, 0));
    EXPECT_TRUE(r->solid(2, 3, 4));
    EXPECT_EQ(r->solidCount(), 2u);
}

TEST(VoxImport, RoundTrip) {
    const test::TempDir tmp;
    VoxelWorld w = VoxelWorld::create({20, 12, 9}, 4).value();
    addBox(w, {0, 0, 0}, {20, 1, 9}, Voxel{10, 200, 10, 255});
    addSphere(w, {10, 6, 4.5f}, 4, Voxel{200, 10, 10, 255});
    w.set(19, 11, 8, Voxel{1, 2, 3, 255});  // the far corner checks the axis mapping
    Result<std::vector<std::uint8_t>> bytes = encodeVox(w);
    ASSERT_TRUE(bytes.ok()) << bytes.error().message();
    Result<VoxelWorld> back = parseVox(*bytes, "rt.vox", 8);
    ASSERT_TRUE(back.ok()) << back.error().message();
    EXPECT_TRUE(w == *back);
    // Vox SIZE is (x, z, y) of the luxel world.
    EXPECT_EQ((*bytes)[32], 20);
    EXPECT_EQ((*bytes)[36], 9);
    EXPECT_EQ((*bytes)[40], 12);

    const std::string path = tmp.path("roundtrip.vox");
    ASSERT_TRUE(saveVox(w, path).ok());
    Result<VoxelWorld> loaded = loadVox(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message();
    EXPECT_TRUE(w == *loaded);

    // Texture slots (alpha 1..254) do not survive: .vox has no such materials.
    w.set(0, 0, 0, Voxel{10, 200, 10, 4});
    Result<VoxelWorld> plain = parseVox(encodeVox(w).value(), "rt.vox", 8);
    ASSERT_TRUE(plain.ok()) << plain.error().message();
    EXPECT_EQ(plain->get(0, 0, 0), (Voxel{10, 200, 10, 255}));
}

TEST(VoxImport, ManyColoursUseNearest) {
    VoxelWorld w = VoxelWorld::create({16, 16, 2}, 4).value();
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x) {
            const auto v = static_cast<std::uint8_t>(y * 16 + x);
            w.set(x, y, 0, Voxel{v, v, v, 255});
            w.set(x, y, 1, Voxel{v, v, v, 255});
        }
    }
    w.set(0, 0, 0, Voxel{1, 0, 0, 255});  // 257 distinct colours
    Result<std::vector<std::uint8_t>> bytes = encodeVox(w);
    ASSERT_TRUE(bytes.ok());
    Result<VoxelWorld> back = parseVox(*bytes, "many.vox", 4);
    ASSERT_TRUE(back.ok()) << back.error().message();
    EXPECT_EQ(back->solidCount(), w.solidCount());
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x) {
            const Voxel a = w.get(x, y, 1), b = back->get(x, y, 1);
            EXPECT_LE(std::abs(a.r - b.r), 1);
        }
    }
}

TEST(VoxImport, SaveIntoAMissingFolderFails) {
    VoxelWorld w = VoxelWorld::create({300, 4, 4}, 4).value();
    w.set(299, 3, 3, Voxel{1, 2, 3, 255});
    const Status s = saveVox(w, "/nonexistent-dir/x.vox");
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message().find("/nonexistent-dir/x.vox"), std::string::npos);
}

TEST(VoxImport, LoadsShippedSample) {
    Result<VoxelWorld> r = loadVox(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/sample.vox");
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_EQ(r->size(), (Int3{24, 16, 24}));
    EXPECT_GT(r->solidCount(), 1000u);
    EXPECT_TRUE(r->solid(5, 0, 5));      // lawn
    EXPECT_FALSE(r->solid(5, 15, 5));    // sky
    EXPECT_EQ(r->get(6, 1, 12).r, 110);  // the door
    EXPECT_EQ(r->get(1, 7, 11).r, 190);  // the roof
}

TEST(VoxImport, MissingAndOversizedFiles) {
    const test::TempDir tmp;
    const Result<VoxelWorld> missing = loadVox("/nonexistent/none.vox");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message().find("/nonexistent/none.vox: cannot read"),
              std::string::npos);
    // A sparse file just over the limit is refused before reading.
    const std::string path = tmp.path("huge.vox");
    {
        std::ofstream out(path, std::ios::binary);
        out.seekp(static_cast<std::streamoff>(kMaxVoxFileBytes));
        out.put('x');
    }
    const Result<VoxelWorld> huge = loadVox(path);
    ASSERT_FALSE(huge.ok());
    EXPECT_NE(huge.error().message().find("larger than the 256 MiB limit"), std::string::npos);
}

TEST(VoxImport, RejectsHostileHeaders) {
    expectError({}, "byte 0: file is truncated: 0 bytes");
    expectError({'V', 'O', 'X'}, "byte 0: file is truncated: 3 bytes");
    expectError({'V', 'O', 'Y', ' ', 150, 0, 0, 0}, "byte 0: not a MagicaVoxel file");
    expectError(voxFile({}, 151), "byte 4: unsupported .vox version 151");
    expectError(voxFile({}, -1), "unsupported .vox version -1");
    expectError({'V', 'O', 'X', ' ', 150, 0, 0, 0}, "byte 8: file is truncated: no MAIN");
    Bytes notMain = voxFile({});
    notMain[8] = 'X';
    expectError(notMain, "byte 8: expected the MAIN chunk, found 'XAIN'");
    Bytes mainTooBig = voxFile({});
    mainTooBig[16] = 100;  // children size 100, nothing follows
    expectError(mainTooBig, "byte 12: MAIN chunk claims 100 bytes but only 0 remain");
    Bytes mainNegative = voxFile({});
    mainNegative[12] = 0xff, mainNegative[13] = 0xff, mainNegative[14] = 0xff,
    mainNegative[15] = 0xff;
    expectError(mainNegative, "byte 12: MAIN chunk has a negative content size (-1)");
    Bytes childrenNegative = voxFile({});
    childrenNegative[19] = 0x80;
    expectError(childrenNegative, "byte 16: MAIN chunk has a negative children size");
    expectError(voxFile({}), "byte 8: no model");
}

TEST(VoxImport, RejectsHostileChunks) {
    const Bytes size = chunk("SIZE", ints({4, 4, 4}));
    // Truncated chunk header inside MAIN.
    expectError(voxFile(Bytes{'S', 'I', 'Z', 'E', 1, 2}),
                "byte 20: truncated chunk header: 6 bytes left in MAIN");
    // A chunk larger than what remains.
    Bytes big = cat({size, xyzi({{0, 0, 0, 1}})});
    big[4] = 0xff, big[5] = 0xff, big[6] = 0xff, big[7] = 0x7f;  // SIZE content 2^31 - 1
    expectError(voxFile(big), "byte 24: SIZE chunk claims 2147483647 bytes but only 32 remain");
    Bytes hugeChildren = cat({size, xyzi({{0, 0, 0, 1}})});
    hugeChildren[8] = 0xff, hugeChildren[9] = 0xff, hugeChildren[10] = 0xff,
    hugeChildren[11] = 0x7f;
    expectError(voxFile(hugeChildren), "SIZE chunk claims 2147483659 bytes");
    Bytes negative = cat({size, xyzi({{0, 0, 0, 1}})});
    negative[7] = 0x80;
    expectError(voxFile(negative), "byte 24: SIZE chunk has a negative content size");
    // SIZE fields.
    expectError(voxFile(cat({chunk("SIZE", ints({4, 4})), xyzi({})})),
                "byte 24: SIZE chunk holds 8 bytes, needs at least 12");
    expectError(voxFile(cat({chunk("SIZE", ints({0, 4, 4})), xyzi({})})),
                "byte 32: SIZE x = 0 is invalid: each side must be in 1..256");
    expectError(voxFile(cat({chunk("SIZE", ints({4, -2, 4})), xyzi({})})), "SIZE y = -2");
    expectError(voxFile(cat({chunk("SIZE", ints({4, 4, 5000})), xyzi({})})),
                "byte 40: SIZE z = 5000 is invalid");
    expectError(voxFile(cat({chunk("SIZE", ints({4, 257, 4})), xyzi({})})), "SIZE y = 257");
    // XYZI counts and coordinates.
    expectError(voxFile(cat({size, chunk("XYZI", ints({1000000, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}))})),
                "byte 56: XYZI chunk claims 1000000 voxels but holds 40 bytes");
    expectError(voxFile(cat({size, chunk("XYZI", ints({-5}))})),
                "byte 56: XYZI chunk claims a negative number of voxels (-5)");
    expectError(voxFile(cat({size, chunk("XYZI", Bytes{1, 0})})),
                "byte 48: XYZI chunk holds 2 bytes, needs at least 4");
    expectError(voxFile(cat({size, xyzi({{0, 0, 0, 1}, {1, 4, 2, 1}})})),
                "byte 64: voxel 1 at (1, 4, 2) is outside the model size 4x4x4");
    expectError(voxFile(cat({size, xyzi({{255, 255, 255, 1}})})),
                "voxel 0 at (255, 255, 255) is outside");
    // Missing SIZE or XYZI, and dangling SIZE.
    expectError(voxFile(xyzi({{0, 0, 0, 1}})), "byte 20: XYZI chunk without a preceding SIZE");
    expectError(voxFile(size), "byte 20: SIZE chunk is not followed by an XYZI chunk");
    expectError(voxFile(cat({size, size, xyzi({})})),
                "byte 20: SIZE chunk is not followed by an XYZI chunk");
    expectError(voxFile(chunk("RGBA", Bytes(1024, 1))), "no model");
    // Palette and PACK sizes.
    expectError(voxFile(cat({size, xyzi({}), chunk("RGBA", Bytes(1000, 1))})),
                "RGBA chunk holds 1000 bytes, needs at least 1024");
    expectError(voxFile(cat({chunk("PACK", Bytes{1}), size, xyzi({})})),
                "byte 24: PACK chunk holds 1 bytes");
    expectError(voxFile(cat({chunk("PACK", ints({-3})), size, xyzi({})})),
                "PACK chunk claims -3 models");
    // Too many models side by side.
    Bytes wide;
    for (int i = 0; i < 20; ++i) wide = cat({wide, chunk("SIZE", ints({250, 1, 1})), xyzi({})});
    expectError(voxFile(wide),
                "byte 8: the placed models span 5000x1x1 voxels (vox axes, from (0, 0, 0)): a "
                "world is at most 4096 per side, and this one would need");
    // A bad chunk size for the world.
    const Result<VoxelWorld> r = parseVox(voxFile(cat({size, xyzi({})})), "model.vox", 3);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message().find("model.vox: chunk size must be a power of two"),
              std::string::npos);
}

TEST(VoxImport, EveryTruncationFailsCleanly) {
    VoxelWorld w = VoxelWorld::create({6, 5, 4}, 4).value();
    addSphere(w, {3, 2.5f, 2}, 2.2f, Voxel{50, 60, 70, 255});
    const Bytes full = encodeVox(w).value();
    for (std::size_t n = 0; n < full.size(); ++n) {
        const Bytes part(full.begin(), full.begin() + static_cast<std::ptrdiff_t>(n));
        EXPECT_FALSE(parseVox(part, "cut.vox").ok()) << n;
    }
    // Flipping any single byte never crashes (it may or may not still parse).
    for (std::size_t i = 0; i < full.size(); ++i) {
        Bytes bad = full;
        bad[i] ^= 0xa5;
        (void)parseVox(bad, "flip.vox").ok();
    }
}

}  // namespace
}  // namespace luxel::voxel
