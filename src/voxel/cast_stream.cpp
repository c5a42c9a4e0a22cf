// castRayBatch and occludedBatch: castRay's walk (src/voxel/fast_walk.h) run for several rays at
// once, one ray per SIMD lane (Highway, the widest vector the CPU has: 8 doubles with AVX-512, 4
// with AVX2), each lane with its own ray so coherent and incoherent rays alike fill the vector. A
// lane whose ray ends (hit, miss, step cap) records it and, once half the lanes are idle, all idle
// lanes take the next rays. Steps and jumps are one operation per lane: a voxel of a non-empty
// brick is a box of one cell, left by the same exit test as an empty box of bricks (for one cell it
// picks the A&W step, lowest axis on ties), so each lane follows its ray through the same cells
// with the same double arithmetic as castRay and the results equal castRay's bit for bit, loop
// count included (docs/algorithms/voxel-traversal.md §4). An empty brick is left through the empty
// cube of bricks its reach gives towards the lane's octant, as in the shared kernel. In a non-empty
// brick, a lane in an empty half of it (src/voxel/brick_blocks.h) crosses the half as one box and
// adds the visits the per-voxel loop makes there (one per cell step), so `steps` still counts that
// loop's iterations. Rays that start inside the world take the one-ray loop instead (measured
// faster for them, Lanes in cast_stream.h). Which rays take lanes and where each starts:
// src/voxel/lane_start-inl.h; a lane's state: src/voxel/lane_state-inl.h.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "voxel/cast_stream.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off
#include <hwy/highway.h>
// clang-format on

#include <cstddef>
#include <cstdint>

#include "voxel/brick_blocks.h"
#include "voxel/cast_stream.h"
#include "voxel/fast_walk.h"
#include "voxel/lane_start-inl.h"
#include "voxel/lane_state-inl.h"

HWY_BEFORE_NAMESPACE();
namespace luxel::voxel::stream::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
namespace shared = gpu::shared;

