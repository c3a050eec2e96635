#include "modbus_gateway.hpp"

#include <algorithm>
#include <cerrno>
#include <optional>
#include <poll.h>
#include <stdexcept>
#include <sys/socket.h>
#include <unistd.h>
#include <utility>

#include <modbus/modbus.h>

#include "modbus_request.hpp"
#include "register_map.hpp"

namespace pac::pacsim {

namespace {

// A client gets this long for the rest of a frame it began (and for taking a reply) before it is disconnected.
constexpr int kFrameTimeoutMs = 500;
// Room for the largest frame libmodbus reads (MODBUS_TCP_MAX_ADU_LENGTH) and more.
constexpr std::size_t kQueryBytes = 512;
// MBAP header (Modbus Messaging on TCP/IP 3.1.3): transaction id, protocol id, length, unit id.
constexpr int kMbapLengthAt = 4;
constexpr int kMbapPrefix = 6;  // the bytes before those the length counts

// Reads and drops `count` bytes that belong to the frame libmodbus stopped reading early (a function code it
// does not know has no length of its own for libmodbus); false if they do not come in time.
bool Drain(int fd, std::size_t count) {
    std::uint8_t sink[kQueryBytes];
    while (count > 0) {
        pollfd p{fd, POLLIN, 0};
        if (poll(&p, 1, kFrameTimeoutMs) <= 0) return false;
        const ssize_t got = recv(fd, sink, count < sizeof sink ? count : sizeof sink, 0);
        if (got <= 0) return false;
        count -= static_cast<std::size_t>(got);
    }
    return true;
}

}  // namespace

struct ModbusGateway::Listener {
    int requestedPort = 0;
    std::unique_ptr<TcpListener> socket;
    std::vector<std::pair<int, std::size_t>> routes;  // unit id -> controller

    // The controller `unit` reaches; on a port of one controller also unit ids 0 and 255, the ones Modbus TCP
    // masters send to a device that is not behind a gateway.
    std::optional<std::size_t> Route(int unit) const {
        for (const auto& [id, index] : routes) {
            if (id == unit) return index;
        }
        if (routes.size() == 1 && (unit == 0 || unit == 255)) return routes.front().second;
        return std::nullopt;
    }
};

struct ModbusGateway::Client {
    Listener* listener = nullptr;
    int fd = -1;  // -1 once closed; guarded by clientsMutex_
    std::thread thread;
    std::atomic<bool> done{false};
};

// One libmodbus register table per controller, filled from its images for each request under its lock.
class ModbusGateway::Tables {
public:
    explicit Tables(const std::vector<std::unique_ptr<SimulatedController>>& controllers) {
        for (const auto& controller : controllers) {
            const int registers = controller->Map().Registers();
            modbus_mapping_t* table =
                modbus_mapping_new_start_address(0, 0, 0, 0, 0, kFromPacHoldingBase + registers, 0, registers);
            if (table == nullptr) throw std::runtime_error("pac-sim: cannot allocate a register table");
            tables_.push_back(table);
        }
    }
    ~Tables() {
        for (modbus_mapping_t* table : tables_) modbus_mapping_free(table);
    }
    Tables(const Tables&) = delete;
    Tables& operator=(const Tables&) = delete;

