// The controller's side of one 12-byte axis module in ONLINE mode (manual 2.7, /work/briefs/axis.md): each
// controller cycle it reads the master's control word, per-mille dynamics and position, acts on one ServoAxis
// (Axis ON, DISABLE DRIVE, the Start handshake, interrupts, G123, reset axis error) and composes the status
// reply. It knows nothing of the bus or of the other axes; docs/simulator.md "Axis modules (2.7)" lists
// every decision where the manual is silent.
#pragma once

#include <chrono>
#include <cstdint>

#include "pac/sim/elements.hpp"
#include "pac/sim/process_image.hpp"
#include "pac/sim/servo_axis.hpp"

namespace pac::sim {

// Control word, master -> PA-CONTROL, bytes 0..3 (2.7.1; bit 4 is G26, NOTES.md).
namespace axis_control {
constexpr std::uint32_t kAxisOn = 1U << 0;
constexpr std::uint32_t kDisableDrive = 1U << 1;
constexpr std::uint32_t kStart = 1U << 2;
constexpr std::uint32_t kHome = 1U << 3;                  // G25
constexpr std::uint32_t kSetReferenced = 1U << 4;         // G26
constexpr std::uint32_t kShift = 1U << 5;                 // G29
constexpr std::uint32_t kAbsolute = 1U << 6;
constexpr std::uint32_t kRelative = 1U << 7;
constexpr std::uint32_t kWhileInputOne = 1U << 8;         // G123 Ix..1
constexpr std::uint32_t kWhileInputZero = 1U << 9;        // G123 Ix..0
constexpr std::uint32_t kJogPositive = 1U << 10;
constexpr std::uint32_t kJogNegative = 1U << 11;
constexpr std::uint32_t kDeleteShift = 1U << 12;
constexpr std::uint32_t kResetDisplaced = 1U << 13;
constexpr std::uint32_t kToMaxRange = 1U << 14;
constexpr std::uint32_t kToMinRange = 1U << 15;
constexpr std::uint32_t kResetAxisError = 1U << 16;
constexpr std::uint32_t kLimitSwitchMonitoringOff = 1U << 17;  // G142
// Exactly one of these with a Start edge (2.7.2 notes).
constexpr std::uint32_t kTraverseBits = kHome | kSetReferenced | kShift | kAbsolute | kRelative | kJogPositive |
                                        kJogNegative | kDeleteShift | kResetDisplaced | kToMaxRange | kToMinRange;
}  // namespace axis_control

// Status word, PA-CONTROL -> master, bytes 0..3 (2.7.2). The limit switch bits are low-active.
namespace axis_status {
constexpr std::uint32_t kDriveEnabled = 1U << 0;
constexpr std::uint32_t kHalt = 1U << 1;
constexpr std::uint32_t kDriveDisabled = 1U << 2;
constexpr std::uint32_t kSafe = 1U << 3;
constexpr std::uint32_t kIdle = 1U << 4;
constexpr std::uint32_t kDisabled = 1U << 5;
constexpr std::uint32_t kFault = 1U << 6;
constexpr std::uint32_t kActive = 1U << 7;
constexpr std::uint32_t kReferenced = 1U << 8;
constexpr std::uint32_t kNegativeLimitSwitch = 1U << 9;   // 0 = actuated
constexpr std::uint32_t kPositiveLimitSwitch = 1U << 10;  // 0 = actuated
constexpr std::uint32_t kStoppedByG123 = 1U << 11;
constexpr std::uint32_t kDisplaced = 1U << 12;
constexpr std::uint32_t kGroupDisplaced = 1U << 13;
constexpr std::uint32_t kCmdError = 1U << 14;
constexpr std::uint32_t kAxisError = 1U << 15;
}  // namespace axis_status

// The master's 12 bytes (2.7.1), big-endian. The position is the raw dword: IEEE REAL, or DINT x 1000.
struct AxisModuleCommand {
    std::uint32_t control = 0;
    std::uint16_t accelerationPerMille = 0;  // bytes 4..5
    std::uint16_t speedPerMille = 0;         // bytes 6..7
    std::uint32_t position = 0;              // bytes 8..11

    static AxisModuleCommand Decode(const Image12& module);
    Image12 Encode() const;
};

// The PA-CONTROL's 12 bytes (2.7.2), big-endian.
struct AxisModuleReply {
    std::uint32_t status = 0;
    std::uint16_t cmdError = 0;   // bytes 4..5
    std::uint16_t axisError = 0;  // bytes 6..7
    std::uint32_t position = 0;   // bytes 8..11, the format of the command's position