void TraceStream(const Walk& walk, const Ray* rays, std::size_t count, shared::VoxelTrace* out) {
    using D = hn::ScalableTag<double>;
    const D d;
    const hn::RebindToSigned<D> di;
    const hn::RebindToUnsigned<D> du;
    using V = hn::Vec<D>;
    using M = hn::Mask<D>;
    const std::size_t lanes = hn::Lanes(d);
    HWY_ASSERT(lanes <= kMaxLanes);
    // Two packets of lanes, stepped alternately so one's memory reads overlap the other's
    // arithmetic (a step is one long dependency chain).
    HWY_ALIGN double state[2][kFields][kMaxLanes] = {};
    for (std::size_t l = 0; l < lanes; ++l) state[0][kRay][l] = state[1][kRay][l] = -1.0;

    const VoxelWorld& world = *walk.world;
    const Int3 size = world.size();
    const Int3 bricks = world.brickCount();
    const std::uint64_t* masks = world.brickMaskData();
    const std::uint8_t* reachPlanes = world.brickReachData();
    const std::int64_t brickTotal = std::int64_t{bricks.x} * bricks.y * bricks.z;
    const double tMax = walk.tMax;

    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0),
            three = hn::Set(d, 3.0), four = hn::Set(d, 4.0);
    const V quarter = hn::Set(d, 0.25), minusOne = hn::Set(d, -1.0);
    const V inf = hn::Set(d, fast::kInf), vtMax = hn::Set(d, tMax);
    const V cap = hn::Set(d, static_cast<double>(walk.cap));
    const V sizeX = hn::Set(d, size.x), sizeY = hn::Set(d, size.y), sizeZ = hn::Set(d, size.z);
    const V bricksX = hn::Set(d, bricks.x), bricksY = hn::Set(d, bricks.y);
    // The reach gathers read 8 bytes at a byte offset: the last 8 of the planes at most.
    const auto lastByte = hn::Set(di, brickTotal * VoxelWorld::kOctants - 8);
    const M none = hn::Lt(zero, zero);

    // Rays started (voxelStart, one per lane) but not yet given a lane, as lane arrays.
    HWY_ALIGN double pending[kFields][kMaxLanes];
    std::size_t pendingCount = 0, pendingNext = 0;
    std::size_t nextRay = 0;
    const auto startRays = [&] {
        pendingCount = StartRays(d, walk, rays, count, nextRay, out, pending);
        pendingNext = 0;
    };
    // Gives idle lanes the next started rays until every lane is busy or the rays run out.
    const auto refill = [&](int p) {
        for (std::size_t l = 0; l < lanes; ++l) {
            if (state[p][kRay][l] >= 0.0) continue;
            while (pendingNext == pendingCount && nextRay < count) startRays();
            if (pendingNext == pendingCount) return;
            for (int f = 0; f < kFields; ++f) state[p][f][l] = pending[f][pendingNext];
            ++pendingNext;
        }
    };
    const auto raysLeft = [&] { return nextRay < count || pendingNext < pendingCount; };

    const auto load = [&](Packet<D>& P, int p) { LoadPacket(d, state[p], P); };
    const auto store = [&](const Packet<D>& P, int p) { StorePacket(d, P, state[p]); };

    // One iteration of voxelTraverse's loop for every busy lane of P; true when P has ended
    // rays and either half its lanes are idle with rays left to start, or all are idle.
    const auto advance = [&](Packet<D> & P) __attribute__((always_inline))->bool {
        V &ox = P.ox, &oy = P.oy, &oz = P.oz, &ix = P.ix, &iy = P.iy, &iz = P.iz;
        V &dx = P.dx, &dy = P.dy, &dz = P.dz, &sx = P.sx, &sy = P.sy, &sz = P.sz;
        V &kx = P.kx, &ky = P.ky, &kz = P.kz, &cx = P.cx, &cy = P.cy, &cz = P.cz;
        V &nx = P.nx, &ny = P.ny, &nz = P.nz, &t = P.t, &axis = P.axis;
        V &steps = P.steps, &ray = P.ray;
        M& active = P.active;
        {
            // The loop head of voxelTraverse: the step cap, then the current cell's brick.
            const M capped = hn::And(active, hn::Ge(steps, cap));
            const M go = hn::AndNot(capped, active);
            steps = hn::IfThenElse(go, hn::Add(steps, one), steps);
            const V bx = hn::Floor(hn::Mul(cx, quarter));
            const V by = hn::Floor(hn::Mul(cy, quarter));
            const V bz = hn::Floor(hn::Mul(cz, quarter));
            const auto brick =
                hn::ConvertTo(di, hn::MulAdd(hn::MulAdd(bz, bricksY, by), bricksX, bx));
            const auto mask = hn::GatherIndex(du, masks, brick);
            // The cell within its brick.
            const V ux = hn::NegMulAdd(bx, four, cx), uy = hn::NegMulAdd(by, four, cy),
                    uz = hn::NegMulAdd(bz, four, cz);
            const V bit = hn::MulAdd(uz, hn::Set(d, 16.0), hn::MulAdd(uy, four, ux));
            const auto bitU = hn::BitCast(du, hn::ConvertTo(di, bit));
            const auto setBit = hn::And(mask >> bitU, hn::Set(du, 1));
            const M hit = hn::And(go, hn::RebindMask(d, hn::Ne(setBit, hn::Zero(du))));
            const M occupied = hn::RebindMask(d, hn::Ne(mask, hn::Zero(du)));
            const M live = hn::AndNot(hit, go);

            // The box to leave: the cell itself in a non-empty brick, else the empty cube of
            // bricks from this one towards the ray's octant (clipped to the world).
            const auto reachByte = hn::Add(brick, hn::ConvertTo(di, P.plane));
            const auto offset = hn::Min(reachByte, lastByte);
            const auto word =
                hn::GatherOffset(di, reinterpret_cast<const std::int64_t*>(reachPlanes), offset);
            const auto shift = hn::ShiftLeft<3>(hn::Sub(reachByte, offset));
            const auto byte =
                hn::And(hn::BitCast(di, hn::BitCast(du, word) >> hn::BitCast(du, shift)),
                        hn::Set(di, 0xFF));
            const V r = hn::Sub(hn::ConvertTo(d, byte), one);
            // The cube spans r more bricks on the side the ray moves to: below the brick on a
            // negative axis, above it otherwise.
            const auto reachDown = [&](V s) { return hn::IfThenElseZero(hn::Lt(s, zero), r); };
            const auto reachUp = [&](V s) { return hn::IfThenElse(hn::Lt(s, zero), zero, r); };
            // In a non-empty brick, the empty half around the cell (y first, then x, then z:
            // ground and walls are mostly horizontal or vertical layers) where the step cap allows
            // its visits; hx2 etc.: the axis the half halves (2 cells), the others span the brick.
            // Quarter columns and octants would save 0.5-1.6% more iterations: less than they cost.
            const auto halfMask = [&](V u, const std::uint64_t(&h)[2]) {
                return hn::IfThenElse(hn::RebindMask(du, hn::Ge(u, two)), hn::Set(du, h[1]),
                                      hn::Set(du, h[0]));
            };
            const auto clear = [&](hn::Vec<decltype(du)> m) {
                return hn::RebindMask(d, hn::Eq(hn::And(mask, m), hn::Zero(du)));
            };
            const M eY = clear(halfMask(uy, blocks::kHalfY));
            const M eX = clear(halfMask(ux, blocks::kHalfX));
            const M eZ = clear(halfMask(uz, blocks::kHalfZ));
            M sub = hn::And(hn::And(hn::And(occupied, live), hn::Or(hn::Or(eX, eY), eZ)),
                            hn::Le(steps, hn::Sub(cap, hn::Set(d, blocks::kMaxVisits))));
            const M hy2 = eY, hx2 = hn::AndNot(eY, eX), hz2 = hn::AndNot(hn::Or(eX, eY), eZ);
            const auto boxLo = [&](V b, V c, V s, M half2) {
                const V block = hn::IfThenElse(
                    half2, hn::Mul(hn::Floor(hn::Mul(c, hn::Set(d, 0.5))), two), hn::Mul(b, four));
                return hn::IfThenElse(occupied, hn::IfThenElse(sub, block, c),
                                      hn::Max(hn::Mul(hn::Sub(b, reachDown(s)), four), zero));
            };
            const auto boxHi = [&](V lo, V b, V c, V s, V n, M half2) {
                const V block =
                    hn::Min(hn::Add(lo, hn::IfThenElse(half2, one, three)), hn::Sub(n, one));
                return hn::IfThenElse(
                    occupied, hn::IfThenElse(sub, block, c),
                    hn::Sub(hn::Min(hn::Mul(hn::Add(hn::Add(b, reachUp(s)), one), four), n), one));
            };
            V lx = boxLo(bx, cx, sx, hx2), ly = boxLo(by, cy, sy, hy2), lz = boxLo(bz, cz, sz, hz2);
            V hx = boxHi(lx, bx, cx, sx, sizeX, hx2), hy = boxHi(ly, by, cy, sy, sizeY, hy2),
              hz = boxHi(lz, bz, cz, sz, sizeZ, hz2);
            // exitAt: (cell + k - o) * inv, the one boundary formula.
            const auto exitAt = [&](V c, V k, V o, V inv) {
                return hn::Mul(hn::Sub(hn::Add(c, k), o), inv);
            };
            const M upX = hn::Gt(sx, zero), upY = hn::Gt(sy, zero), upZ = hn::Gt(sz, zero);
            const M flatX = hn::Eq(sx, zero), flatY = hn::Eq(sy, zero), flatZ = hn::Eq(sz, zero);
            V tx = hn::IfThenElse(flatX, inf, exitAt(hn::IfThenElse(upX, hx, lx), kx, ox, ix));
            V ty = hn::IfThenElse(flatY, inf, exitAt(hn::IfThenElse(upY, hy, ly), ky, oy, iy));
            V tz = hn::IfThenElse(flatZ, inf, exitAt(hn::IfThenElse(upZ, hz, lz), kz, oz, iz));
            // The exit axis: the first plane crossed, lowest axis on ties.
            M pickY = hn::Lt(ty, tx);
            V tJump = hn::IfThenElse(pickY, ty, tx);
            M pickZ = hn::Lt(tz, tJump);
            tJump = hn::IfThenElse(pickZ, tz, tJump);
            // A half whose exit lies past tMax (or overflowed to inf) is not jumped: the
            // per-voxel loop may end inside it, so those lanes take one voxel step instead (a box
            // of one cell, whose exits are the cell's next boundaries).
            const M unsafe = hn::AndNot(hn::And(hn::Le(tJump, vtMax), hn::Lt(tJump, inf)), sub);
            if (HWY_UNLIKELY(!hn::AllFalse(d, unsafe))) {
                sub = hn::AndNot(unsafe, sub);
                lx = hn::IfThenElse(unsafe, cx, lx);
                ly = hn::IfThenElse(unsafe, cy, ly);
                lz = hn::IfThenElse(unsafe, cz, lz);
                hx = hn::IfThenElse(unsafe, cx, hx);
                hy = hn::IfThenElse(unsafe, cy, hy);
                hz = hn::IfThenElse(unsafe, cz, hz);
                tx = hn::IfThenElse(unsafe, nx, tx);
                ty = hn::IfThenElse(unsafe, ny, ty);
                tz = hn::IfThenElse(unsafe, nz, tz);
                pickY = hn::Lt(ty, tx);
                tJump = hn::IfThenElse(pickY, ty, tx);
                pickZ = hn::Lt(tz, tJump);
                tJump = hn::IfThenElse(pickZ, tz, tJump);
            }
            const M selZ = pickZ;
            const M selY = hn::AndNot(pickZ, pickY);
            const M selX = hn::Not(hn::Or(pickY, pickZ));
            const M escaped = hn::And(live, hn::Eq(tJump, inf));
            const M move = hn::AndNot(escaped, live);

            // The other axes: the first cell whose exit the per-voxel loop has not yet taken at
            // tJump (taken: earlier, or tied and a lower axis than the exit axis).
            const auto settle = [&](V& c, V& next, M sel, M flat, M up, V lo, V hi, V o, V dir,
                                    V inv, V k, V n, M lower) {
                const auto taken = [&](V tc) {
                    return hn::Or(hn::Lt(tc, tJump), hn::And(hn::Eq(tc, tJump), lower));
                };
                const M need = hn::And(hn::AndNot(hn::Or(sel, flat), move), taken(next));
                if (hn::AllFalse(d, need)) return;
                const V s = hn::IfThenElse(up, one, minusOne);
                const V first = c, last = hn::IfThenElse(up, hi, lo);
                V g = hn::Floor(
                    hn::Min(hn::Max(hn::MulAdd(tJump, dir, o), minusOne), hn::Add(n, one)));
                g = hn::IfThenElse(up, hn::Min(hn::Max(g, first), last),
                                   hn::Max(hn::Min(g, first), last));
                // Usually the guess is the cell or one off: one correction each way, then loops
                // only where a lane is still short of its cell.
                const auto backOk = [&](V cell) {
                    return hn::AndNot(taken(exitAt(hn::Sub(cell, s), k, o, inv)),
                                      hn::Ne(cell, first));
                };
                const M back = hn::And(need, backOk(g));
                g = hn::IfThenElse(back, hn::Sub(g, s), g);
                V tc = exitAt(g, k, o, inv);
                M forward = hn::And(need, hn::And(hn::Ne(g, last), taken(tc)));
                g = hn::IfThenElse(forward, hn::Add(g, s), g);
                tc = hn::IfThenElse(forward, exitAt(g, k, o, inv), tc);
                M more = hn::Or(hn::And(back, backOk(g)),
                                hn::And(forward, hn::And(hn::Ne(g, last), taken(tc))));
                if (HWY_UNLIKELY(!hn::AllFalse(d, more))) {
                    for (;;) {
                        const M again = hn::And(need, backOk(g));
                        if (hn::AllFalse(d, again)) break;
                        g = hn::IfThenElse(again, hn::Sub(g, s), g);
                    }
                    tc = exitAt(g, k, o, inv);
                    for (;;) {
                        forward = hn::And(need, hn::And(hn::Ne(g, last), taken(tc)));
                        if (hn::AllFalse(d, forward)) break;
                        g = hn::IfThenElse(forward, hn::Add(g, s), g);
                        tc = hn::IfThenElse(forward, exitAt(g, k, o, inv), tc);
                    }
                }
                c = hn::IfThenElse(need, g, c);
                next = hn::IfThenElse(need, tc, next);
            };
            const M lowerX = hn::Not(selX);  // a > 0
            const M lowerY = selZ;           // a > 1
            V ncx = cx, ncy = cy, ncz = cz;
            settle(ncx, nx, selX, flatX, upX, lx, hx, ox, dx, ix, kx, sizeX, lowerX);
            settle(ncy, ny, selY, flatY, upY, ly, hy, oy, dy, iy, ky, sizeY, lowerY);
            settle(ncz, nz, selZ, flatZ, upZ, lz, hz, oz, dz, iz, kz, sizeZ, none);
            // The exit axis crosses its box plane.
            ncx = hn::IfThenElse(hn::And(move, selX),
                                 hn::IfThenElse(upX, hn::Add(hx, one), hn::Sub(lx, one)), ncx);
            ncy = hn::IfThenElse(hn::And(move, selY),
                                 hn::IfThenElse(upY, hn::Add(hy, one), hn::Sub(ly, one)), ncy);
            ncz = hn::IfThenElse(hn::And(move, selZ),
                                 hn::IfThenElse(upZ, hn::Add(hz, one), hn::Sub(lz, one)), ncz);
            const auto outsideAxis = [&](V c, V n) {
                return hn::Or(hn::Lt(c, zero), hn::Ge(c, n));
            };
            const M outside = hn::Or(hn::Or(outsideAxis(ncx, sizeX), outsideAxis(ncy, sizeY)),
                                     hn::Or(outsideAxis(ncz, sizeZ), hn::Gt(tJump, vtMax)));
            const M left = hn::And(move, outside);
            const M stepped = hn::AndNot(outside, move);
            // A jump over a half stands for the per-voxel loop's visits to the cells it crossed,
            // one per cell step: the Manhattan distance to the new cell, less the visit counted
            // above.
            const V crossed = hn::Add(hn::Add(hn::Abs(hn::Sub(ncx, cx)), hn::Abs(hn::Sub(ncy, cy))),
                                      hn::Abs(hn::Sub(ncz, cz)));
            steps =
                hn::IfThenElse(hn::And(move, sub), hn::Add(steps, hn::Sub(crossed, one)), steps);
            t = hn::IfThenElse(move, tJump, t);
            axis = hn::IfThenElse(
                move, hn::IfThenElse(selX, zero, hn::IfThenElse(selY, one, hn::Set(d, 2.0))), axis);
            cx = hn::IfThenElse(stepped, ncx, cx);
            cy = hn::IfThenElse(stepped, ncy, cy);
            cz = hn::IfThenElse(stepped, ncz, cz);
            nx = hn::IfThenElse(hn::And(stepped, selX), exitAt(cx, kx, ox, ix), nx);
            ny = hn::IfThenElse(hn::And(stepped, selY), exitAt(cy, ky, oy, iy), ny);
            nz = hn::IfThenElse(hn::And(stepped, selZ), exitAt(cz, kz, oz, iz), nz);

            // Rays that ended: record them, free their lanes.
            const M ended = hn::Or(hn::Or(capped, hit), hn::Or(escaped, left));
            if (!hn::AllFalse(d, ended)) {
                HWY_ALIGN double lane[8][kMaxLanes];
                HWY_ALIGN std::uint8_t bits[(kMaxLanes + 7) / 8 + 8] = {};
                hn::Store(cx, d, lane[0]);
                hn::Store(cy, d, lane[1]);
                hn::Store(cz, d, lane[2]);
                hn::Store(t, d, lane[3]);
                hn::Store(axis, d, lane[4]);
                hn::Store(steps, d, lane[5]);
                hn::Store(ray, d, lane[6]);
                hn::Store(hn::IfThenElseZero(hit, one), d, lane[7]);
                hn::StoreMaskBits(d, ended, bits);
                HWY_ALIGN double cappedLane[kMaxLanes];
                hn::Store(hn::IfThenElseZero(capped, one), d, cappedLane);
                HWY_ALIGN double stepX[kMaxLanes], stepY[kMaxLanes], stepZ[kMaxLanes];
                hn::Store(sx, d, stepX);
                hn::Store(sy, d, stepY);
                hn::Store(sz, d, stepZ);
                for (std::size_t l = 0; l < lanes; ++l) {
                    if (!((bits[l / 8] >> (l % 8)) & 1)) continue;
                    const std::size_t i = static_cast<std::size_t>(lane[6][l]);
                    const int n = static_cast<int>(lane[5][l]);
                    if (lane[7][l] != 0.0) {
                        out[i] = shared::VoxelTrace(
                            true, false,
                            shared::ivec3(int(lane[0][l]), int(lane[1][l]), int(lane[2][l])),
                            lane[3][l], int(lane[4][l]),
                            shared::ivec3(int(stepX[l]), int(stepY[l]), int(stepZ[l])), n);
                    } else {
                        out[i] = shared::voxelMiss(n, cappedLane[l] != 0.0);
                    }
                }
                ray = hn::IfThenElse(ended, minusOne, ray);
                active = hn::AndNot(ended, active);
                const std::size_t idle = lanes - hn::CountTrue(d, active);
                return (idle * 2 >= lanes && raysLeft()) || idle == lanes;
            }
        }
        return false;
    };

    refill(0);
    refill(1);
    Packet<D> A, B;
    load(A, 0);
    load(B, 1);
    if (hn::AllFalse(d, A.active) && hn::AllFalse(d, B.active)) return;  // no ray got a lane
    for (;;) {
        const bool wantA = advance(A);
        const bool wantB = advance(B);
        if (HWY_LIKELY(!wantA && !wantB)) continue;
        if (wantA) {
            store(A, 0);
            refill(0);
            load(A, 0);
        }
        if (wantB) {
            store(B, 1);
            refill(1);
            load(B, 1);
        }
        if (hn::AllFalse(d, A.active) && hn::AllFalse(d, B.active) && !raysLeft()) return;
    }
}

}  // namespace luxel::voxel::stream::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace luxel::voxel::stream {

HWY_EXPORT(TraceStream);

void trace(const Walk& walk, std::span<const Ray> rays, gpu::shared::VoxelTrace* out) {
    HWY_DYNAMIC_DISPATCH(TraceStream)(walk, rays.data(), rays.size(), out);
}

}  // namespace luxel::voxel::stream
#endif
