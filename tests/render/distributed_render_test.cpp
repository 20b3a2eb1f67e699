// The serial side of distributed renders (docs/distributed.md): map-photon block ranges and tile shares, put
// back together as the ranks do, equal the single-process photon map, angular histogram and image bit for
// bit. The MPI side (mpirun renders against single-process ones) runs in tests/mpi.cmake.
#include <gtest/gtest.h>

#include <cstring>

#include "cuts/mesh_resolver.h"
#include "photonmap/floor_photons.h"
#include "photonmap/photon_map.h"
#include "render/renderer.h"
#include "stats/angular_histogram.h"
#include "support/fixtures.h"
#include "support/thread_communicator.h"
#include "util/distributed.h"
#include "util/error.h"

namespace facetlight {
namespace {

using test::roundBrilliant;

TraceSettings smallTrace() {
    TraceSettings t;
    t.photons = 20'000;
    t.threads = 2;
    t.seed = 11;
    return t;
}

constexpr uint64_t kMapPhotons = 7 * kPhotonBlock + 321;  // a partial last block

TEST(DistributedFloorPhotons, BlockRangesInOrderEqualTheWholePass) {
    const TraceSettings t = smallTrace();
    const Scene scene(roundBrilliant(), t);
    const TraceBase trace(scene, t);
    const FloorPhotons whole = traceFloorPhotons(trace, kMapPhotons, 2);
    ASSERT_GT(whole.caustic.size(), 0u);
    ASSERT_GT(whole.crownExits.total, 0u);
    for (int size : {2, 3, 5}) {
        std::vector<Photon> caustic;
        AngularHistogram histogram;
        uint64_t traced = 0;
        for (int r = 0; r < size; ++r) {
            const IndexRange blocks = partition(blockCount(kMapPhotons), r, size);
            const FloorPhotons part =
                traceFloorPhotons(trace, kMapPhotons, blocks.begin, blocks.end, 1 + r % 2);
            EXPECT_FALSE(part.cancelled);
            caustic.insert(caustic.end(), part.caustic.begin(), part.caustic.end());
            std::vector<uint64_t> sum = histogram.tallies();
            const std::vector<uint64_t> theirs = part.crownExits.tallies();
            for (size_t i = 0; i < sum.size(); ++i) sum[i] += theirs[i];
            histogram.setTallies(sum);
            traced += part.traced;
        }
        EXPECT_EQ(traced, kMapPhotons);
        ASSERT_EQ(caustic.size(), whole.caustic.size()) << size << " ranks";
        EXPECT_EQ(0, std::memcmp(caustic.data(), whole.caustic.data(), caustic.size() * sizeof(Photon)));
        EXPECT_EQ(histogram.counts, whole.crownExits.counts);
        EXPECT_EQ(histogram.total, whole.crownExits.total);
    }
}

TEST(DistributedFloorPhotons, SerialCommunicatorGivesTheWholePass) {
    const TraceSettings t = smallTrace();
    const Scene scene(roundBrilliant(), t);
    const TraceBase trace(scene, t);
    const FloorPhotons whole = traceFloorPhotons(trace, kMapPhotons, 2);
    SerialCommunicator serial;
    const FloorPhotons viaComm = traceFloorPhotons(serial, trace, kMapPhotons, 1);
    ASSERT_EQ(viaComm.caustic.size(), whole.caustic.size());
    EXPECT_EQ(
        0, std::memcmp(viaComm.caustic.data(), whole.caustic.data(), whole.caustic.size() * sizeof(Photon)));
    EXPECT_EQ(viaComm.crownExits.counts, whole.crownExits.counts);
    EXPECT_EQ(viaComm.traced, kMapPhotons);
}

TEST(AngularHistogramTallies, RoundTripAndRejectWrongLength) {
    AngularHistogram h;
    h.add(normalize(Vec3{0.3, -0.2, 1}));
    h.add(Vec3{0, 0, -1});  // below the horizon: counted in total only
    AngularHistogram copy;
    copy.setTallies(h.tallies());
    EXPECT_EQ(copy.counts, h.counts);
    EXPECT_EQ(copy.total, 2u);
    EXPECT_THROW(copy.setTallies(std::vector<uint64_t>(3)), Error);
}

TEST(TileShares, CoverEveryPixelOnce) {
    for (auto [w, h] : {std::pair{64, 48}, {37, 20}, {5, 5}}) {
        for (int size : {1, 2, 3, 7, 40}) {
            uint64_t sum = 0;
            for (int r = 0; r < size; ++r) sum += sharePixelCount(w, h, {r, size});
            EXPECT_EQ(sum, uint64_t(w) * uint64_t(h)) << w << "x" << h << " over " << size;
        }
    }
    EXPECT_THROW(sharePixelCount(10, 10, {2, 2}), Error);
    EXPECT_THROW(sharePixelCount(10, 10, {0, 0}), Error);
}

TEST(TileShares, RenderedApartAndPlacedEqualTheWholeRender) {
    const TraceSettings t = smallTrace();
    const Scene scene(roundBrilliant(), t);
    const TraceBase trace(scene, t);
    FloorPhotons photons = traceFloorPhotons(trace, kMapPhotons, 2);
    const PhotonMap caustics(std::move(photons.caustic), 2);
    RenderSettings r;
    r.width = 53;  // tiles that do not divide the image
    r.height = 40;
    r.samples = 2;
    const RenderedImage whole = render(scene, caustics, r, 2, t.seed);
    for (int size : {2, 3}) {
        RenderedImage assembled;
        assembled.width = r.width;
        assembled.height = r.height;
        assembled.pixels.assign(whole.pixels.size(), Vec3{});
        for (int rank = 0; rank < size; ++rank) {
            const TileShare share{rank, size};
            RunControl control;
            const RenderedImage part = render(scene, caustics, r, 1 + rank % 2, t.seed, &control, share);
            EXPECT_FALSE(part.cancelled);
            EXPECT_EQ(control.done(), sharePixelCount(r.width, r.height, share));
            const std::vector<Vec3> pixels = sharePixels(part, share);
            // Only the share's pixels were rendered: the others are still zero.
            size_t lit = 0;
            for (const Vec3& p : part.pixels) lit += !(p == Vec3{});
            EXPECT_LE(lit, pixels.size());
            EXPECT_GT(lit, 0u);
            placeSharePixels(assembled, share, pixels);
        }
        EXPECT_TRUE(assembled.pixels == whole.pixels) << size << " shares";
    }
    RenderedImage wrong = whole;
    EXPECT_THROW(placeSharePixels(wrong, {0, 2}, std::vector<Vec3>(3)), Error);
}

TEST(TileShares, SerialCommunicatorRendersTheWholeImage) {
    const TraceSettings t = smallTrace();
    const Scene scene(roundBrilliant(), t);
    RenderSettings r;
    r.width = 40;
    r.height = 24;
    r.samples = 1;
    SerialCommunicator serial;
    const RenderedImage a = render(scene, PhotonMap(), r, 2, t.seed);
    const RenderedImage b = render(serial, scene, PhotonMap(), r, 1, t.seed);
    EXPECT_FALSE(b.cancelled);
    EXPECT_TRUE(a.pixels == b.pixels);
}

// Every rank learns whether any rank raised its flag (a cancel on one rank stops them all): with the flag on
// no rank, on one rank (first, middle or last) and on every rank, over groups of 1 to 4 ranks.
TEST(AnyRank, EveryRankSeesAFlagRaisedOnAnyRank) {
    for (int size = 1; size <= 4; ++size) {
        for (int raised = -2; raised < size; ++raised) {  // -2: none, -1: all, else that rank alone
            const auto flagOf = [&](int rank) { return raised == -1 || raised == rank; };
            std::vector<int> seen(size_t(size), -1);
            test::onEveryRank(size, [&](Communicator& comm) {
                seen[size_t(comm.rank())] = anyRank(comm, flagOf(comm.rank()));
            });
            for (int r = 0; r < size; ++r)
                EXPECT_EQ(seen[size_t(r)], raised != -2)
                    << size << " ranks, raised " << raised << ", rank " << r;
        }
    }
    SerialCommunicator serial;
    EXPECT_TRUE(anyRank(serial, true));
    EXPECT_FALSE(anyRank(serial, false));
}

}  // namespace
}  // namespace facetlight