    static AxisModuleReply Decode(const Image12& module);
    Image12 Encode() const;
};

// A position as the module carries it (2.5.3): IEEE single, or a DINT of the value x 1000, rounded to the
// nearest and clamped to the DINT range (the manual does not say what happens beyond it).
std::uint32_t EncodeModulePosition(double position, bool integerFormat);
double DecodeModulePosition(std::uint32_t raw, bool integerFormat);

// What the controller's operating status lets the module do.
enum class AxisModuleService {
    kReportOnly,  // outside ONLINE: the status is reported, the control word is not acted upon
    kControl,     // ONLINE, but not ONLINE proper (30, 32, 35, 37, 39): Axis ON, DISABLE DRIVE, reset axis error
    kJobs,        // ONLINE proper (31): also jobs on a Start edge
};

// What one controller cycle gives the module besides the master's bytes.
struct AxisModuleContext {
    std::chrono::nanoseconds now{0};
    AxisModuleService service = AxisModuleService::kReportOnly;
    bool integerFormat = false;      // 2.5.3: the format in force (CTRL status bit 15)
    const BitBank* inputs = nullptr; // for G123; nullptr: every input reads 0
    bool groupDisplaced = false;     // status bit 13 besides the axis's own flag (an axis of the group)
};

// How a CMD error that is showing looks in the cycle of the next Start edge (2.7.4.14: "deleted during the
// next Start command"). Both happen on real controllers as far as the master can tell, and FB_PAC_Axis must
// cope with both (/work/briefs/axis.md).
enum class CmdErrorRestart {
    kSameCycle,      // cleared and, if the new job is refused, set again with its number in the same cycle
    kOneCycleClear,  // the edge cycle shows flag and number 0; a refusal shows from the next cycle on
};

struct AxisModuleConfig {
    CmdErrorRestart cmdErrorRestart = CmdErrorRestart::kSameCycle;
};

class AxisModule {
public:
    // CMD error numbers of the module itself (the axis's refusals come from ServoAxis, axis_error::k...).
    static constexpr std::uint16_t kInadmissible = 20;  // 6.5 "inadmissible command": no / several traverse
                                                        // bits, a bad G123 combination, Start outside ONLINE
    static constexpr int kDefaultConditionInput = 1;    // 2.7.3.10: input 1 at the start of ONLINE

    explicit AxisModule(AxisModuleConfig config = {});

    // One controller cycle: act on `master` (Serve), then compose the reply (Reply).
    Image12 Cycle(const Image12& master, ServoAxis& axis, const AxisModuleContext& context);
    // The control word's effects at context.now. Brings the axis to context.now first.
    void Serve(const Image12& master, ServoAxis& axis, const AxisModuleContext& context);
    // The 12 reply bytes for the axis as it stands (call after Serve in the same cycle).
    Image12 Reply(const ServoAxis& axis, const AxisModuleContext& context) const;

    // G123 input (2.7.3.10 / 2.7.3.11; cmd_put_condition_move_axis). 1..n; back to 1 when ONLINE starts.
    // std::invalid_argument below 1. An input the controller does not have reads 0.
    void SetConditionInput(int input);
    int ConditionInput() const { return conditionInput_; }

    // State as the reply shows it.
    bool Active() const { return active_; }
    bool JobRunning() const { return job_ != 0 && !jobComplete_; }  // taken over, not yet complete
    std::uint16_t CmdError() const { return cmdError_; }
    bool StoppedByCondition() const { return stoppedByG123_; }

    // Back to the power-on state (no job, no CMD error, input 1, no edges remembered).
    void Reset();

private:
    enum class Condition { kNone, kWhileOne, kWhileZero };

    void FollowMode(ServoAxis& axis, const AxisModuleContext& context);
    void ApplyDrive(std::uint32_t control, ServoAxis& axis, const AxisModuleContext& context);
    void FollowJob(std::uint32_t control, ServoAxis& axis, const AxisModuleContext& context);
    void StartEdge(const AxisModuleCommand& command, ServoAxis& axis, const AxisModuleContext& context);
    std::uint16_t TakeOver(const AxisModuleCommand& command, ServoAxis& axis, const AxisModuleContext& context);
    bool ConditionHolds(const AxisModuleContext& context) const;
    void ShowCmdError(std::uint16_t number);

    AxisModuleConfig config_;
    int conditionInput_ = kDefaultConditionInput;
    bool served_ = false;            // the last cycle was an ONLINE one (kControl / kJobs)
    std::uint32_t lastControl_ = 0;  // for the Start and reset edges (0 at power-on)

    std::uint32_t job_ = 0;          // the traverse bit of the job taken over; 0: none
    bool jobComplete_ = true;
    bool interrupted_ = false;       // the module has interrupted the job (bit removed, G123)
    Condition condition_ = Condition::kNone;
    bool active_ = false;
    bool stoppedByG123_ = false;
    std::uint16_t cmdError_ = 0;
    std::uint16_t pendingCmdError_ = 0;  // kOneCycleClear: shown from the next cycle
};

}  // namespace pac::sim
