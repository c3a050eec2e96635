// A PLC wired to a simulated PA-CONTROL over RS232 (manual 3): simulated clock, PLC task, the controller at
// its own cycle with its COM1 on a SerialLine, and the PLC's serial driver, which each scan moves the bytes
// that have arrived into an FB's receive ring buffer before the FB runs and sends what the FB left in its
// transmit ring buffer after it (the job of Tc2_SerialCom's SerialLineControl or CODESYS's COM.Read /
// COM.Write, docs/fb/FB_PAC_Rs232Cmd.md). The buffers are the FB's TxBuffer / RxBuffer in-outs, shaped like
// T_PAC_ComBuffer; the driver keeps to its ring rules (300 bytes in Buffer[0..299]).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "pac/fb_instance.hpp"
#include "pac/plc_task.hpp"
#include "pac/sim/bus.hpp"
#include "pac/sim/pa_control.hpp"
#include "pac/sim/pac_runner.hpp"
#include "pac/sim/serial_line.hpp"
#include "pac/sim/serial_port.hpp"
#include "pac/sim_clock.hpp"

namespace pac {

// The ring rules of T_PAC_ComBuffer on its generated C struct.
namespace com_ring {
constexpr int kCapacity = 300;

template <class Ring>
bool Put(Ring& ring, std::uint8_t byte) {
    if (ring.COUNT < 0 || ring.COUNT >= kCapacity || ring.WRIDX < 0 || ring.WRIDX >= kCapacity) return false;
    ring.BUFFER.table[ring.WRIDX] = byte;
    ring.WRIDX = static_cast<decltype(ring.WRIDX)>((ring.WRIDX + 1) % kCapacity);
    ++ring.COUNT;
    ring.FREEBYTE = static_cast<decltype(ring.FREEBYTE)>(kCapacity - ring.COUNT);
    return true;
}

template <class Ring>
std::vector<std::uint8_t> TakeAll(Ring& ring) {
    std::vector<std::uint8_t> bytes;
    while (ring.COUNT > 0 && ring.RDIDX >= 0 && ring.RDIDX < kCapacity) {
        bytes.push_back(ring.BUFFER.table[ring.RDIDX]);
        ring.RDIDX = static_cast<decltype(ring.RDIDX)>((ring.RDIDX + 1) % kCapacity);
        --ring.COUNT;
    }
    ring.FREEBYTE = static_cast<decltype(ring.FREEBYTE)>(kCapacity - ring.COUNT);
    return bytes;
}
}  // namespace com_ring

struct SerialRigTiming {
    std::chrono::nanoseconds plcCycle{std::chrono::milliseconds(1)};
    std::chrono::nanoseconds pacCycle{std::chrono::milliseconds(10)};
    std::chrono::nanoseconds pacPhase{0};  // the controller's first cycle
    pac::sim::SerialFormat format{};
    std::chrono::nanoseconds bootTime{0};
    std::uint64_t seed = 1;
};

class SerialRig {
public:
    explicit SerialRig(SerialRigTiming timing = {}, pac::sim::PaControlConfig config = {},
                            pac::sim::SerialPortConfig port = {});

    // Registers `fb` with its TxBuffer / RxBuffer on the line, after the programs registered before.
    template <class Fb>
    void Call(pac::FbInstance<Fb>& fb, std::function<void()> before = {}) {
        CallWhen(fb, [before] {
            if (before) before();
            return true;
        });
    }
    // As Call, for a program that leaves the FB out in some scans (a CASE step, an IF branch): the driver
    // moves the bytes in every scan, the FB runs when `calls` says so, and `after` sees what a call left.
    template <class Fb>
    void CallWhen(pac::FbInstance<Fb>& fb, std::function<bool()> calls, std::function<void()> after = {}) {
        task_.AddProgram([this, &fb, calls, after] {
            const bool called = calls();
            for (std::uint8_t byte : line_.fromPac.Receive(clock_.Now())) {
                if (!com_ring::Put(fb->RXBUFFER.value, byte)) ++overruns_;
            }
            // A driver in a faster task holds a buffer (Blocked) while the FB runs in the scans it says.
            fb->RXBUFFER.value.BLOCKED = rxHeld_ && rxHeld_() ? 1 : 0;
            fb->TXBUFFER.value.BLOCKED = txHeld_ && txHeld_() ? 1 : 0;
            if (called) {
                fb();
                if (after) after();
            }
            fb->RXBUFFER.value.BLOCKED = 0;
            fb->TXBUFFER.value.BLOCKED = 0;
            const std::vector<std::uint8_t> out = com_ring::TakeAll(fb->TXBUFFER.value);
            if (!out.empty()) line_.toPac.Send(clock_.Now(), out);
        });
    }

    // The PLC's serial driver in a faster task (Tc2_SerialCom's Blocked): it holds the FB's receive or
    // transmit buffer during the FB's call in the scans in which `held` returns TRUE (asked once a scan,
    // before the call). The bytes still arrive; the FB finds them in its next call with the buffer free.
    void HoldRxBuffer(std::function<bool()> held) { rxHeld_ = std::move(held); }
    void HoldTxBuffer(std::function<bool()> held) { txHeld_ = std::move(held); }

    void Scan(int n = 1);
    // Scans until `predicate` holds after a scan; returns the scans run, or -1 after maxScans.
    int ScanUntil(const std::function<bool()>& predicate, int maxScans);

    pac::sim::PaControl& Controller() { return pac_; }
    pac::sim::SerialLine& Line() { return line_; }
    pac::PlcTask& Task() { return task_; }
    std::chrono::nanoseconds Now() const { return clock_.Now(); }
    const SerialRigTiming& Timing() const { return timing_; }
    // Bytes the driver could not put into a full receive buffer.
    std::uint64_t Overruns() const { return overruns_; }

private:
    SerialRigTiming timing_;
    pac::SimClock clock_;
    pac::PlcTask task_;
    pac::sim::Bus bus_;
    pac::sim::PaControl pac_;
    pac::sim::PacRunner runner_;
    pac::sim::SerialLine line_;
    std::uint64_t overruns_ = 0;
    std::function<bool()> rxHeld_;
    std::function<bool()> txHeld_;
};

}  // namespace pac
