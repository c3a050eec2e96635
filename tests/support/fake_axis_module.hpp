// A scripted PA-CONTROL axis behind one 12-byte axis module in ONLINE mode (manual 2.7, read as
// docs/fb/FB_PAC_Axis.md describes): it answers the control word once per controller cycle with the
// status word, CMD and axis error numbers and the position, and it can be made to misbehave the ways a
// real controller may (CMD error cleared and set again in one cycle, answers held back for N cycles,
// ACTIVE that never falls, no answer at all). ScanDelayLine is the bus latency.
#pragma once

#include <array>
#include <bitset>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <deque>
#include <vector>

#include "pac/axis_module_bits.hpp"

namespace pac::test {

using AxisImage = std::array<std::uint8_t, 12>;

inline std::uint32_t ReadBe32(const AxisImage& image, int at) {
    return (std::uint32_t{image[at]} << 24) | (std::uint32_t{image[at + 1]} << 16) |
           (std::uint32_t{image[at + 2]} << 8) | std::uint32_t{image[at + 3]};
}

inline std::uint16_t ReadBe16(const AxisImage& image, int at) {
    return static_cast<std::uint16_t>((image[at] << 8) | image[at + 1]);
}

inline void WriteBe32(AxisImage& image, int at, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) image[at + i] = static_cast<std::uint8_t>(value >> (24 - 8 * i));
}

inline void WriteBe16(AxisImage& image, int at, std::uint16_t value) {
    image[at] = static_cast<std::uint8_t>(value >> 8);
    image[at + 1] = static_cast<std::uint8_t>(value);
}

// A fixed delay of whole scans: Push() gives back the value pushed `delay` pushes earlier.
template <class T>
class ScanDelayLine {
public:
    ScanDelayLine(int delay, const T& initial) : queue_(static_cast<std::size_t>(delay), initial) {}

    T Push(const T& value) {
        queue_.push_back(value);
        T out = queue_.front();
        queue_.pop_front();
        return out;
    }

private:
    std::deque<T> queue_;
};

// How a controller shows a refused job when the CMD error bit is already set from an earlier one.
enum class CmdErrorStyle {
    kClearThenSet,      // the Start edge clears bit and number, the refusal sets them one cycle later
    kSameCycle,         // cleared and set again in the same cycle: the master never sees the bit fall
};

struct FakeAxisConfig {
    CmdErrorStyle cmdErrorStyle = CmdErrorStyle::kClearThenSet;
    int answerDelay = 0;    // cycles between the Start edge and its answer; the reply stays unchanged meanwhile
    int moveCycles = 4;     // cycles an absolute/relative move, a reference run or a jog's whole distance takes
    int brakeCycles = 2;    // cycles from an interruption to standstill
    bool integerFormat = false;  // positions as DINT x 1000 (2.5.3), else IEEE REAL
    bool referenced = true;
    float position = 0.0f;
};

// One job as the controller received it with its Start edge.
struct ReceivedJob {
    std::uint32_t control = 0;
    std::uint16_t acceleration = 0;
    std::uint16_t speed = 0;
    std::uint32_t position = 0;
};

class FakeAxisModule {
public:
    explicit FakeAxisModule(FakeAxisConfig config = {})
        : config_(config), referenced_(config.referenced), position_(config.position) {}

    // One controller cycle on the control word image it receives; returns the module it sends.
    AxisImage Cycle(const AxisImage& fromMaster) {
        using namespace axis_control;
        const std::uint32_t control = ReadBe32(fromMaster, 0);
        axisOn_ = (control & kAxisOn) != 0;
        const bool start = (control & kStart) != 0;
        if ((control & kResetAxisError) != 0) {
            ++resetCycles_;
            if (axisError_ && !axisErrorPersists_) {
                axisError_ = false;
                axisErrorNumber_ = 0;
            }
        }
        if (pendingCmdError_ != 0) {
            cmdError_ = true;
            cmdErrorNumber_ = pendingCmdError_;
            pendingCmdError_ = 0;
        }
        Progress(control, start);
        if (start && !lastStart_ && !active_ && !answering_ && !mute_) {
            answering_ = true;
            answerCountdown_ = config_.answerDelay;
            edgeImage_ = fromMaster;
        }
        if (answering_) {
            if (answerCountdown_ == 0) {
                answering_ = false;
                Recognise(edgeImage_);
            } else {
                --answerCountdown_;
            }
        }
        lastStart_ = start;
        return Reply();
    }

