// The controller's side of one 12-byte axis module in ONLINE mode (manual 2.7, docs/sim_axis_modules.md): each
// controller cycle it reads the PLC's control word (pac/axis_module_bits.hpp), per-mille dynamics and position,
// acts on one ServoAxis (Axis ON, DISABLE DRIVE, the Start handshake, interrupts, G123, reset axis error) and
// composes the status reply. It knows nothing of the bus or of the other axes; docs/sim_axis_modules.md lists
// every decision where the manual is silent.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pac/axis_module_bits.hpp"
#include "pac/sim/elements.hpp"
#include "pac/sim/process_image.hpp"
#include "pac/sim/servo_axis.hpp"

namespace pac::sim {

// The PLC's 12 bytes, to PAC (2.7.1), big-endian. The position is the raw dword: IEEE REAL, or DINT x 1000.
struct AxisModuleCommand {
    std::uint32_t control = 0;
    std::uint16_t accelerationPerMille = 0;  // bytes 4..5
    std::uint16_t speedPerMille = 0;         // bytes 6..7
    std::uint32_t position = 0;              // bytes 8..11

    static AxisModuleCommand Decode(const Image12& module);
    Image12 Encode() const;
};

// The PA-CONTROL's 12 bytes, from PAC (2.7.2), big-endian.
struct AxisModuleReply {
    std::uint32_t status = 0;
    std::uint16_t cmdError = 0;   // bytes 4..5
    std::uint16_t axisError = 0;  // bytes 6..7
    std::uint32_t position = 0;   // bytes 8..11, the format of the command's position

    static AxisModuleReply Decode(const Image12& module);
    Image12 Encode() const;
    void EncodeInto(Image12& module) const;
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

// What one controller cycle gives the module besides the PLC's bytes.
struct AxisModuleContext {
    std::chrono::nanoseconds now{0};
    AxisModuleService service = AxisModuleService::kReportOnly;
    bool integerFormat = false;      // 2.5.3: the format in force (CTRL status bit 15)
    const BitBank* inputs = nullptr; // for G123; nullptr: every input reads 0
    bool groupDisplaced = false;     // status bit 13 besides the axis's own flag (an axis of the group)
};

// How a CMD error that is showing looks in the cycle of the next Start edge (2.7.4.14: "deleted during the
// next Start command"). Both happen on real controllers as far as the PLC can tell, and FB_PAC_Axis must
// cope with both (docs/sim_axis_modules.md).
enum class CmdErrorRestart {
    kSameCycle,      // cleared and, if the new job is refused, set again with its number in the same cycle
    kOneCycleClear,  // the edge cycle shows flag and number 0; a refusal shows from the next cycle on
};

// Which jobs raise ACTIVE (2.7.4.8: "the control processes a traversing task"), an open reading
// (docs/open_points.md). A job that does not traverse: G26, G29, delete offset, reset "displaced", a G123 move
// whose input condition is not met, a move to where the axis stands.
enum class ActiveForJobs {
    kEveryJob,        // every job taken over shows ACTIVE for at least its take-over cycle (the default)
    kTraversingOnly,  // a job complete in its take-over cycle never shows ACTIVE
};

// How a move of an unreferenced axis is refused, an open reading (docs/open_points.md): CMD error 43 (6.5) or,
// as the 2.7.2 note says, system error E525 "no reference point", which the module can show only as the axis
// error bit with its number.
enum class NoReferenceAnswer {
    kCmdError43,       // the default
    kSystemError525,   // no CMD error; axis error 525 until "reset axis error"
};

// What becomes of a traverse interrupted by Axis ON = 0 (2.7.2 note: "continued after the axis-ON function
// according to axis parameter 'switch on traverse mode'"), an open reading (docs/open_points.md).
enum class InterruptedTraverse {
    kEnds,                   // the job ends interrupted (HALT); the default
    kContinuesAfterAxisOn,   // a move's target is approached again by itself once the drive is enabled again in
                             // ONLINE proper, whatever the traverse bit says (the master removed it meanwhile)
};

// Whether the axis type changes speed and ramps while it traverses (2.7.2 note: "not possible for all axes
// types", only PA-CONTROL MP, LV-servoTEC, flexmoTEC, intelliMOT, dunMOT; 2.7.6 names PLS-MP, servoTEC, linMOT,
// intelliMOT). Where it can, new per-mille values in bytes 4..7 during a move or jog apply at once.
enum class SpeedChange {
    kNotWhileTraversing,  // the values are taken with Start only (the default)
    kWhileTraversing,
};

struct AxisModuleConfig {
    CmdErrorRestart cmdErrorRestart = CmdErrorRestart::kSameCycle;
    ActiveForJobs activeFor = ActiveForJobs::kEveryJob;
    NoReferenceAnswer noReference = NoReferenceAnswer::kCmdError43;
    InterruptedTraverse interruptedTraverse = InterruptedTraverse::kEnds;
    SpeedChange speedChange = SpeedChange::kNotWhileTraversing;
};

// A job the module took over on a Start edge (the ledger of what the controller executed): its control word,
// per-mille values and position bytes as the module carried them, and the controller's time.
struct TakenAxisJob {
    AxisModuleCommand command;
    std::chrono::nanoseconds at{0};
};

// The jobs an axis module took over, numbered 0, 1, ... from power-on in the order taken. It keeps the last
// kKept of them, so that a simulation running for hours holds bounded memory; a test reads a job by its number
// while it is kept (a test takes far fewer jobs between its edge and its check).
class TakenAxisJobLedger {
public:
    static constexpr std::size_t kKept = 1024;

