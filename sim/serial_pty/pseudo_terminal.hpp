// A pseudo-terminal (POSIX openpt): the simulated PA-CONTROL holds the master side, a real client (a
// terminal program, pyserial, a PLC runtime on the same machine) opens the slave side like a serial port.
// The slave is set to raw mode and held open here too, so the master never sees a hang-up while no client
// has it open. Not copyable; closes both sides (and removes the link) when destroyed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pac::sim {

class PseudoTerminal {
public:
    // `link`: a symbolic link to the slave's path to create (replacing an old link there), or empty.
    // std::runtime_error when the system refuses.
    explicit PseudoTerminal(const std::string& link = {});
    ~PseudoTerminal();
    PseudoTerminal(const PseudoTerminal&) = delete;
    PseudoTerminal& operator=(const PseudoTerminal&) = delete;

    const std::string& SlavePath() const { return slavePath_; }
    // Waits at most timeoutMs for bytes from the client and returns those there are (maybe none).
    std::vector<std::uint8_t> Read(int timeoutMs);
    void Write(const std::vector<std::uint8_t>& bytes);

private:
    int master_ = -1;
    int slave_ = -1;
    std::string slavePath_;
    std::string link_;
};

}  // namespace pac::sim
