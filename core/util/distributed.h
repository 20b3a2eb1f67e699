#pragma once
// How a run is spread over processes: a Communicator with the few collectives facetlight needs. The serial
// one (rank 0 of 1) is always here; the MPI one lives in cli/mpi_communicator.cpp, built only with
// FACETLIGHT_MPI, so core and the service never link MPI. Every rank calls the collectives in the same order.
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace facetlight {

class Communicator {
  public:
    virtual ~Communicator() = default;

    virtual int rank() const = 0;
    virtual int size() const = 0;
    bool isRoot() const { return rank() == 0; }

    // Element-wise sum of every rank's `values` (the same length everywhere) into rank 0's; integer sums, so
    // the result does not depend on how the ranks are arranged. Other ranks' values are left as they were.
    virtual void sumToRoot(std::span<uint64_t> values) = 0;
    // Rank 0's `bytes` replace every other rank's.
    virtual void broadcast(std::string& bytes) = 0;
    // Every rank's bytes in rank order: on rank 0 only (gather), or on every rank (allGather).
    virtual std::vector<std::string> gather(std::string_view bytes) = 0;
    virtual std::vector<std::string> allGather(std::string_view bytes) = 0;
};

class SerialCommunicator final : public Communicator {
  public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    void sumToRoot(std::span<uint64_t>) override {}
    void broadcast(std::string&) override {}
    std::vector<std::string> gather(std::string_view bytes) override { return {std::string(bytes)}; }
    std::vector<std::string> allGather(std::string_view bytes) override { return {std::string(bytes)}; }
};

// Whether `flag` is true on any rank, on every rank (a collective: every rank must call it).
bool anyRank(Communicator& comm, bool flag);

// Part `rank` of [0, count) cut into `size` contiguous parts whose lengths differ by at most one.
struct IndexRange {
    uint64_t begin = 0, end = 0;
    uint64_t size() const { return end - begin; }
};
IndexRange partition(uint64_t count, int rank, int size);

// Plain values to and from bytes, for the collectives (same machine architecture on every rank).
template <class T>
std::string_view asBytes(std::span<const T> values) {
    return {reinterpret_cast<const char*>(values.data()), values.size_bytes()};
}
template <class T>
void appendFromBytes(std::string_view bytes, std::vector<T>& out) {
    const size_t n = bytes.size() / sizeof(T);
    const size_t at = out.size();
    out.resize(at + n);
    std::memcpy(out.data() + at, bytes.data(), n * sizeof(T));
}

}  // namespace facetlight