    void Add(const TakenAxisJob& job);
    // The number of jobs taken over: the next job's number.
    std::size_t size() const { return count_; }
    // The number of the oldest job kept.
    std::size_t First() const { return count_ > kKept ? count_ - kKept : 0; }
    // Job `number`; std::out_of_range unless First() <= number < size().
    const TakenAxisJob& operator[](std::size_t number) const;

private:
    std::vector<TakenAxisJob> jobs_;  // grows to kKept, then job n is at n % kKept
    std::size_t count_ = 0;
};

class AxisModule {
public:
    // CMD error numbers of the module itself (the axis's refusals come from ServoAxis, axis_error::k...).
    static constexpr std::uint16_t kInadmissible = 20;  // 6.5 "inadmissible command": no / several traverse
                                                        // bits, a bad G123 combination, Start outside ONLINE
    static constexpr int kDefaultConditionInput = 1;    // 2.7.3.10: input 1 at the start of ONLINE
    static constexpr std::uint16_t kSystemErrorNoReference = 525;  // E525, NoReferenceAnswer::kSystemError525

    explicit AxisModule(AxisModuleConfig config = {});

    // One controller cycle: act on `toPac` (Serve), then compose the reply (Reply).
    Image12 Cycle(const Image12& toPac, ServoAxis& axis, const AxisModuleContext& context);
    // The control word's effects at context.now. Brings the axis to context.now first.
    void Serve(const Image12& toPac, ServoAxis& axis, const AxisModuleContext& context);
    // Outside the axis interface (AUTOMATIC, 2.6): the control word is taken as the reference for the next
    // edges only, so that flag data are no Start or reset edge once the module is an axis module again.
    void Follow(const Image12& toPac) { lastControl_ = AxisModuleCommand::Decode(toPac).control; }
    // The 12 reply bytes for the axis as it stands (call after Serve in the same cycle).
    Image12 Reply(const ServoAxis& axis, const AxisModuleContext& context) const;
    void ReplyInto(const ServoAxis& axis, const AxisModuleContext& context, Image12& module) const;

    // G123 input (2.7.3.10 / 2.7.3.11; cmd_put_condition_move_axis). 1..n; back to 1 when ONLINE starts.
    // std::invalid_argument below 1. An input the controller does not have reads 0.
    void SetConditionInput(int input);
    int ConditionInput() const { return conditionInput_; }

    // State as the reply shows it.
    bool Active() const { return active_; }
    bool JobRunning() const { return job_ != 0 && !jobComplete_; }  // taken over, not yet complete
    // The per-mille speed and acceleration in force for the job (its Start's, or a change while traversing).
    std::uint16_t SpeedPerMille() const { return speedPerMille_; }
    std::uint16_t AccelerationPerMille() const { return accelerationPerMille_; }
    std::uint16_t CmdError() const { return cmdError_; }
    bool StoppedByCondition() const { return stoppedByG123_; }
    // The jobs taken over since power-on of the simulation, the last TakenAxisJobLedger::kKept of them.
    const TakenAxisJobLedger& TakenJobs() const { return taken_; }

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
    void ContinueInterruptedTraverse(ServoAxis& axis, const AxisModuleContext& context);
    void FollowDynamics(const AxisModuleCommand& command, ServoAxis& axis, const AxisModuleContext& context);
    void ShowCmdError(std::uint16_t number);

    AxisModuleConfig config_;
    int conditionInput_ = kDefaultConditionInput;
    bool served_ = false;            // the last cycle was an ONLINE one (kControl / kJobs)
    std::uint32_t lastControl_ = 0;  // for the Start and reset edges (0 at power-on)

    std::uint32_t job_ = 0;          // the traverse bit of the job taken over; 0: none
    bool jobComplete_ = true;
    bool interrupted_ = false;       // the module has interrupted the job (bit removed, G123)
    bool continued_ = false;         // the job is an interrupted traverse continued by the controller itself
    bool toContinue_ = false;        // kContinuesAfterAxisOn: a move was interrupted by Axis ON = 0
    double target_ = 0.0;            // the target of the last move taken over
    Dynamics dynamics_{0.0, 0.0, 0.0};
    std::uint16_t speedPerMille_ = 0;         // the per-mille values in force for the job
    std::uint16_t accelerationPerMille_ = 0;
    Condition condition_ = Condition::kNone;
    bool active_ = false;
    bool stoppedByG123_ = false;
    std::uint16_t cmdError_ = 0;
    std::uint16_t pendingCmdError_ = 0;  // kOneCycleClear: shown from the next cycle
    TakenAxisJobLedger taken_;
};

}  // namespace pac::sim
