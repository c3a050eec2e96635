#include "tcp_serial_bridge.hpp"

#include <cerrno>
#include <cstdint>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>
#include <vector>

namespace pac::pacsim {

namespace {

// How often the bridge looks at the line while a client is connected: a byte at 115200 baud takes 87 us,
// a reply of the manual's length a few ms at 9600 baud.
constexpr int kRelayPeriodMs = 1;

// Whether the peer of `fd` has closed its end (its bytes still unread do not count).
bool Gone(int fd) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, 0) <= 0) return false;
    if (p.revents & (POLLHUP | POLLERR)) return true;
    std::uint8_t byte;
    return recv(fd, &byte, 1, MSG_PEEK | MSG_DONTWAIT) == 0;
}

}  // namespace

TcpSerialBridge::TcpSerialBridge(SimulatedController& controller, const WallClock& clock, const std::string& address,
                           int port)
    : controller_(controller), clock_(clock), address_(address), listener_(address, port) {}

std::string TcpSerialBridge::Where() const { return "raw TCP " + address_ + ":" + std::to_string(Port()); }

TcpSerialBridge::~TcpSerialBridge() { Stop(); }

void TcpSerialBridge::Start() { thread_ = std::thread([this] { Run(); }); }

void TcpSerialBridge::Stop() {
    if (stopping_.exchange(true)) return;
    wake_.Wake();
    if (thread_.joinable()) thread_.join();
}

void TcpSerialBridge::Run() {
    int client = -1;
    while (!stopping_) {
        pollfd fds[3] = {{listener_.Fd(), POLLIN, 0}, {wake_.Fd(), POLLIN, 0}, {client, POLLIN, 0}};
        const int ready = poll(fds, client >= 0 ? 3 : 2, client >= 0 ? kRelayPeriodMs : -1);
        if (ready < 0 && errno != EINTR) break;
        if (fds[1].revents != 0) break;
        // The client first: one that has just gone makes room for the one that connects after it.
        if (client >= 0 && !Relay(client, (fds[2].revents & (POLLIN | POLLHUP | POLLERR)) != 0)) {
            close(client);
            client = -1;
        }
        if (fds[0].revents & POLLIN) {
            const int next = listener_.Accept();
            if (client >= 0 && next >= 0 && Gone(client)) {
                close(client);
                client = -1;
            }
            if (client < 0) {
                client = next;
            } else if (next >= 0) {
                close(next);  // the line has its peer
            }
        }
    }
    if (client >= 0) close(client);
}

bool TcpSerialBridge::Relay(int client, bool readable) {
    std::vector<std::uint8_t> received;
    if (readable) {
        std::uint8_t buffer[4096];
        const ssize_t got = recv(client, buffer, sizeof buffer, 0);
        if (got == 0 || (got < 0 && errno != EAGAIN && errno != EINTR)) return false;
        if (got > 0) received.assign(buffer, buffer + got);
    }
    const std::vector<std::uint8_t> reply = RelaySerial(controller_, clock_, received);
    // A client that does not take what the line sends it is disconnected, as a buffer that overflows.
    return reply.empty() ||
           send(client, reply.data(), reply.size(), MSG_NOSIGNAL | MSG_DONTWAIT) == static_cast<ssize_t>(reply.size());
}

}  // namespace pac::pacsim
