// libFuzzer target: FB_PAC_Axis on a 12-byte axis module (manual 2.7), scan by scan, against whatever the
// input makes the PA-CONTROL's side say: a status that follows the Start bit (ACTIVE while Start is out) with
// any status bits, error numbers and position flipped in, raw bytes, an all-zero module (link lost), or nothing
// new. The input also drives every input of the FB: Enable, Execute, Command (out-of-range values included),
// Position (any REAL, NaN and infinities included), Velocity, Acceleration, the jog inputs, Abort,
// ResetError, DisableDrive, DisableLimitSwitches, Condition, IntegerMode, Timeout, OpStatus, ModeChange, and
// the PLC cycle.
// Checked after every scan: the PLCopen rules (plcopen_checker.hpp; a move has no Busy bound of its own) and
// the control word rule: never two traverse bits, Start only with exactly one (axis_control_rules.hpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "axis_control_rules.hpp"
#include "fuzz_bytes.hpp"
#include "fuzz_plc.hpp"
#include "pac/axis_module_bits.hpp"
#include "pac/fb_instance.hpp"
#include "pac/st_program.hpp"
#include "plcopen_checker.hpp"

namespace {

using pac::fuzz::FuzzBytes;
namespace ac = pac::axis_control;
namespace as = pac::axis_status;

using Module = std::array<std::uint8_t, 12>;

// PAC byte order: the first byte on the wire is the most significant (manual 2.3.2).
std::uint32_t DwordAt(const Module& m, std::size_t offset) {
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < 4; ++i) value = (value << 8) | m[offset + i];
    return value;
}
void SetDwordAt(Module& m, std::size_t offset, std::uint32_t value) {
    for (std::size_t i = 0; i < 4; ++i) m[offset + 3 - i] = static_cast<std::uint8_t>(value >> (8 * i));
}

// The PA-CONTROL's side of the axis module, one decision per scan.
class AxisReplies {
public:
    void Next(FuzzBytes& in, std::uint32_t control) {
        const std::uint8_t op = in.Byte();
        switch (op & 3U) {
            case 0:
                break;
            case 1: {  // a plausible axis: ON follows Axis ON, ACTIVE follows Start, any bits flipped on top
                std::uint32_t status = as::kReferenced | as::kNegativeLimitNotActuated | as::kPositiveLimitNotActuated;
                if ((control & ac::kAxisOn) != 0) status |= as::kDriveEnabled;
                if ((control & ac::kStart) != 0) status |= as::kActive;
                if ((op & 0x04U) != 0) status ^= in.Dword();
                SetDwordAt(reply_, 0, status);
                if ((op & 0x08U) != 0) {
                    for (std::size_t i = 4; i < 8; ++i) reply_[i] = in.Byte();  // CMD and axis error numbers
                }
                if ((op & 0x10U) != 0) SetDwordAt(reply_, 8, in.Dword());  // the position
                break;
            }
            case 2:
                for (auto& b : reply_) b = in.Byte();
                break;
            default:
                reply_.fill(0);
                break;
        }
    }
    const Module& Bytes() const { return reply_; }

private:
    Module reply_{};
};

class AxisFuzzRun {
public:
    explicit AxisFuzzRun(FuzzBytes& in) : in_(in), plc_(in), check_("FB_PAC_Axis", pac::fuzz::AbortOnViolation()) {
        plc_.Task().AddProgram([this] { Scan(); });
    }

    void Run() {
        plc_.Run(in_, [this] { return axis_->BUSY.value != 0; });
    }

private:
    void Scan() {
        Drive(in_.Byte());
        replies_.Next(in_, Control());
        for (std::size_t i = 0; i < 12; ++i) axis_->FROMPAC.value.table[i] = replies_.Bytes()[i];
        axis_();
        if (trace_) Trace();
        check_.Check(plc_.Task().ScanCount(), axis_);
        if (const char* broken = pac::test::AxisControlWordViolation(Control(), ac::kTraverseBits, ac::kStart)) {
            pac::fuzz::Violation("scan " + std::to_string(plc_.Task().ScanCount()) + ": " + broken);
        }
    }

    void Drive(std::uint8_t bits) {
        auto level = [bits](unsigned bit) { return (bits & (1U << bit)) != 0 ? TRUE : FALSE; };
        axis_->ENABLE.value = level(0);
        axis_->EXECUTE.value = level(1);
        axis_->JOGPOSITIVE.value = level(2);
        axis_->JOGNEGATIVE.value = level(3);
        axis_->ABORT.value = level(4);
        axis_->RESETERROR.value = level(5);
        axis_->DISABLEDRIVE.value = level(6);
        if ((bits & 0x80U) == 0) return;
        axis_->COMMAND.value = static_cast<E_PAC_AXISCOMMAND>(in_.Below(12));
        axis_->POSITION.value = in_.Real();
        axis_->VELOCITY.value = in_.Word();
        axis_->ACCELERATION.value = in_.Word();
        axis_->CONDITION.value = static_cast<E_PAC_MOVECONDITION>(in_.Below(4));
        const std::uint8_t flags = in_.Byte();
        axis_->INTEGERMODE.value = (flags & 1U) != 0 ? TRUE : FALSE;
        axis_->DISABLELIMITSWITCHES.value = (flags & 2U) != 0 ? TRUE : FALSE;
        axis_->TIMEOUT.value = pac::fuzz::ShortTime(in_);
        // The operating status the program passes on (FB_PAC_CmdInterface.OpStatus): 1 home, 31 ONLINE, or any.
        const std::uint8_t status = in_.Byte();
        axis_->OPSTATUS.value = (status & 0x80U) != 0 ? status : (status & 1U) != 0 ? 31 : 1;
        axis_->MODECHANGE.value = (flags & 4U) != 0 ? TRUE : FALSE;
    }

    void Trace() {
        const auto& fb = axis_.Data();
        std::fprintf(stderr, "scan %lld: En %d Ex %d Cmd %d J+ %d J- %d Ab %d Rst %d | CW %05X SW %08X | %c ErrID %04X State %d\n",
                     static_cast<long long>(plc_.Task().ScanCount()), fb.ENABLE.value, fb.EXECUTE.value,
                     static_cast<int>(fb.COMMAND.value), fb.JOGPOSITIVE.value, fb.JOGNEGATIVE.value, fb.ABORT.value,
                     fb.RESETERROR.value, Control(), DwordAt(replies_.Bytes(), 0),
                     pac::test::OutputsOf(axis_).Letter(), fb.ERRORID.value, static_cast<int>(fb.STATE.value));
    }

    std::uint32_t Control() {
        Module out{};
        for (std::size_t i = 0; i < 12; ++i) out[i] = axis_->TOPAC.value.table[i];
        return DwordAt(out, 0);
    }

    FuzzBytes& in_;
    pac::fuzz::FuzzPlc plc_;
    pac::FbInstance<FB_PAC_AXIS> axis_ = PAC_FB(FB_PAC_AXIS);
    AxisReplies replies_;
    pac::test::PlcOpenChecker check_;
    bool trace_ = pac::fuzz::TraceWanted();
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return pac::fuzz::RunOneInput<AxisFuzzRun>(data, size);
}
