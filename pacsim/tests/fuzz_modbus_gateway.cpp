// Fuzz target of pac-sim's Modbus gateway: the fuzzer's bytes are what one client sends over loopback TCP to a
// gateway in front of one simulated PA-CONTROL (CMD, CTRL, two axis modules), then it closes its side. What comes
// back must be well-formed Modbus TCP replies (protocol id 0, a length that fits, a served function code or an
// exception pac-sim documents), and a client after it must be served: nothing a client sends takes the server
// down. With PAC_FUZZ a libFuzzer program; otherwise tests/fuzz/replay_main.cpp replays the corpus under ctest.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include "modbus_gateway.hpp"
#include "modbus_request.hpp"
#include "sim_config.hpp"
#include "simulated_controller.hpp"
#include "wall_clock.hpp"

namespace {

using Bytes = std::vector<std::uint8_t>;

[[noreturn]] void Broken(const char* invariant) {
    std::fprintf(stderr, "fuzz_modbus_gateway: %s\n", invariant);
    std::abort();
}

// The gateway, made once for the whole run: a server lives across its clients, and so do its faults.
class Server {
public:
    Server() {
        const auto config = pac::pacsim::SimConfigLoader::FromText(
            R"({"port": 0, "controllers": [{"modules": {"ctrl": true, "axes": 2}}]})");
        controllers_.push_back(std::make_unique<pac::pacsim::SimulatedController>(config.controllers.at(0)));
        gateway_ = std::make_unique<pac::pacsim::ModbusGateway>(controllers_, clock_, "127.0.0.1");
        gateway_->Start();
    }

    // Sends `bytes` on a new connection, closes its sending side and returns all the server sent back.
    Bytes Exchange(const std::uint8_t* bytes, std::size_t size) const {
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        address.sin_port = htons(static_cast<std::uint16_t>(gateway_->PortOf(0)));
        // Two clients an input, thousands a second: the machine's own limits (its ephemeral ports, the listen
        // queue) may refuse one for a moment; a server that takes none for a second is broken.
        int fd = -1;
        for (int attempt = 0; fd < 0; ++attempt) {
            fd = socket(AF_INET, SOCK_STREAM, 0);
            if (fd >= 0 && connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) break;
            const int error = errno;
            if (fd >= 0) close(fd);
            fd = -1;
            if (attempt == 100) {
                std::fprintf(stderr, "fuzz_modbus_gateway: connect: %s\n", std::strerror(error));
                Broken("the server takes no client");
            }
            usleep(10000);
        }
        for (std::size_t sent = 0; sent < size;) {
            const ssize_t n = send(fd, bytes + sent, size - sent, MSG_NOSIGNAL);
            if (n <= 0) break;  // the server closed the connection on a frame it could not read
            sent += static_cast<std::size_t>(n);
        }
        shutdown(fd, SHUT_WR);
        Bytes reply;
        std::uint8_t buffer[4096];
        pollfd p{fd, POLLIN, 0};
        while (poll(&p, 1, 5000) > 0) {
            const ssize_t n = recv(fd, buffer, sizeof buffer, 0);
            if (n <= 0) break;
            reply.insert(reply.end(), buffer, buffer + n);
        }
        close(fd);
        return reply;
    }

private:
    pac::pacsim::WallClock clock_;
    std::vector<std::unique_ptr<pac::pacsim::SimulatedController>> controllers_;
    std::unique_ptr<pac::pacsim::ModbusGateway> gateway_;
};

// Every reply in `stream` is a Modbus TCP frame pac-sim may send.
void CheckReplies(const Bytes& stream) {
    std::size_t at = 0;
    while (at < stream.size()) {
        if (stream.size() - at < 9) Broken("a reply shorter than an MBAP header and a function code");
        if (stream[at + 2] != 0 || stream[at + 3] != 0) Broken("a reply with a protocol id other than 0");
        const std::size_t length = static_cast<std::size_t>(stream[at + 4] << 8 | stream[at + 5]);
        if (length < 3 || at + 6 + length > stream.size()) Broken("a reply whose length does not fit");
        const int function = stream[at + 7];
        if (function & 0x80) {
            const int exception = stream[at + 8];
            if (length != 3 || (exception != pac::pacsim::kIllegalFunction && exception != pac::pacsim::kIllegalDataAddress &&
                                exception != pac::pacsim::kIllegalDataValue &&
                                exception != pac::pacsim::kGatewayPathUnavailable)) {
                Broken("an exception pac-sim does not document");
            }
        } else if (function != 3 && function != 4 && function != 6 && function != 16 && function != 23) {
            Broken("a reply to a function code pac-sim does not serve");
        }
        at += 6 + length;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const Server server;  // libFuzzer calls this function once per input: the server outlives them
    CheckReplies(server.Exchange(data, size));
    // Read input registers 0..3 of unit 1: a well-formed request, answered whatever came before. A client is
    // closed at once while 32 are connected, and the server may not have seen the last ones leave yet: a few tries.
    const std::uint8_t read[] = {0, 1, 0, 0, 0, 6, 1, 4, 0, 0, 0, 4};
    for (int attempt = 0; attempt < 100; ++attempt) {
        const Bytes reply = server.Exchange(read, sizeof read);
        if (reply.size() == 17 && reply[7] == 4 && reply[8] == 8) return 0;
        if (!reply.empty()) Broken("a well-formed read after it is answered wrongly");
        usleep(10000);
    }
    Broken("a client after it is not served");
}