    modbus_mapping_t* Of(std::size_t index) const { return tables_.at(index); }

private:
    std::vector<modbus_mapping_t*> tables_;
};

ModbusGateway::ModbusGateway(std::vector<std::unique_ptr<SimulatedController>>& controllers, const WallClock& clock,
                             std::string address)
    : controllers_(controllers), clock_(clock), address_(std::move(address)), tables_(std::make_unique<Tables>(controllers)) {
    for (std::size_t i = 0; i < controllers_.size(); ++i) {
        const int port = controllers_[i]->Spec().port;
        Listener* listener = nullptr;
        for (auto& l : listeners_) {
            if (l->requestedPort == port) listener = l.get();
        }
        if (listener == nullptr) {
            listeners_.push_back(std::make_unique<Listener>());
            listener = listeners_.back().get();
            listener->requestedPort = port;
            listener->socket = std::make_unique<TcpListener>(address_, port);
        }
        listener->routes.emplace_back(controllers_[i]->Spec().unitId, i);
    }
}

ModbusGateway::~ModbusGateway() { Stop(); }

int ModbusGateway::PortOf(std::size_t index) const {
    for (const auto& listener : listeners_) {
        for (const auto& route : listener->routes) {
            if (route.second == index) return listener->socket->Port();
        }
    }
    throw std::out_of_range("ModbusGateway: no controller " + std::to_string(index));
}

void ModbusGateway::Start() { acceptor_ = std::thread([this] { AcceptLoop(); }); }

void ModbusGateway::Stop() {
    if (stopping_.exchange(true)) return;
    wake_.Wake();
    if (acceptor_.joinable()) acceptor_.join();
    {
        const std::lock_guard<std::mutex> lock(clientsMutex_);
        for (auto& client : clients_) {
            if (client->fd >= 0) shutdown(client->fd, SHUT_RDWR);
        }
    }
    Reap(true);
}

GatewayCounters ModbusGateway::Counters() const {
    return {connections_.load(), refused_.load(), requests_.load(), exceptions_.load(), dropped_.load()};
}

void ModbusGateway::AcceptLoop() {
    std::vector<pollfd> fds;
    for (const auto& listener : listeners_) fds.push_back({listener->socket->Fd(), POLLIN, 0});
    fds.push_back({wake_.Fd(), POLLIN, 0});
    while (!stopping_) {
        for (pollfd& p : fds) p.revents = 0;
        if (poll(fds.data(), fds.size(), -1) < 0) {
            if (errno == EINTR) continue;
            return;
        }
        if (fds.back().revents != 0) return;
        for (std::size_t i = 0; i < listeners_.size(); ++i) {
            if (fds[i].revents & POLLIN) Accept(*listeners_[i]);
        }
    }
}

void ModbusGateway::Accept(Listener& listener) {
    const int fd = listener.socket->Accept();
    if (fd < 0) return;  // gone before it was accepted, or out of descriptors: the next one may fare better
    Reap(false);
    const std::lock_guard<std::mutex> lock(clientsMutex_);
    if (clients_.size() >= kMaxClients) {
        close(fd);
        ++refused_;
        return;
    }
    auto client = std::make_unique<Client>();
    client->listener = &listener;
    client->fd = fd;
    Client& served = *client;
    clients_.push_back(std::move(client));
    ++connections_;
    served.thread = std::thread([this, &served] { Serve(served); });
}

void ModbusGateway::Reap(bool all) {
    std::vector<std::unique_ptr<Client>> finished;
    {
        const std::lock_guard<std::mutex> lock(clientsMutex_);
        for (auto it = clients_.begin(); it != clients_.end();) {
            if (all || (*it)->done) {
                finished.push_back(std::move(*it));
                it = clients_.erase(it);
            } else {
                ++it;
            }
        }
    }
    for (auto& client : finished) {
        if (client->thread.joinable()) client->thread.join();
    }
}

bool ModbusGateway::Answer(modbus_t* ctx, const std::uint8_t* query, int length, const Listener& listener) {
    const int header = modbus_get_header_length(ctx);
    const std::optional<std::size_t> index = listener.Route(query[header - 1]);
    RequestCheck check;
    if (!index) {
        check.exception = kGatewayPathUnavailable;
    } else {
        check = CheckRequest(query + header, static_cast<std::size_t>(length - header),
                             controllers_[*index]->Map().Registers());
    }
    if (check.exception != 0) {
        ++exceptions_;
        return modbus_reply_exception(ctx, query, static_cast<unsigned>(check.exception)) >= 0;
    }
    SimulatedController& controller = *controllers_[*index];
    modbus_mapping_t* table = tables_->Of(*index);
    const auto lock = controller.Lock();
    const auto now = clock_.Now();
    controller.CatchUp(now);
    const std::vector<std::uint16_t> toPac = controller.ToPacRegisters();
    const std::vector<std::uint16_t> fromPac = controller.FromPacRegisters();
    std::copy(toPac.begin(), toPac.end(), table->tab_registers);
    std::copy(fromPac.begin(), fromPac.end(), table->tab_registers + kFromPacHoldingBase);
    std::copy(fromPac.begin(), fromPac.end(), table->tab_input_registers);
    // A non-blocking socket: a client that does not take its replies is dropped, it never holds the lock.
    const int sent = modbus_reply(ctx, query, length, table);
    if (check.writeCount > 0) {
        // Applied even when the reply could not go out: the request arrived whole.
        const std::uint16_t* written = table->tab_registers + check.writeFirst;
        controller.WriteToPac(now, check.writeFirst, std::vector<std::uint16_t>(written, written + check.writeCount));
    }
    return sent >= 0;
}

void ModbusGateway::Serve(Client& client) {
    modbus_t* ctx = modbus_new_tcp(nullptr, 0);  // a context for libmodbus's TCP framing; the socket is ours
    const int fd = client.fd;
    bool open = ctx != nullptr && modbus_set_socket(ctx, fd) == 0;
    if (open) {
        modbus_set_byte_timeout(ctx, 0, kFrameTimeoutMs * 1000);
        modbus_set_indication_timeout(ctx, 0, kFrameTimeoutMs * 1000);
    }
    std::uint8_t query[kQueryBytes];
    while (open && !stopping_) {
        pollfd fds[2] = {{fd, POLLIN, 0}, {wake_.Fd(), POLLIN, 0}};
        if (poll(fds, 2, -1) < 0) {
            if (errno == EINTR) continue;
            break;
        }
        if (fds[1].revents != 0) break;
        const int length = modbus_receive(ctx, query);
        if (length == 0) continue;  // libmodbus: not for this server (never over TCP)
        if (length < 0) {
            if (errno != ECONNRESET) ++dropped_;  // a frame libmodbus cannot read, or one left unfinished
            break;
        }
        ++requests_;
        // The MBAP length counts the unit id and the PDU: the rest of a frame libmodbus read no further than its
        // function code is dropped. A frame that is not a Modbus request ends the link: a protocol id other than
        // 0, a length shorter than what was read, or a function code of 128 or more (those are exception
        // responses; libmodbus would answer one with function code 127, which a client takes for a reply).
        const std::size_t framed = static_cast<std::size_t>(query[kMbapLengthAt] << 8 | query[kMbapLengthAt + 1]);
        const std::size_t read = static_cast<std::size_t>(length - kMbapPrefix);
        const bool request = query[2] == 0 && query[3] == 0 && framed >= read && query[kMbapPrefix + 1] < 0x80;
        if (!request || (framed > read && !Drain(fd, framed - read))) {
            ++dropped_;
            break;
        }
        if (!Answer(ctx, query, length, *client.listener)) {
            ++dropped_;
            break;
        }
    }
    if (ctx != nullptr) {
        modbus_set_socket(ctx, -1);
        modbus_free(ctx);
    }
    {
        const std::lock_guard<std::mutex> lock(clientsMutex_);
        close(fd);
        client.fd = -1;
    }
    client.done = true;
}

}  // namespace pac::pacsim
