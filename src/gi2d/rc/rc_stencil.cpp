// The CPU RC pass by stencil walks (docs/algorithms/radiance-cascades-2d.md §8): per direction,
// the stencils (gi2d/rc/rc_stencil_trace.h), what lies beyond the intervals, and the groups of
// probes that walk them.
#include "gi2d/rc/rc_stencil.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "gi2d/rc/rc_cascade_pass.h"
#include "gi2d/rc/rc_internal.h"
#include "gi2d/rc/rc_stencil_trace.h"
#include "luxel/core/parallel.h"

namespace luxel::gi2d::rc {

namespace shared = gpu::shared;

namespace {

Vec2d vec(shared::dvec2 v) {
    return {v.x, v.y};
}

// The lane stride of cascade c's walks: probes one apart, or two for the bilinear fix (whose
// probes of one parity share their upper neighbours' offsets).
int laneStride(const RcCascade& c, bool fix) {
    return static_cast<int>(c.spacing) * (fix ? 2 : 1);
}

// Planes for this stride stay within a few times the medium (or are small anyway).
bool stencilsFit(int width, int height, int stride) {
    const std::int64_t cells = Planes::cells(width, height, stride);
    return cells <= 6 * static_cast<std::int64_t>(width) * height + (1 << 22) && cells < (1 << 30);
}

}  // namespace

std::uint64_t stencilPassBytes(int width, int height, const RcCascade& cascade, bool fix) {
    const int stride = laneStride(cascade, fix);
    if (!stencilsFit(width, height, stride)) return 0;
    return static_cast<std::uint64_t>(Planes::cells(width, height, stride)) *
           (3 * sizeof(float) + 1);
}

std::vector<Rgb> cascadePassStencil(const RayMarcher& marcher, const StencilMedium& medium,
                                    const std::vector<RcCascade>& cascades, int i,
                                    const std::vector<Rgb>& upper, Rgb sky, RcMerge merge) {
    const RcCascade& c = cascades[i];
    const int count = static_cast<int>(cascades.size());
    const RcCascade* up = i + 1 < count ? &cascades[i + 1] : nullptr;
    const int stored = storedPerProbe(c, i);
    const int group = shared::rcGroup(c.rays, stored);
    const int w = medium.width(), h = medium.height();
    const int probesX = c.probesX, probesY = c.probesY;
    const std::size_t probes = static_cast<std::size_t>(probesX) * probesY;
    const bool fix = up != nullptr && merge == RcMerge::BilinearFix;
    const int step = fix ? 2 : 1;  // probes between lanes
    const int spacing = static_cast<int>(c.spacing);
    const int stride = laneStride(c, fix);
    const Vec2d offset{c.offsetX, c.offsetY};
    std::vector<Rgb> current(probes * stored);

    auto upperValue = [&](int ux, int uy, int k) {
        return upper[(static_cast<std::size_t>(k) * up->probesY + uy) * up->probesX + ux];
    };
    auto probeCentre = [&](int px, int py) {
        return vec(shared::rcProbeCentre(px, py, c.spacing)) + offset;
    };

    const bool useStencils = spacing == c.spacing && stencilsFit(w, h, stride);
    if (!useStencils) {  // the exact pass, slot-major
        parallelForRange(static_cast<int>(probes), 16, [&](int begin, int end) {
            for (int index = begin; index < end; ++index) {
                const Vec2d p = probeCentre(index % probesX, index / probesX);
                for (int s = 0; s < stored; ++s) {
                    Rgb sum;
                    for (int k = s * group; k < (s + 1) * group; ++k) {
                        sum += mergedRay(marcher, c, up, p, k, upperValue, sky, merge);
                    }
                    current[s * probes + index] = sum * (1.0f / static_cast<float>(group));
                }
            }
        });
        return current;
    }

    const Planes planes(medium, stride);
    const int lanes = stencilWalkLanes();
    const int classes = fix ? 2 : 1, corners = fix ? 4 : 1;
    // Lanes of one class in a row, and the row length of the per-class buffers (a whole group
    // readable past the last lane).
    const int classColumns = (probesX + step - 1) / step;
    const int rowCap = classColumns + kStencilLanes;
    // The cells a stencil may need: its reference probe lies in the first two rows and columns,
    // the others are moved right and down by less than the grid's extent.
    const Vec2d boxLo{-static_cast<double>(probesX) * spacing - 2,
                      -static_cast<double>(probesY) * spacing - 2};
    const Vec2d boxHi{w + 2.0, h + 2.0};

    // The upper neighbours of probes of parity class q (x and y alike): the unclamped first
    // neighbour of probe (q, q) and the bilinear weights, shared by the class (probe q + 2 n has
    // neighbours n further on).
    int refX[2] = {0, 0}, refY[2] = {0, 0};
    float weightX[2][2] = {}, weightY[2][2] = {};
    if (up) {
        for (int q = 0; q < 2; ++q) {
            const Vec2d p = probeCentre(q, q);
            refX[q] = static_cast<int>(std::floor((p.x - up->offsetX) / up->spacing - 0.5));
            refY[q] = static_cast<int>(std::floor((p.y - up->offsetY) / up->spacing - 0.5));
            const shared::RcBilinear b = shared::rcBilinearAt(
                {p.x - up->offsetX, p.y - up->offsetY}, up->spacing, up->probesX, up->probesY);
            weightX[q][0] = b.wx0, weightX[q][1] = b.wx1;
            weightY[q][0] = b.wy0, weightY[q][1] = b.wy1;
        }
    }
    const int upX = up ? up->probesX : 0, upY = up ? up->probesY : 0;
    // Vanilla: the upper columns probes blend, refX[q] + m and one more for probe q + 2 m,
    // and a margin around the grid.
    const int blendLo = std::min({0, refX[0], refX[1]});
    const int blendW =
        std::max({upX, refX[0] + probesX / 2 + 2, refX[1] + probesX / 2 + 2}) - blendLo;

    // The fix: which nominal neighbour serves neighbour a (0, 1) of probe column px: 0 or 1
    // where the nominal neighbour clamped to the grid is a's (as rcBilinearAt clamps), -1 where
    // no stencil reaches a's neighbour (then the probe takes the marcher); likewise for rows.
    // Separable, as x and y of the bilinear footprint are.
    std::vector<std::int8_t> columnSource[2], rowSource[2];
    auto serving = [](int actual, int nominal, int a, int size) {
        const int d = actual - nominal;
        return d >= 0 && d <= 1 && actual == std::clamp(nominal + a, 0, size - 1) ? d : -1;
    };
    if (fix) {
        for (int a = 0; a < 2; ++a) {
            columnSource[a].resize(probesX);
            rowSource[a].resize(probesY);
        }
        for (int px = 0; px < probesX; ++px) {
            const Vec2d p = probeCentre(px, 0);
            const shared::RcBilinear b =
                shared::rcBilinearAt({p.x - up->offsetX, p.y - up->offsetY}, up->spacing, upX, upY);
            const int nx = refX[px % 2] + (px - px % 2) / 2;
            for (int a = 0; a < 2; ++a) {
                columnSource[a][px] =
                    static_cast<std::int8_t>(serving(shared::rcBilinearX(b, a), nx, a, upX));
            }
        }
        for (int py = 0; py < probesY; ++py) {
            const Vec2d p = probeCentre(0, py);
            const shared::RcBilinear b =
                shared::rcBilinearAt({p.x - up->offsetX, p.y - up->offsetY}, up->spacing, upX, upY);
            const int ny = refY[py % 2] + (py - py % 2) / 2;
            for (int a = 0; a < 2; ++a) {
                rowSource[a][py] =
                    static_cast<std::int8_t>(serving(shared::rcBilinearY(b, a), ny, a, upY));
            }
        }
    }
    auto nominalColumn = [&](int px) {
        return columnSource[0][px] == 0 && columnSource[1][px] == 1;
    };
    auto nominalRow = [&](int py) { return rowSource[0][py] == 0 && rowSource[1][py] == 1; };
    auto marcherColumn = [&](int px) { return columnSource[0][px] < 0 || columnSource[1][px] < 0; };
    auto marcherRow = [&](int py) { return rowSource[0][py] < 0 || rowSource[1][py] < 0; };
    auto marcherOnly = [&](int px, int py) { return marcherColumn(px) || marcherRow(py); };
    std::vector<int> marcherColumns;
    for (int px = 0; fix && px < probesX; ++px) {
        if (marcherColumn(px)) marcherColumns.push_back(px);
    }

    // Tasks: a slot (a group of directions) and a block of probe rows; the lower cascades have
    // few slots, so their rows are split.
    const int chunks = std::clamp((64 + stored - 1) / stored, 1, probesY);
    const int rowsPerChunk = (probesY + chunks - 1) / chunks;
    parallelForRange(stored * chunks, 1, [&](int taskBegin, int taskEnd) {
        // Stencils: [qy][qx][corner] for the fix (probe parity classes, upper neighbours),
        // else one.
        std::array<Stencil, 16> stencils;
        std::vector<float> sums, beyond, blend;
        std::vector<float> skyRow(3 * kStencilLanes);
        for (int ch = 0; ch < 3; ++ch) {
            std::fill_n(skyRow.begin() + ch * kStencilLanes, kStencilLanes, sky[ch]);
        }
        // Groups waiting to be walked, each with its own corner sources.
        std::array<StencilGroup, kStencilBatch> batch;
        int batched = 0;
        auto flush = [&] {
            if (batched > 0) walkStencilGroups(batch.data(), batched);
            batched = 0;
        };
        std::vector<std::int32_t> groupSources(kStencilBatch * 4 * kStencilLanes);
        std::vector<char> insideX, insideY;
        for (int task = taskBegin; task < taskEnd; ++task) {
            const int s = task / chunks;
            const int y0 = (task % chunks) * rowsPerChunk;
            const int y1 = std::min(probesY, y0 + rowsPerChunk);
            if (y0 >= y1) continue;
            const int rows = y1 - y0;
            sums.assign(static_cast<std::size_t>(classes) * 3 * rows * rowCap, 0.0f);
            auto sumAt = [&](int px, int py, int ch) -> float& {
                const int q = px % step;
                return sums[((static_cast<std::size_t>(q) * 3 + ch) * rows + (py - y0)) * rowCap +
                            (px - q) / step];
            };
            auto addSum = [&](int px, int py, Rgb v) {
                for (int ch = 0; ch < 3; ++ch) sumAt(px, py, ch) += v[ch];
            };
            // The fix's upper values with the sky where an upper interval starts off the canvas:
            // rows uyLo.., columns uxLo.. (nominal neighbours, clamped to the grid as
            // rcBilinearAt clamps them).
            int uxLo = 0, uyLo = 0, upadW = 0;
            if (fix) {
                uxLo = std::min(refX[0], refX[1]);
                const int uxHi = std::max(refX[0], refX[1]) + classColumns + kStencilLanes + 1;
                uyLo = std::min(refY[0], refY[1]) + y0 / 2 - 1;
                const int uyHi = std::max(refY[0], refY[1]) + y1 / 2 + 2;
                upadW = uxHi - uxLo + 1;
                beyond.assign(static_cast<std::size_t>(3) * (uyHi - uyLo + 1) * upadW, 0.0f);
            } else if (up) {
                beyond.assign(static_cast<std::size_t>(3) * rows * rowCap, 0.0f);
                blend.assign(static_cast<std::size_t>(3) * blendW, 0.0f);
            }
            const int upadH = fix ? static_cast<int>(beyond.size() / (3 * upadW)) : 0;

            for (int k = s * group; k < (s + 1) * group; ++k) {
                const Vec2d dir = vec(shared::rcDirection(k, c.rays));
                bool degenerate = false;
                for (int qy = 0; qy < classes; ++qy) {
                    for (int qx = 0; qx < classes; ++qx) {
                        const Vec2d p = probeCentre(qx, qy);
                        const Vec2d from = p + dir * c.intervalStart;
                        for (int corner = 0; corner < corners; ++corner) {
                            Vec2d to = p + dir * c.intervalEnd;
                            if (fix) {
                                const Vec2d q =
                                    vec(shared::rcProbeCentre(refX[qx] + corner / 2,
                                                              refY[qy] + corner % 2, up->spacing)) +
                                    Vec2d{up->offsetX, up->offsetY};
                                to = q + dir * up->intervalStart;
                            }
                            Stencil& st = stencils[(qy * 2 + qx) * 4 + corner];
                            st.trace(from, to, boxLo, boxHi, planes);
                            degenerate = degenerate || st.degenerate;
                        }
                    }
                }
                if (degenerate) {  // every probe of this direction takes the marcher
                    for (int py = y0; py < y1; ++py) {
                        for (int px = 0; px < probesX; ++px) {
                            addSum(px, py,
                                   mergedRay(marcher, c, up, probeCentre(px, py), k, upperValue,
                                             sky, merge));
                        }
                    }
                    continue;
                }

                // What lies beyond each probe's interval for direction k.
                if (fix) {
                    // Upper probe (ux, uy)'s interval starts off the canvas where its x or y
                    // does (as RayMarcher::segment decides `leavesCanvas`).
                    insideX.resize(upX);
                    insideY.resize(upY);
                    for (int ux = 0; ux < upX; ++ux) {
                        const double x = (vec(shared::rcProbeCentre(ux, 0, up->spacing)) +
                                          Vec2d{up->offsetX, up->offsetY} + dir * up->intervalStart)
                                             .x;
                        insideX[ux] = !(x < 0 || x > w);
                    }
                    for (int uy = 0; uy < upY; ++uy) {
                        const double y = (vec(shared::rcProbeCentre(0, uy, up->spacing)) +
                                          Vec2d{up->offsetX, up->offsetY} + dir * up->intervalStart)
                                             .y;
                        insideY[uy] = !(y < 0 || y > h);
                    }
                    for (int row = 0; row < upadH; ++row) {
                        const int uy = std::clamp(uyLo + row, 0, upY - 1);
                        for (int col = 0; col < upadW; ++col) {
                            const int ux = std::clamp(uxLo + col, 0, upX - 1);
                            const Rgb v = insideX[ux] && insideY[uy] ? upperValue(ux, uy, k) : sky;
                            for (int ch = 0; ch < 3; ++ch) {
                                beyond[(static_cast<std::size_t>(ch) * upadH + row) * upadW + col] =
                                    v[ch];
                            }
                        }
                    }
                } else if (up) {
                    // Bilinear blend of the upper probes (rows, then columns), or the sky where
                    // the interval ends off the canvas. Probe q + 2 m (q = 0, 1) blends upper
                    // columns refX[q] + m and one more, clamped to the grid: the blended row is
                    // padded with copies of its end values.
                    // The probes whose interval ends on the canvas in x (a run of columns, as
                    // x grows with px).
                    int insideFirst = probesX, insideEnd = 0;
                    for (int px = 0; px < probesX; ++px) {
                        const double x = (probeCentre(px, 0) + dir * c.intervalEnd).x;
                        if (!(x < 0 || x > w)) {
                            insideFirst = std::min(insideFirst, px);
                            insideEnd = px + 1;
                        }
                    }
                    const Rgb* plane = &upper[static_cast<std::size_t>(k) * upX * upY];
                    for (int py = y0; py < y1; ++py) {
                        const double y = (probeCentre(0, py) + dir * c.intervalEnd).y;
                        float* out[3];
                        for (int ch = 0; ch < 3; ++ch) {
                            out[ch] =
                                &beyond[(static_cast<std::size_t>(ch) * rows + (py - y0)) * rowCap];
                        }
                        if (y < 0 || y > h || insideFirst >= insideEnd) {
                            for (int ch = 0; ch < 3; ++ch) std::fill_n(out[ch], probesX, sky[ch]);
                            continue;
                        }
                        const int qy = py % 2, ny = refY[qy] + (py - qy) / 2;
                        const Rgb* row0 = plane + std::clamp(ny, 0, upY - 1) * upX;
                        const Rgb* row1 = plane + std::clamp(ny + 1, 0, upY - 1) * upX;
                        const float wy0 = weightY[qy][0], wy1 = weightY[qy][1];
                        float* b[3];
                        for (int ch = 0; ch < 3; ++ch) {
                            b[ch] = &blend[static_cast<std::size_t>(ch) * blendW] - blendLo;
                        }
                        for (int ux = 0; ux < upX; ++ux) {
                            b[0][ux] = row0[ux].r * wy0 + row1[ux].r * wy1;
                            b[1][ux] = row0[ux].g * wy0 + row1[ux].g * wy1;
                            b[2][ux] = row0[ux].b * wy0 + row1[ux].b * wy1;
                        }
                        for (int ch = 0; ch < 3; ++ch) {
                            float* bc = b[ch];
                            std::fill(bc + blendLo, bc, bc[0]);
                            std::fill(bc + upX, bc + blendLo + blendW, bc[upX - 1]);
                            for (int q = 0; q < 2 && q < probesX; ++q) {
                                const float w0 = weightX[q][0], w1 = weightX[q][1];
                                const float* in = bc + refX[q];
                                float* o = out[ch] + q;
                                const int n = (probesX - q + 1) / 2;
                                for (int m = 0; m < n; ++m) o[2 * m] = in[m] * w0 + in[m + 1] * w1;
                            }
                            std::fill(out[ch], out[ch] + insideFirst, sky[ch]);
                            std::fill(out[ch] + insideEnd, out[ch] + probesX, sky[ch]);
                        }
                    }
                }

                StencilGroup g{};
                for (int ch = 0; ch < 3; ++ch) {
                    g.planes[ch] = planes.data[std::min(ch, planes.channels - 1)].data();
                }
                g.grey = planes.channels == 1;
                g.medium = &medium;
                g.radius = planes.radius.data();
                g.laneStride = stride;
                g.corners = corners;
                for (int py = y0; py < y1; ++py) {
                    const int qy = fix ? py % 2 : 0;
                    const int shiftY = (py - qy) * spacing;
                    for (int qx = 0; qx < classes; ++qx) {
                        for (int first = qx; first < probesX; first += lanes * step) {
                            const int n = std::min(lanes, (probesX - first + step - 1) / step);
                            const int shiftX = (first - qx) * spacing;  // a multiple of stride
                            const int column = (first - qx) / step;
                            g.lanes = n;
                            for (int corner = 0; corner < corners; ++corner) {
                                const Stencil& st = stencils[(qy * 2 + qx) * 4 + corner];
                                const int gx = shiftX / stride;
                                const int yLo = -shiftY, yHi = h - 1 - shiftY;
                                const int xLo = -(n - 1) - gx, xHi = planes.rowLen - 1 - gx;
                                const int all = static_cast<int>(st.cellY.size());
                                const auto [ya, yb] =
                                    st.minY >= yLo && st.maxY <= yHi
                                        ? std::pair<int, int>(0, all)
                                        : Stencil::where(st.cellY, yLo, yHi, st.signY);
                                const auto [xa, xb] =
                                    st.minColumn >= xLo && st.maxColumn <= xHi
                                        ? std::pair<int, int>(0, all)
                                        : Stencil::where(st.column, xLo, xHi, st.signX);
                                StencilGroup::Walk& walk = g.walk[corner];
                                walk.base =
                                    static_cast<std::int64_t>(shiftY) * planes.planeSize + gx;
                                walk.offset = st.offset.data();
                                walk.length = st.length.data();
                                walk.cellX = st.cellX.data();
                                walk.cellY = st.cellY.data();
                                walk.shiftX = shiftX;
                                walk.shiftY = shiftY;
                                walk.begin = std::max(ya, xa);
                                walk.end = std::min(yb, xb);
                                walk.cum = st.cum.data();
                                walk.firstX = st.firstX.data();
                                walk.firstY = st.firstY.data();
                                walk.cellX0 = all > 0 ? st.cellX[0] : 0;
                                walk.cellY0 = all > 0 ? st.cellY[0] : 0;
                                walk.signX = st.signX;
                                walk.signY = st.signY;
                                walk.spanX = static_cast<int>(st.firstX.size()) - 2;
                                walk.spanY = static_cast<int>(st.firstY.size()) - 2;
                                if (!fix) {
                                    g.weight[corner] = 1.0f;
                                    for (int ch = 0; ch < 3; ++ch) {
                                        g.beyond[corner][ch] =
                                            up ? &beyond[(static_cast<std::size_t>(ch) * rows +
                                                          (py - y0)) *
                                                             rowCap +
                                                         first]
                                               : &skyRow[ch * kStencilLanes];
                                    }
                                    continue;
                                }
                                const int a = corner / 2, bb = corner % 2;
                                g.weight[corner] = weightX[qx][a] * weightY[qy][bb];
                                const int row = refY[qy] + (py - qy) / 2 + bb - uyLo;
                                const int col = refX[qx] + column + a - uxLo;
                                for (int ch = 0; ch < 3; ++ch) {
                                    g.beyond[corner][ch] =
                                        &beyond[(static_cast<std::size_t>(ch) * upadH + row) *
                                                    upadW +
                                                col];
                                }
                            }
                            for (int ch = 0; ch < 3; ++ch) {
                                g.sum[ch] = &sums[((static_cast<std::size_t>(qx) * 3 + ch) * rows +
                                                   (py - y0)) *
                                                      rowCap +
                                                  column];
                            }
                            g.source = nullptr;
                            if (fix) {
                                bool nominal = nominalRow(py);
                                for (int l = 0; l < n && nominal; ++l) {
                                    nominal = nominalColumn(first + l * step);
                                }
                                if (!nominal) {
                                    std::int32_t* groupSource =
                                        &groupSources[batched * 4 * kStencilLanes];
                                    std::fill_n(groupSource, 4 * kStencilLanes, -1);
                                    for (int l = 0; l < n; ++l) {
                                        const int px = first + l * step;
                                        if (marcherOnly(px, py)) continue;
                                        for (int corner = 0; corner < 4; ++corner) {
                                            groupSource[corner * kStencilLanes + l] =
                                                columnSource[corner / 2][px] * 2 +
                                                rowSource[corner % 2][py];
                                        }
                                    }
                                    g.source = groupSource;
                                }
                            }
                            batch[batched++] = g;
                            if (batched == kStencilBatch ||
                                (batched + 1) * corners > kStencilBatchWalks) {
                                flush();
                            }
                        }
                    }
                    if (fix) {  // probes no stencil serves, once the walks have added
                        flush();
                        auto exact = [&](int px) {
                            addSum(px, py,
                                   mergedRay(marcher, c, up, probeCentre(px, py), k, upperValue,
                                             sky, merge));
                        };
                        if (marcherRow(py)) {
                            for (int px = 0; px < probesX; ++px) exact(px);
                        } else {
                            for (int px : marcherColumns) exact(px);
                        }
                    }
                }
                flush();  // before `beyond` changes with the direction
            }
            const float scale = 1.0f / static_cast<float>(group);
            for (int py = y0; py < y1; ++py) {
                Rgb* out = &current[s * probes + static_cast<std::size_t>(py) * probesX];
                for (int q = 0; q < classes; ++q) {
                    const float* in[3];
                    for (int ch = 0; ch < 3; ++ch) in[ch] = &sumAt(q, py, ch);
                    for (int m = 0, px = q; px < probesX; ++m, px += step) {
                        out[px] = Rgb(in[0][m], in[1][m], in[2][m]) * scale;
                    }
                }
            }
        }
    });
    return current;
}

}  // namespace luxel::gi2d::rc
