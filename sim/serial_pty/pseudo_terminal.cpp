// The pseudo-terminal of pac_sim --serial (see pseudo_terminal.hpp).
#include "pseudo_terminal.hpp"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace pac::sim {

namespace {

[[noreturn]] void Fail(const std::string& what) {
    throw std::runtime_error("pseudo-terminal: " + what + ": " + std::strerror(errno));
}

}  // namespace

PseudoTerminal::PseudoTerminal(const std::string& link) : link_(link) {
    master_ = posix_openpt(O_RDWR | O_NOCTTY);
    if (master_ < 0) Fail("posix_openpt");
    if (grantpt(master_) != 0 || unlockpt(master_) != 0) Fail("grantpt/unlockpt");
    const char* name = ptsname(master_);
    if (name == nullptr) Fail("ptsname");
    slavePath_ = name;
    slave_ = open(slavePath_.c_str(), O_RDWR | O_NOCTTY);
    if (slave_ < 0) Fail("open " + slavePath_);
    // Raw: no echo, no line editing, no CR/LF translation: the protocol's control symbols pass untouched.
    termios raw{};
    if (tcgetattr(slave_, &raw) != 0) Fail("tcgetattr");
    cfmakeraw(&raw);
    if (tcsetattr(slave_, TCSANOW, &raw) != 0) Fail("tcsetattr");
    const int flags = fcntl(master_, F_GETFL);
    if (flags < 0 || fcntl(master_, F_SETFL, flags | O_NONBLOCK) != 0) Fail("fcntl");
    if (!link_.empty()) {
        unlink(link_.c_str());
        if (symlink(slavePath_.c_str(), link_.c_str()) != 0) Fail("symlink " + link_);
    }
}

PseudoTerminal::~PseudoTerminal() {
    if (!link_.empty()) unlink(link_.c_str());
    if (slave_ >= 0) close(slave_);
    if (master_ >= 0) close(master_);
}

std::vector<std::uint8_t> PseudoTerminal::Read(int timeoutMs) {
    std::vector<std::uint8_t> bytes;
    pollfd p{master_, POLLIN, 0};
    if (poll(&p, 1, timeoutMs) <= 0 || (p.revents & POLLIN) == 0) return bytes;
    std::uint8_t buffer[256];
    for (;;) {
        const ssize_t n = read(master_, buffer, sizeof buffer);
        if (n <= 0) break;
        bytes.insert(bytes.end(), buffer, buffer + n);
    }
    return bytes;
}

void PseudoTerminal::Write(const std::vector<std::uint8_t>& bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = write(master_, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno != EAGAIN && errno != EINTR) Fail("write");
        if (n > 0) done += static_cast<std::size_t>(n);
    }
}

}  // namespace pac::sim