    // What the module sends in the current state (also before the first cycle).
    AxisImage Reply() const {
        using namespace axis_status;
        std::uint32_t status = 0;
        status |= axisOn_ ? kDriveEnabled : kIdle;
        if (halted_) status |= kHalt;
        if (axisError_) status |= kFault | kAxisError;
        if (active_) status |= kActive;
        if (referenced_) status |= kReferenced;
        if (!negativeLimit_) status |= kNegativeLimitNotActuated;
        if (!positiveLimit_) status |= kPositiveLimitNotActuated;
        if (stoppedByCondition_) status |= kStoppedByCondition;
        if (displaced_) status |= kDisplaced;
        if (cmdError_) status |= kCmdError;
        AxisImage image{};
        WriteBe32(image, 0, status);
        WriteBe16(image, 4, cmdErrorNumber_);
        WriteBe16(image, 6, axisErrorNumber_);
        WriteBe32(image, 8, EncodePosition(position_));
        return image;
    }

    // --- the script -------------------------------------------------------------------------------
    void RefuseJobsWith(std::uint16_t cmdErrorNumber) { refuseWith_ = cmdErrorNumber; }
    void SetReferenced(bool referenced) { referenced_ = referenced; }
    // A CMD error left over from an earlier job (or from before a PLC restart).
    void SetCmdError(std::uint16_t number) {
        cmdError_ = number != 0;
        cmdErrorNumber_ = number;
    }
    // An axis error (limit switch, following error...): the axis stops at once and the job ends.
    void RaiseAxisError(std::uint16_t number, bool persists = false) {
        axisError_ = true;
        axisErrorNumber_ = number;
        axisErrorPersists_ = persists;
        moving_ = false;
    }
    void ClearAxisErrorCause() { axisErrorPersists_ = false; }
    // Something other than the module interrupts the job (STOP ONLINE...): the axis brakes, HALT.
    void InterruptFromOutside() { interruptFromOutside_ = true; }
    // The G123 input of the running move changes: it brakes and reports "stopped by G123".
    void StopByCondition() {
        if (moving_ && (job_.control & (axis_control::kWhileInput0 | axis_control::kWhileInput1)) != 0) {
            BeginBraking();
            conditionStopping_ = true;
        }
    }
    void SetLimitSwitches(bool negativeActuated, bool positiveActuated) {
        negativeLimit_ = negativeActuated;
        positiveLimit_ = positiveActuated;
    }
    void SetDisplaced(bool displaced) { displaced_ = displaced; }
    // Ignores every Start edge: no take-over, no CMD error.
    void Mute(bool mute) { mute_ = mute; }
    // ACTIVE stays up however long the master waits (a drive that never reports standstill).
    void HoldActive(bool hold) { holdActive_ = hold; }

    // --- what happened ----------------------------------------------------------------------------
    const std::vector<ReceivedJob>& Jobs() const { return jobs_; }
    int ResetCycles() const { return resetCycles_; }
    bool IsMoving() const { return moving_; }
    float Position() const { return position_; }

private:
    static int TraverseBitCount(std::uint32_t control) {
        return static_cast<int>(std::bitset<32>(control & axis_control::kTraverseBits).count());
    }

    std::uint32_t EncodePosition(float value) const {
        if (config_.integerFormat) {
            return static_cast<std::uint32_t>(static_cast<std::int32_t>(std::lround(double{value} * 1000.0)));
        }
        std::uint32_t bits;
        std::memcpy(&bits, &value, sizeof bits);
        return bits;
    }

    float DecodePosition(std::uint32_t bits) const {
        if (config_.integerFormat) {
            return static_cast<float>(static_cast<std::int32_t>(bits) / 1000.0);
        }
        float value;
        std::memcpy(&value, &bits, sizeof value);
        return value;
    }

    void Refuse(std::uint16_t number) {
        if (config_.cmdErrorStyle == CmdErrorStyle::kClearThenSet) {
            cmdError_ = false;
            cmdErrorNumber_ = 0;
            pendingCmdError_ = number;
        } else {
            cmdError_ = true;
            cmdErrorNumber_ = number;
        }
    }

