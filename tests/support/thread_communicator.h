#pragma once
// A group of ranks in one process, one thread each, for testing collectives without MPI: every rank holds a
// ThreadCommunicator over the same ThreadGroup and calls the collectives in the same order, as MPI ranks do.
#include <barrier>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "util/distributed.h"

namespace facetlight::test {

class ThreadGroup {
  public:
    explicit ThreadGroup(int size) : size_(size), slots_(size_t(size)), sync_(size) {}
    int size() const { return size_; }

    // Rank r publishes `bytes`; once every rank has, each reads all of them; then the slots are free again.
    std::vector<std::string> exchange(int rank, std::string_view bytes) {
        slots_[size_t(rank)] = std::string(bytes);
        sync_.arrive_and_wait();
        std::vector<std::string> all = slots_;
        sync_.arrive_and_wait();
        return all;
    }

  private:
    int size_;
    std::vector<std::string> slots_;
    std::barrier<> sync_;
};

class ThreadCommunicator final : public Communicator {
  public:
    ThreadCommunicator(ThreadGroup& group, int rank) : group_(group), rank_(rank) {}
    int rank() const override { return rank_; }
    int size() const override { return group_.size(); }
    void sumToRoot(std::span<uint64_t> values) override {
        const std::vector<std::string> all = group_.exchange(rank_, asBytes<uint64_t>(values));
        if (!isRoot()) return;
        for (size_t r = 1; r < all.size(); ++r) {
            std::vector<uint64_t> theirs;
            appendFromBytes(all[r], theirs);
            for (size_t i = 0; i < values.size(); ++i) values[i] += theirs[i];
        }
    }
    void broadcast(std::string& bytes) override { bytes = group_.exchange(rank_, bytes)[0]; }
    std::vector<std::string> gather(std::string_view bytes) override {
        std::vector<std::string> all = group_.exchange(rank_, bytes);
        return isRoot() ? all : std::vector<std::string>{};
    }
    std::vector<std::string> allGather(std::string_view bytes) override {
        return group_.exchange(rank_, bytes);
    }

  private:
    ThreadGroup& group_;
    int rank_;
};

// Runs body(comm) on every rank of a group of `size`, one thread each, and returns when all are done.
inline void onEveryRank(int size, const std::function<void(Communicator&)>& body) {
    ThreadGroup group(size);
    std::vector<std::jthread> ranks;
    for (int r = 0; r < size; ++r) {
        ranks.emplace_back([&group, &body, r] {
            ThreadCommunicator comm(group, r);
            body(comm);
        });
    }
}

}  // namespace facetlight::test
