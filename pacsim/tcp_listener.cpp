#include "tcp_listener.hpp"

#include <arpa/inet.h>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <stdexcept>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

namespace pac::pacsim {

namespace {

[[noreturn]] void Fail(const std::string& what) { throw std::runtime_error(what + ": " + std::strerror(errno)); }

}  // namespace

TcpListener::TcpListener(const std::string& address, int port) {
    const std::string where = address + ":" + std::to_string(port);
    sockaddr_in socketAddress{};
    socketAddress.sin_family = AF_INET;
    socketAddress.sin_port = htons(static_cast<std::uint16_t>(port));
    if (inet_pton(AF_INET, address.c_str(), &socketAddress.sin_addr) != 1) {
        throw std::runtime_error("pac-sim: " + address + " is not an IPv4 address");
    }
    fd_ = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd_ < 0) Fail("pac-sim: cannot open a socket for " + where);
    const int on = 1;
    setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
    socklen_t length = sizeof socketAddress;
    if (bind(fd_, reinterpret_cast<sockaddr*>(&socketAddress), sizeof socketAddress) != 0 || listen(fd_, 16) != 0 ||
        getsockname(fd_, reinterpret_cast<sockaddr*>(&socketAddress), &length) != 0) {
        const int error = errno;
        close(fd_);
        errno = error;
        Fail("pac-sim: cannot listen on " + where);
    }
    port_ = ntohs(socketAddress.sin_port);
}

TcpListener::~TcpListener() { close(fd_); }

int TcpListener::Accept() const {
    const int fd = accept4(fd_, nullptr, nullptr, SOCK_CLOEXEC | SOCK_NONBLOCK);
    if (fd >= 0) {
        const int on = 1;
        setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
    }
    return fd;
}

WakeEvent::WakeEvent() : fd_(eventfd(0, EFD_CLOEXEC)) {
    if (fd_ < 0) Fail("pac-sim: cannot make an eventfd");
}

WakeEvent::~WakeEvent() { close(fd_); }

void WakeEvent::Wake() const {
    const std::uint64_t one = 1;
    if (write(fd_, &one, sizeof one) != sizeof one) {
        // One write to a fresh eventfd cannot fail; the callers also shut their sockets down.
    }
}

}  // namespace pac::pacsim
