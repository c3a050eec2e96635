// A listening TCP socket on an IPv4 address, for the Modbus gateway and the RS232 bridge.
#pragma once

#include <string>

namespace pac::pacsim {

class TcpListener {
public:
    // Listens on `address`:`port` (0: a free port chosen by the system); std::runtime_error naming both when it
    // cannot (not an IPv4 address, the port taken, ...).
    TcpListener(const std::string& address, int port);
    ~TcpListener();
    TcpListener(const TcpListener&) = delete;
    TcpListener& operator=(const TcpListener&) = delete;

    int Fd() const { return fd_; }
    int Port() const { return port_; }  // the port bound
    // The next client, non-blocking, with Nagle off (replies go out at once); -1 if none could be accepted.
    int Accept() const;

private:
    int fd_ = -1;
    int port_ = 0;
};

// An eventfd that Stop() writes once to wake every poll() of the threads, which then return.
class WakeEvent {
public:
    WakeEvent();
    ~WakeEvent();
    WakeEvent(const WakeEvent&) = delete;
    WakeEvent& operator=(const WakeEvent&) = delete;

    int Fd() const { return fd_; }
    void Wake() const;

private:
    int fd_ = -1;
};

}  // namespace pac::pacsim
