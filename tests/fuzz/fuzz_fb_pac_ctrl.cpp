// libFuzzer target: FB_PAC_Ctrl on the CTRL module (manual 2.5), scan by scan, against whatever the input
// makes the PA-CONTROL's side say: a new status word, a new system error word, raw bytes, an all-zero module
// (link lost, controller booting), or nothing new. The input also drives Execute, Request (out-of-range
// values included), IntegerMode, Timeout and the PLC cycle.
// Checked after every scan: the PLCopen rules with the Busy bound Timeout (plcopen_checker.hpp), and that the
// control word (2.5.1) asks for one thing at most, and only while the FB is Busy: of Start ONLINE, Start
// AUTOMATIC (high-active) and Stop, Cancel, Error reset (low-active), at most one is asserted.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_bytes.hpp"
#include "fuzz_plc.hpp"
#include "pac/fb_instance.hpp"
#include "pac/st_program.hpp"
#include "plcopen_checker.hpp"

namespace {

using pac::fuzz::FuzzBytes;

// The PA-CONTROL's side of the CTRL module, one decision per scan: bytes 0..1 the status word, 2..3 the
// system error number (2.5.2).
class CtrlReplies {
public:
    void Next(FuzzBytes& in) {
        const std::uint8_t op = in.Byte();
        switch (op & 3U) {
            case 0:
                break;
            case 1:
                reply_[0] = in.Byte();
                reply_[1] = in.Byte();
                if ((op & 0x80U) != 0) {
                    reply_[2] = in.Byte();
                    reply_[3] = in.Byte();
                }
                break;
            case 2:
                for (auto& b : reply_) b = in.Byte();
                break;
            default:
                reply_.fill(0);
                break;
        }
    }
    const std::array<std::uint8_t, 8>& Bytes() const { return reply_; }

private:
    std::array<std::uint8_t, 8> reply_{0, 0x03, 0, 0, 0, 0, 0, 0};  // ready, battery ok
};

class CtrlFuzzRun {
public:
    explicit CtrlFuzzRun(FuzzBytes& in) : in_(in), plc_(in), check_("FB_PAC_Ctrl", pac::fuzz::AbortOnViolation()) {
        plc_.Task().AddProgram([this] { Scan(); });
    }

    void Run() {
        plc_.Run(in_, [this] { return ctrl_->BUSY.value != 0; });
    }

private:
    void Scan() {
        const std::uint8_t inputs = in_.Byte();
        // New request data with an Execute edge only: the Busy bound is the job's own Timeout.
        const bool edge = (inputs & 1U) != 0 && ctrl_->EXECUTE.value == 0;
        ctrl_->EXECUTE.value = (inputs & 1U) != 0 ? TRUE : FALSE;
        if (edge && ctrl_->BUSY.value == 0 && (inputs & 2U) != 0) {
            ctrl_->REQUEST.value = static_cast<E_PAC_CTRLREQUEST>(in_.Below(8));
            ctrl_->INTEGERMODE.value = in_.Bit() ? TRUE : FALSE;
            ctrl_->TIMEOUT.value = pac::fuzz::ShortTime(in_);
        }
        replies_.Next(in_);
        for (std::size_t i = 0; i < 8; ++i) ctrl_->FROMPAC.value.table[i] = replies_.Bytes()[i];
        ctrl_();
        check_.Check(plc_.Task().ScanCount(), ctrl_, pac::test::RequestBusyBoundOf(ctrl_, plc_.Cycle()));
        CheckControlWord();
    }

    void CheckControlWord() {
        const auto& out = ctrl_->TOPAC.value.table;
        const unsigned word = (static_cast<unsigned>(out[0]) << 8) | out[1];
        const unsigned asserted = (word & 0x08U ? 1 : 0) + (word & 0x10U ? 1 : 0) + (word & 0x01U ? 0 : 1) +
                                  (word & 0x02U ? 0 : 1) + (word & 0x04U ? 0 : 1);
        const std::string scan = "scan " + std::to_string(plc_.Task().ScanCount()) + ": ";
        if (asserted > 1) pac::fuzz::Violation(scan + "the control word asks for several things at once");
        if (asserted == 1 && ctrl_->BUSY.value == 0) pac::fuzz::Violation(scan + "a request bit out while not Busy");
    }

    FuzzBytes& in_;
    pac::fuzz::FuzzPlc plc_;
    pac::FbInstance<FB_PAC_CTRL> ctrl_ = PAC_FB(FB_PAC_CTRL);
    CtrlReplies replies_;
    pac::test::PlcOpenChecker check_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return pac::fuzz::RunOneInput<CtrlFuzzRun>(data, size);
}
