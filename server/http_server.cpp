#include "http_server.h"

#include <arpa/inet.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <functional>
#include <thread>
#include <vector>

namespace facetlight::server {

namespace {

using Clock = std::chrono::steady_clock;

// Set while a response is written that must end its connection. httplib 0.11 writes "Connection: close" but
// goes on reading: the unread body of a refused request would be taken for the next request.
thread_local bool closeAfterResponse = false;
// Set when the request's head passed its limits (ConnectionLimits::maxHeadBytes, maxHeaderLines) or its body
// came too slowly.
thread_local HttpServer::ReadRefusal readRefused;

// Threads added while every one is busy, up to a cap; they stay until shutdown. A connection that finds every
// thread busy at the cap calls `saturated` with the number of connections waiting for a thread: each is
// served in turn, so as many threads must be freed for the newest to be served.
class GrowingThreadPool : public httplib::TaskQueue {
  public:
    GrowingThreadPool(size_t threads, size_t maxThreads, std::function<void(size_t)> saturated)
        : maxThreads_(std::max(threads, maxThreads)), saturated_(std::move(saturated)) {
        std::lock_guard lock(mutex_);
        for (size_t i = 0; i < threads; ++i) addThread();
    }

    void enqueue(std::function<void()> fn) override {
        size_t waiting = 0;  // connections without a thread, beyond the idle ones, at the cap
        {
            std::lock_guard lock(mutex_);
            jobs_.push_back(std::move(fn));
            if (idle_ < jobs_.size()) {
                if (threads_.size() < maxThreads_)
                    addThread();
                else
                    waiting = jobs_.size() - idle_;
            }
        }
        cond_.notify_one();
        if (waiting > 0) saturated_(waiting);
    }

    void shutdown() override {
        {
            std::lock_guard lock(mutex_);
            stopping_ = true;
        }
        cond_.notify_all();
        for (auto& t : threads_) t.join();  // no thread is added once stopping_ is set
    }

  private:
    void addThread() {
        threads_.emplace_back([this] {
            for (;;) {
                std::function<void()> fn;
                {
                    std::unique_lock lock(mutex_);
                    ++idle_;
                    cond_.wait(lock, [&] { return stopping_ || !jobs_.empty(); });
                    --idle_;
                    if (jobs_.empty()) return;  // stopping, nothing left
                    fn = std::move(jobs_.front());
                    jobs_.pop_front();
                }
                fn();
            }
        });
    }

    const size_t maxThreads_;
    const std::function<void(size_t)> saturated_;
    std::mutex mutex_;
    std::condition_variable cond_;
    std::deque<std::function<void()>> jobs_;
    std::vector<std::thread> threads_;
    size_t idle_ = 0;
    bool stopping_ = false;
};

// Rounded up: a poll() that wakes before its deadline would take it for another (DeadlineStream::slowBody).
int millisecondsUntil(Clock::time_point deadline) {
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now()).count();
    return int(std::clamp<long long>(left, 0, 1 << 30));
}

// Waits until `sock` is ready for `events` or the deadline passes.
bool waitFor(int sock, short events, Clock::time_point deadline) {
    pollfd p{sock, events, 0};
    for (;;) {
        const int n = ::poll(&p, 1, millisecondsUntil(deadline));
        if (n > 0) return (p.revents & (events | POLLHUP | POLLERR)) != 0;
        if (n == 0 || errno != EINTR) return false;
    }
}

std::string wholeSeconds(Clock::duration d) {
    return std::to_string(std::chrono::duration_cast<std::chrono::seconds>(d).count());
}

std::string peerAddress(int sock, int& port, bool local) {
    sockaddr_storage addr{};
    socklen_t len = sizeof addr;
    const int rc = local ? ::getsockname(sock, reinterpret_cast<sockaddr*>(&addr), &len)
                         : ::getpeername(sock, reinterpret_cast<sockaddr*>(&addr), &len);
    char host[NI_MAXHOST] = "", service[NI_MAXSERV] = "";
    if (rc != 0 || ::getnameinfo(reinterpret_cast<sockaddr*>(&addr), len, host, sizeof host, service,
                                 sizeof service, NI_NUMERICHOST | NI_NUMERICSERV) != 0)
        return {};
    port = std::atoi(service);
    return host;
}

// httplib's SocketStream with a deadline for the request: reads wait for the sooner of the read timeout and
// the deadline, so a request trickling in byte by byte ends when the deadline passes. Once the head has
// arrived, the body's bytes must also keep up with ConnectionLimits::minBodyRate: a read waits no longer than
// until the body falls behind it.
class DeadlineStream : public httplib::Stream {
  public:
    DeadlineStream(HttpServer::Connection& connection, int sock, std::string peer, int peerPort,
                   std::chrono::microseconds readTimeout, std::chrono::microseconds writeTimeout,
                   const ConnectionLimits& limits)
        : connection_(connection),
          sock_(sock),
          peer_(std::move(peer)),
          peerPort_(peerPort),
          readTimeout_(readTimeout),
          writeTimeout_(writeTimeout),
          limits_(limits) {
        local_ = peerAddress(sock, localPort_, true);
    }

