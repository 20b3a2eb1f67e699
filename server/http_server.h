#pragma once
// cpp-httplib's server with the guards a public service needs that 0.11 lacks (issue 18): a whole request
// must arrive within a deadline (0.11 only times out single reads, so a client sending a header line every
// 2 s held a thread for ever), each peer may hold only so many connections, threads are added while every
// one is busy (up to a cap) so that slow clients cannot leave /healthz unanswered, and the listen backlog is
// raised from 5. It reads sockets with poll(), so descriptors above 1023 are safe too. When every thread is
// busy at the cap, a new connection ends the one that has waited longest for its request's head (idle between
// requests, or trickling its head in): slow clients from many addresses, each under the per-peer cap, cannot
// hold every thread (issue 31, item 3). A body must keep coming at ConnectionLimits::minBodyRate once its
// first seconds are past, else 408: a client trickling its body held a thread until the request's deadline.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <map>
#include <mutex>
#include <string>
#include <unordered_set>

#include <httplib.h>

namespace facetlight::server {

struct ConnectionLimits {
    size_t threads = 8;                                // started at once
    size_t maxThreads = 256;                           // added while all are busy, never more
    size_t maxPerPeer = 64;                            // connections open at once from one address
    std::chrono::milliseconds requestTimeout{30'000};  // request line, headers and body, from the first byte
    int backlog = 1024;               // connections waiting to be accepted (the kernel caps it at somaxconn)
    size_t keepAliveRequests = 1000;  // requests on one connection (httplib's 5 made pollers reconnect)
    // A request's head (its line and headers): 0.11 kept every header line it was sent, 110 MB a connection.
    size_t maxHeadBytes = 64 << 10;
    size_t maxHeaderLines = 100;  // Host, Content-Type and the others, each a line
    // A body must have brought minBodyRate x (t - bodyGrace) bytes t after its head ended, else 408 (0: no
    // minimum). 1 KiB/s takes a 1 MiB job in 17 min: no honest client is that slow; a few bytes a second, as
    // Kestrel's MinRequestBodyDataRate (240 B/s after 5 s) bounds it, are an attack.
    size_t minBodyRate = 1024;  // bytes per second
    std::chrono::milliseconds bodyGrace{2000};
};

class HttpServer : public httplib::Server {
  public:
    explicit HttpServer(const ConnectionLimits& limits);

    // As bind_to_port and bind_to_any_port, with the listen backlog raised.
    bool bind(const std::string& host, int port);
    int bindToAnyPort(const std::string& host);

    // Why the request this thread is answering was cut off while it was read (status 0: it was not): in its
    // head, 431 past the head's limits, 400 for a malformed line; in its body, 408 when it came too slowly
    // (below minBodyRate, no byte for the read timeout, or past the request's deadline). For the error
    // handler, which httplib calls with a plain 400, and for the routes that read their own body
    // (request_body.h).
    struct ReadRefusal {
        int status = 0;
        std::string detail;
    };
    static const ReadRefusal& readRefusal();

    // Where a connection is, for the choice of one to end when every thread is busy: waiting for a request
    // (Idle) or for the rest of its head (Head) may be ended; reading a body, answering or writing (Busy)
    // not. Written by the connection's thread without a lock (twice a request), read under connectionsMutex_.
    enum class Phase { Idle, Head, Busy };
    struct Connection {
        explicit Connection(int s) : sock(s) {}
        void enter(Phase p) {
            since.store(std::chrono::steady_clock::now().time_since_epoch().count(),
                        std::memory_order_relaxed);
            phase.store(p, std::memory_order_relaxed);
        }
        const int sock;
        std::atomic<Phase> phase{Phase::Idle};
        std::atomic<std::chrono::steady_clock::rep> since{0};  // when it entered its phase
        bool ended = false;  // shut down to free its thread (under connectionsMutex_)
    };

  private:
    // Replaces httplib's connection loop (same keep-alive rules) with one reading through DeadlineStream.
    bool process_and_close_socket(socket_t sock) override;
    // Shuts down the `n` connections that have been Idle or in their Head longest, which frees their threads;
    // fewer when the others are Busy.
    void endLongestWaiting(size_t n);
    // A connection is tracked while its thread serves it, and forgotten before its descriptor is closed, so
    // that no later connection on the same descriptor is shut down for it.
    void track(Connection& c);
    void forget(Connection& c);
    // Counts a connection against its peer's cap; false when the peer has too many.
    bool admit(const std::string& peer);
    void release(const std::string& peer);
    void raiseBacklog();

    ConnectionLimits limits_;
    std::mutex mutex_;
    std::map<std::string, size_t> perPeer_;
    std::mutex connectionsMutex_;
    std::unordered_set<Connection*> connections_;
};

}  // namespace facetlight::server
