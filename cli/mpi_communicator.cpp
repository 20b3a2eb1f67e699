// The MPI communicator (OpenMPI's world), used when this process was started by mpirun.
#include <mpi.h>

#include <algorithm>
#include <cstdlib>
#include <memory>

#include "process_communicator.h"
#include "util/error.h"

#if defined(__SANITIZE_ADDRESS__)
#define FACETLIGHT_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FACETLIGHT_ASAN 1
#endif
#endif

#ifdef FACETLIGHT_ASAN
// ASan builds (docs/reliability.md): Open MPI 4.1 and the libraries it loads keep start-up allocations until
// exit by design, so LeakSanitizer reports only ours. Matching them needs whole allocation stacks, as Open MPI's
// frames keep no frame pointers for the fast unwinder; this program allocates nothing in its hot loops.
extern "C" const char* __asan_default_options() {
    return "fast_unwind_on_malloc=0";
}
extern "C" const char* __lsan_default_suppressions() {
    return "leak:libmpi.so\nleak:libopen-pal.so\nleak:libopen-rte.so\nleak:libevent\n";
}
#endif

namespace facetlight::cli {
namespace {

// MPI counts are ints: larger buffers go in pieces.
constexpr size_t kChunkBytes = size_t(1) << 30;

void check(int code, const char* what) {
    if (code != MPI_SUCCESS) throw Error(std::string("MPI ") + what + " failed");
}

void broadcastRaw(char* data, size_t bytes) {
    for (size_t at = 0; at < bytes; at += kChunkBytes)
        check(MPI_Bcast(data + at, int(std::min(kChunkBytes, bytes - at)), MPI_BYTE, 0, MPI_COMM_WORLD),
              "broadcast");
}

class MpiCommunicator final : public Communicator {
  public:
    MpiCommunicator() {
        int provided = 0;
        // Only the main thread calls MPI; the tracer's threads never do.
        check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "init");
        MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
        MPI_Comm_size(MPI_COMM_WORLD, &size_);
    }
    ~MpiCommunicator() override { MPI_Finalize(); }

    int rank() const override { return rank_; }
    int size() const override { return size_; }

    void sumToRoot(std::span<uint64_t> values) override {
        const size_t chunk = kChunkBytes / sizeof(uint64_t);
        for (size_t at = 0; at < values.size(); at += chunk) {
            const int n = int(std::min(chunk, values.size() - at));
            void* data = values.data() + at;
            check(MPI_Reduce(rank_ == 0 ? MPI_IN_PLACE : data, rank_ == 0 ? data : nullptr, n, MPI_UINT64_T,
                             MPI_SUM, 0, MPI_COMM_WORLD),
                  "reduce");
        }
    }

    void broadcast(std::string& bytes) override {
        uint64_t length = bytes.size();
        check(MPI_Bcast(&length, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD), "broadcast");
        bytes.resize(length);
        broadcastRaw(bytes.data(), length);
    }

    std::vector<std::string> gather(std::string_view bytes) override {
        uint64_t length = bytes.size();
        std::vector<uint64_t> lengths(rank_ == 0 ? size_ : 0);
        check(MPI_Gather(&length, 1, MPI_UINT64_T, lengths.data(), 1, MPI_UINT64_T, 0, MPI_COMM_WORLD),
              "gather");
        if (rank_ != 0) {
            for (size_t at = 0; at < bytes.size(); at += kChunkBytes)
                check(MPI_Send(bytes.data() + at, int(std::min(kChunkBytes, bytes.size() - at)), MPI_BYTE, 0,
                               0, MPI_COMM_WORLD),
                      "send");
            return {};
        }
        std::vector<std::string> out(size_);
        out[0] = std::string(bytes);
        for (int r = 1; r < size_; ++r) {
            out[r].resize(lengths[r]);
            for (size_t at = 0; at < lengths[r]; at += kChunkBytes)
                check(MPI_Recv(out[r].data() + at, int(std::min(kChunkBytes, lengths[r] - at)), MPI_BYTE, r,
                               0, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
                      "receive");
        }
        return out;
    }

    std::vector<std::string> allGather(std::string_view bytes) override {
        std::vector<std::string> parts = gather(bytes);
        std::vector<uint64_t> lengths(size_);
        std::string joined;
        if (rank_ == 0) {
            for (int r = 0; r < size_; ++r) {
                lengths[r] = parts[r].size();
                joined += parts[r];
            }
        }
        check(MPI_Bcast(lengths.data(), size_, MPI_UINT64_T, 0, MPI_COMM_WORLD), "broadcast");
        broadcast(joined);
        if (rank_ == 0) return parts;
        parts.resize(size_);
        size_t at = 0;
        for (int r = 0; r < size_; ++r) {
            parts[r] = joined.substr(at, lengths[r]);
            at += lengths[r];
        }
        return parts;
    }

  private:
    int rank_ = 0, size_ = 1;
};

// OpenMPI's mpirun sets OMPI_COMM_WORLD_SIZE; PMIx and PMI launchers (srun, prterun) set their rank.
bool launchedByMpi() {
    return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK") || std::getenv("PMI_RANK");
}

}  // namespace

Communicator& processCommunicator() {
    static const std::unique_ptr<Communicator> world =
        launchedByMpi() ? std::unique_ptr<Communicator>(std::make_unique<MpiCommunicator>())
                        : std::make_unique<SerialCommunicator>();
    return *world;
}

void abortOtherRanks(int exitCode) {
    if (processCommunicator().size() > 1) MPI_Abort(MPI_COMM_WORLD, exitCode);
}

}  // namespace facetlight::cli