    void startRequest(Clock::time_point deadline) {
        deadline_ = deadline;
        inHead_ = true, lineEmpty_ = false, sawColon_ = false, headBytes_ = 0, headLines_ = 0;
        bodyBytes_ = 0, timedOut_ = false;
        readRefused = {};
    }

    bool is_readable() const override {
        const auto now = Clock::now(), until = readDeadline();
        return now < until && waitFor(sock_, POLLIN, std::min(until, now + readTimeout_));
    }
    bool is_writable() const override { return waitFor(sock_, POLLOUT, Clock::now() + writeTimeout_); }

    // A head past its limits or with a malformed line, and a body that stopped coming or came too slowly,
    // read as the end of the connection: httplib answers 400 (a route reading its own body sees it stop
    // short), which the error handler (or the route) makes the refusal's problem.
    ssize_t read(char* ptr, size_t size) override {
        const bool inBody = !inHead_;
        const ssize_t n = readBytes(ptr, size);
        if (n > 0 && inBody) bodyBytes_ += size_t(n);
        if (n > 0 && !inBody) readRefused = checkHead(ptr, size_t(n));
        if (n < 0 && inBody && timedOut_) readRefused = slowBody();
        if (readRefused.status == 0) return n;
        closeAfterResponse = true;
        return -1;
    }

    // Bytes already there are taken without a poll() first: one system call less per request.
    ssize_t readBytes(char* ptr, size_t size) {
        if (bufferBegin_ == bufferEnd_) {
            char* into = size < sizeof buffer_ ? buffer_ : ptr;
            const size_t most = size < sizeof buffer_ ? sizeof buffer_ : size;
            timedOut_ = Clock::now() >= deadline_;
            if (timedOut_) return -1;
            ssize_t n = recvRetrying(into, most, MSG_DONTWAIT);
            if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
                timedOut_ = !is_readable();
                if (timedOut_) return -1;
                n = recvRetrying(into, most, 0);
            }
            if (n <= 0 || size >= sizeof buffer_) return n;
            bufferBegin_ = 0, bufferEnd_ = size_t(n);
        }
        const size_t n = std::min(size, bufferEnd_ - bufferBegin_);
        std::memcpy(ptr, buffer_ + bufferBegin_, n);
        bufferBegin_ += n;
        return ssize_t(n);
    }

    // Likewise, a poll() only when the socket's buffer is full.
    ssize_t write(const char* ptr, size_t size) override {
        for (;;) {
            const ssize_t n = ::send(sock_, ptr, size, MSG_NOSIGNAL | MSG_DONTWAIT);
            if (n >= 0) return n;
            if (errno == EINTR) continue;
            if ((errno != EAGAIN && errno != EWOULDBLOCK) || !is_writable()) return -1;
        }
    }

    // Known when the connection was accepted: no getpeername() per request.
    void get_remote_ip_and_port(std::string& ip, int& port) const override {
        ip = peer_;
        port = peerPort_;
    }
    void get_local_ip_and_port(std::string& ip, int& port) const override {
        ip = local_;
        port = localPort_;
    }
    socket_t socket() const override { return sock_; }

    bool hasBufferedBytes() const { return bufferBegin_ < bufferEnd_; }

  private:
    // The body must have brought minBodyRate bytes a second since its grace period ended: with b bytes so
    // far it falls behind at bodyStart + grace + b / rate.
    Clock::time_point rateDeadline() const {
        const auto behind = std::chrono::duration<double>(double(bodyBytes_) / double(limits_.minBodyRate));
        return bodyStart_ + limits_.bodyGrace + std::chrono::duration_cast<Clock::duration>(behind);
    }
    Clock::time_point readDeadline() const {
        return inHead_ || limits_.minBodyRate == 0 ? deadline_ : std::min(deadline_, rateDeadline());
    }