    // The Start edge of a job while no job is processed (2.7.3.2): take it over or refuse it.
    void Recognise(const AxisImage& image) {
        using namespace axis_control;
        ReceivedJob job{ReadBe32(image, 0), ReadBe16(image, 4), ReadBe16(image, 6), ReadBe32(image, 8)};
        jobs_.push_back(job);
        const std::uint32_t traverse = job.control & kTraverseBits;
        const bool needsReference = (traverse & (kMoveAbsolute | kMoveRelative | kMoveToMax | kMoveToMin)) != 0;
        std::uint16_t refusal = 0;
        if (TraverseBitCount(job.control) != 1) {
            refusal = 20;  // no or several traverse bits
        } else if (!axisOn_) {
            refusal = 55;  // axis not switched on
        } else if (axisError_) {
            refusal = 46;  // axis not ready
        } else if (needsReference && !referenced_) {
            refusal = 43;  // no reference
        } else if (refuseWith_ != 0) {
            refusal = refuseWith_;
        }
        if (refusal != 0) {
            Refuse(refusal);
            return;
        }
        cmdError_ = false;
        cmdErrorNumber_ = 0;
        pendingCmdError_ = 0;
        active_ = true;
        halted_ = false;
        job_ = job;
        const float value = DecodePosition(job.position);
        // The flag tells about the last G123 move (2.7.4.11): a new one starts it afresh.
        if ((job.control & (kWhileInput0 | kWhileInput1)) != 0) stoppedByCondition_ = false;
        switch (traverse) {
            case kHome: StartMove(0.0f); break;
            case kMoveAbsolute: StartMove(value); break;
            case kMoveRelative: StartMove(position_ + value); break;
            case kMoveToMax: StartMove(1000.0f); break;
            case kMoveToMin: StartMove(-1000.0f); break;
            case kJogPositive: StartMove(position_ + std::fabs(value)); break;
            case kJogNegative: StartMove(position_ - std::fabs(value)); break;
            case kSetReferenced:
                position_ = value;
                referenced_ = true;
                break;
            case kSetPosition: position_ = value; break;
            case kClearDisplaced: displaced_ = false; break;
            default: break;  // kClearOffset: nothing the fake tracks
        }
    }

    void StartMove(float target) {
        start_ = position_;
        target_ = target;
        moving_ = true;
        braking_ = false;
        conditionStopping_ = false;
        remaining_ = config_.moveCycles;
        total_ = config_.moveCycles;
        if (remaining_ == 0) FinishMove();
    }

    void BeginBraking() {
        braking_ = true;
        remaining_ = config_.brakeCycles;
    }

    void FinishMove() {
        moving_ = false;
        if (braking_) {
            halted_ = true;  // an interrupted job, the drive stands (2.7.4.2)
            stoppedByCondition_ = conditionStopping_;
            return;
        }
        position_ = target_;
        if ((job_.control & axis_control::kHome) != 0) referenced_ = true;
    }

    // The running job: interruption by a missing traverse bit, Axis ON 0 or from outside; ACTIVE falls
    // once the job is complete and Start is 0 (2.7.4.8).
    void Progress(std::uint32_t control, bool start) {
        if (!active_) return;
        if (moving_ && !braking_) {
            const bool keep = (control & job_.control & axis_control::kTraverseBits) != 0 && axisOn_;
            if (!keep || interruptFromOutside_) BeginBraking();
        }
        interruptFromOutside_ = false;
        if (moving_) {
            if (remaining_ > 0) {
                --remaining_;
                if (!braking_ && total_ > 0) {
                    position_ = start_ + (target_ - start_) * static_cast<float>(total_ - remaining_) / total_;
                }
            }
            if (remaining_ == 0) FinishMove();
        }
        if (!moving_ && !start && !holdActive_) active_ = false;
    }

    FakeAxisConfig config_;
    bool axisOn_ = false;
    bool active_ = false;
    bool moving_ = false;
    bool braking_ = false;
    bool conditionStopping_ = false;
    bool halted_ = false;
    bool referenced_ = false;
    bool stoppedByCondition_ = false;
    bool displaced_ = false;
    bool negativeLimit_ = false;
    bool positiveLimit_ = false;
    bool cmdError_ = false;
    std::uint16_t cmdErrorNumber_ = 0;
    std::uint16_t pendingCmdError_ = 0;
    bool axisError_ = false;
    bool axisErrorPersists_ = false;
    std::uint16_t axisErrorNumber_ = 0;
    std::uint16_t refuseWith_ = 0;
    bool interruptFromOutside_ = false;
    bool mute_ = false;
    bool holdActive_ = false;
    bool lastStart_ = false;
    bool answering_ = false;
    int answerCountdown_ = 0;
    AxisImage edgeImage_{};
    ReceivedJob job_{};
    float position_ = 0.0f;
    float start_ = 0.0f;
    float target_ = 0.0f;
    int remaining_ = 0;
    int total_ = 0;
    int resetCycles_ = 0;
    std::vector<ReceivedJob> jobs_;
};

}  // namespace pac::test
