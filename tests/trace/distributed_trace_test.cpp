// The serial side of distributed runs: the block partition, the flat tallies a rank sends, and that the
// ranks' shares summed equal a whole trace. The MPI side runs under mpirun in tests/mpi.cmake.
#include "util/distributed.h"

#include <gtest/gtest.h>

#include "io/mesh_io.h"
#include "support/fixtures.h"
#include "trace/distributed_trace.h"
#include "util/error.h"

using namespace facetlight;

namespace {

const std::string kData = FACETLIGHT_SOURCE_DIR "/tests/data/";

TraceSettings smallTrace() {
    TraceSettings s;
    s.photons = 5 * kPhotonBlock + 123;  // a partial last block
    s.threads = 2;
    s.seed = 7;
    return s;
}

}  // namespace

TEST(Partition, CoversTheRangeInOrderWithBalancedParts) {
    for (uint64_t count : {0u, 1u, 5u, 7u, 100u}) {
        for (int size : {1, 2, 3, 4, 8}) {
            uint64_t next = 0;
            for (int r = 0; r < size; ++r) {
                const IndexRange part = partition(count, r, size);
                EXPECT_EQ(part.begin, next) << count << " over " << size;
                EXPECT_LE(part.size(), count / size + 1);
                EXPECT_GE(part.size(), count / size);
                next = part.end;
            }
            EXPECT_EQ(next, count);
        }
    }
}

TEST(FacetStatsTallies, RoundTripAndSumLikeMerge) {
    const Stone stone = loadStone(kData + "brilliant.asc");
    const Scene scene(stone, smallTrace());
    const TraceBase trace(scene, smallTrace());
    FacetStats a(stone.facets.size()), b(stone.facets.size());
    traceBlocks(trace, 0, 2, 1, a);
    traceBlocks(trace, 2, 6, 1, b);
    ASSERT_GT(a.exited, 0u);

    FacetStats copy(stone.facets.size());
    copy.setTallies(a.tallies());
    EXPECT_EQ(copy, a);

    std::vector<uint64_t> summed = a.tallies();
    const std::vector<uint64_t> other = b.tallies();
    for (size_t i = 0; i < summed.size(); ++i) summed[i] += other[i];
    FacetStats merged = a;
    merged.merge(b);
    FacetStats fromSum(stone.facets.size());
    fromSum.setTallies(summed);
    EXPECT_EQ(fromSum, merged);

    FacetStats wrong(stone.facets.size() + 1);
    EXPECT_THROW(wrong.setTallies(a.tallies()), Error);
}

TEST(DistributedTrace, RankSharesSumToTheWholeTrace) {
    const Stone stone = loadStone(kData + "brilliant.asc");
    const TraceSettings settings = smallTrace();
    const TraceResult whole = test::traceStone(stone, settings);
    for (int size : {2, 3, 4}) {
        const Scene scene(stone, settings);
        const TraceBase trace(scene, settings);
        FacetStats sum(stone.facets.size());
        uint64_t photons = 0;
        for (int r = 0; r < size; ++r) {
            const IndexRange blocks = partition(blockCount(settings.photons), r, size);
            FacetStats share(stone.facets.size());
            traceBlocks(trace, blocks.begin, blocks.end, 1 + r % 2, share);
            sum.merge(share);
            photons += share.photons;
        }
        EXPECT_EQ(sum, whole.stats) << size << " ranks";
        EXPECT_EQ(photons, settings.photons);
    }
}

TEST(DistributedTrace, SerialCommunicatorGivesTheWholeTrace) {
    const Stone stone = loadStone(kData + "brilliant.asc");
    SerialCommunicator comm;
    const Scene scene(stone, smallTrace());
    const TraceResult result = traceDistributed(comm, TraceBase(scene, smallTrace()));
    EXPECT_EQ(result.stats, test::traceStone(stone, smallTrace()).stats);
    EXPECT_FALSE(result.cancelled);
    EXPECT_EQ(localPhotons(comm, smallTrace().photons), smallTrace().photons);
}