    // Why a read of the body timed out: the request's deadline, the rate, or the read timeout (no byte).
    HttpServer::ReadRefusal slowBody() const {
        const auto now = Clock::now();
        if (now >= deadline_)
            return {408, "the request took longer than " + wholeSeconds(limits_.requestTimeout) +
                             " s to arrive (--request-timeout)"};
        if (limits_.minBodyRate > 0 && now >= rateDeadline())
            return {408, "the body came slower than " + std::to_string(limits_.minBodyRate) +
                             " bytes/s (--min-body-rate): " + std::to_string(bodyBytes_) + " bytes in " +
                             wholeSeconds(now - bodyStart_) + " s"};
        return {408, "the body stopped coming: no byte for " + wholeSeconds(readTimeout_) + " s"};
    }

    // Reads the head's bytes as they come, until the empty line that ends it: its size and lines within the
    // limits, and header lines httplib 0.11 would take or drop silently refused (issue 31): a NUL byte, a
    // line without a colon, white space before the colon (e.g. "Transfer-Encoding : chunked", which a proxy
    // in front may read as chunked while httplib does not).
    HttpServer::ReadRefusal checkHead(const char* p, size_t n) {
        for (size_t i = 0; i < n && inHead_; ++i) {
            ++headBytes_;
            const char c = p[i];
            const bool headerLine = headLines_ > 0;  // the request line is no header line
            if (c == '\0') return {400, "the request's head holds a NUL byte"};
            if (c == '\n') {
                if (headerLine && !lineEmpty_ && !sawColon_)
                    return {400, "header line " + std::to_string(headLines_) + " has no colon"};
                ++headLines_;
                inHead_ = !lineEmpty_;
                if (!inHead_) {
                    connection_.enter(HttpServer::Phase::Busy);
                    bodyStart_ = Clock::now();
                }
                lineEmpty_ = true, sawColon_ = false;
                continue;
            }
            if (headerLine && !sawColon_ && (c == ' ' || c == '\t'))
                return {400, "header line " + std::to_string(headLines_) + " has white space in its name"};
            sawColon_ = sawColon_ || c == ':';
            if (c != '\r') lineEmpty_ = false;
        }
        // The request line and the empty line are no header lines.
        if (headBytes_ > limits_.maxHeadBytes || headLines_ > limits_.maxHeaderLines + 2)
            return {431, "the request's head is larger than " + std::to_string(limits_.maxHeadBytes) +
                             " bytes or " + std::to_string(limits_.maxHeaderLines) + " header lines"};
        return {};
    }

    ssize_t recvRetrying(char* ptr, size_t size, int flags) {
        for (;;) {
            const ssize_t n = ::recv(sock_, ptr, size, flags);
            if (n >= 0 || errno != EINTR) return n;
        }
    }

    HttpServer::Connection& connection_;
    const int sock_;
    const std::string peer_;
    const int peerPort_;
    std::string local_;
    int localPort_ = 0;
    const std::chrono::microseconds readTimeout_, writeTimeout_;
    const ConnectionLimits& limits_;
    Clock::time_point deadline_ = Clock::time_point::max();
    bool inHead_ = true, lineEmpty_ = false, sawColon_ = false;
    size_t headBytes_ = 0, headLines_ = 0;
    Clock::time_point bodyStart_;
    size_t bodyBytes_ = 0;
    bool timedOut_ = false;  // the last read failed on a deadline or the read timeout
    char buffer_[4096];
    size_t bufferBegin_ = 0, bufferEnd_ = 0;
};

void sendTooManyConnections(int sock, size_t limit) {
    const std::string body =
        "{\"type\":\"about:blank\",\"title\":\"Too Many Requests\",\"status\":429,\"detail\":\"too many "
        "connections from your address at once (the limit is " +
        std::to_string(limit) + ")\"}";
    const std::string response =
        "HTTP/1.1 429 Too Many Requests\r\nContent-Type: application/problem+json\r\n"
        "Retry-After: 1\r\nConnection: close\r\nContent-Length: " +
        std::to_string(body.size()) + "\r\n\r\n" + body;
    [[maybe_unused]] const ssize_t sent =
        ::send(sock, response.data(), response.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
}

}  // namespace

HttpServer::HttpServer(const ConnectionLimits& limits) : limits_(limits) {
    const size_t threads = std::max<size_t>(1, limits.threads), maxThreads = limits.maxThreads;
    new_task_queue = [this, threads, maxThreads] {
        return new GrowingThreadPool(threads, maxThreads, [this](size_t n) { endLongestWaiting(n); });
    };
    set_keep_alive_max_count(std::max<size_t>(1, limits.keepAliveRequests));
    // 400, 413 and 414 also come from httplib's own parser, which leaves the rest of the request unread.
    // A refused read (a slow body's 408) has set it already.
    set_post_routing_handler([](const httplib::Request&, httplib::Response& res) {
        closeAfterResponse = closeAfterResponse || res.get_header_value("Connection") == "close" ||
                             res.status == 400 || res.status == 413 || res.status == 414;
    });
}

const HttpServer::ReadRefusal& HttpServer::readRefusal() {
    return readRefused;
}

bool HttpServer::bind(const std::string& host, int port) {
    if (!bind_to_port(host, port)) return false;
    raiseBacklog();
    return true;
}

int HttpServer::bindToAnyPort(const std::string& host) {
    const int port = bind_to_any_port(host);
    if (port > 0) raiseBacklog();
    return port;
}

// httplib listens with a backlog of 5: 200 clients connecting at once saw resets. listen() again on a
// listening socket only changes its backlog (Linux).
void HttpServer::raiseBacklog() {
    ::listen(svr_sock_, limits_.backlog);
}

bool HttpServer::admit(const std::string& peer) {
    std::lock_guard lock(mutex_);
    size_t& open = perPeer_[peer];
    if (open >= limits_.maxPerPeer) return false;
    ++open;
    return true;
}

void HttpServer::release(const std::string& peer) {
    std::lock_guard lock(mutex_);
    if (--perPeer_[peer] == 0) perPeer_.erase(peer);
}

void HttpServer::track(Connection& c) {
    std::lock_guard lock(connectionsMutex_);
    connections_.insert(&c);
}

void HttpServer::forget(Connection& c) {
    std::lock_guard lock(connectionsMutex_);
    connections_.erase(&c);
}

void HttpServer::endLongestWaiting(size_t n) {
    std::lock_guard lock(connectionsMutex_);
    std::vector<std::pair<Clock::rep, Connection*>> waiting;
    for (Connection* c : connections_)
        if (!c->ended && c->phase.load(std::memory_order_relaxed) != Phase::Busy)
            waiting.emplace_back(c->since.load(std::memory_order_relaxed), c);
    n = std::min(n, waiting.size());
    std::partial_sort(waiting.begin(), waiting.begin() + ptrdiff_t(n), waiting.end());
    for (size_t i = 0; i < n; ++i) {
        // Its thread's poll() or recv() sees the end at once and closes the connection. The descriptor is
        // still open: its thread forgets it before closing it.
        ::shutdown(waiting[i].second->sock, SHUT_RDWR);
        waiting[i].second->ended = true;
    }
}

// The keep-alive loop of httplib 0.11's process_server_socket, with each request's deadline set when its
// first byte is there.
bool HttpServer::process_and_close_socket(socket_t sock) {
    int port = 0;
    const std::string peer = peerAddress(sock, port, false);
    bool ok = false;
    Connection connection(sock);
    if (admit(peer)) {
        connection.enter(Phase::Idle);
        track(connection);
        DeadlineStream stream(
            connection, sock, peer, port,
            std::chrono::seconds(read_timeout_sec_) + std::chrono::microseconds(read_timeout_usec_),
            std::chrono::seconds(write_timeout_sec_) + std::chrono::microseconds(write_timeout_usec_),
            limits_);
        for (size_t left = keep_alive_max_count_; left > 0 && svr_sock_ != INVALID_SOCKET; --left) {
            connection.enter(Phase::Idle);
            if (!stream.hasBufferedBytes() &&
                !waitFor(sock, POLLIN, Clock::now() + std::chrono::seconds(keep_alive_timeout_sec_)))
                break;
            connection.enter(Phase::Head);
            stream.startRequest(Clock::now() + limits_.requestTimeout);
            bool closed = false;
            closeAfterResponse = false;
            ok = process_request(stream, left == 1, closed, nullptr);
            if (!ok || closed || closeAfterResponse) break;
        }
        release(peer);
    } else {
        sendTooManyConnections(sock, limits_.maxPerPeer);
    }
    forget(connection);
    ::shutdown(sock, SHUT_RDWR);
    ::close(sock);
    return ok;
}

}  // namespace facetlight::server
