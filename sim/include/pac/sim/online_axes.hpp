// What the ONLINE commands of manual 5.2.6 keep per axis beside its motion (ServoAxis): measuring mode
// (0AA0 / 0AA1), limit switch monitoring (0AA2), the condition for the next movement (0AA3), the keep-alive
// of a manual traverse (0A90 / 0A91 / 0A92), the largest following error seen (190F) and the cooler
// temperature (1920). OnlineAxes::Supervise() acts on them once per controller cycle. The settings cover the
// readings the manual leaves open (docs/open_points.md, docs/sim_cmd.md).
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

#include "pac/sim/axis_group.hpp"
#include "pac/sim/elements.hpp"

namespace pac::sim {

// 5.2.6.23 numbers the bytes of the 32-bit command data "Byte 3", "Byte 4" and "Byte 1/0".
enum class ConditionLayout : std::uint8_t {
    kBySignificance,  // byte n = bits 8n+7..8n: condition in bits 31..24, element type in 23..16, number in 15..0
    kByProfibusByte,  // byte 0 first on the bus (as in 5.2.4.28): number in 31..16, type in 15..8, condition in 7..0
};

struct OnlineCommandOptions {
    // 5.2.6.10..12: "the repetition time for this command must be less than one second".
    std::chrono::nanoseconds keepAlive{std::chrono::seconds(1)};
    // 190E, 190F, 1915, 1920 are "only PA-CONTROL EP": false answers them with 19 (unknown command).
    bool epCommands = true;
    // 1915 / 1920 (and 190F) give "0000 - FFFF" in their header, IEEE REAL bytes in their examples.
    bool epValuesAsReal = true;
    ConditionLayout conditionLayout = ConditionLayout::kBySignificance;
    float temperature = 40.0F;  // 1920: every cooler, degrees Celsius
};

enum class ElementType : std::uint8_t { kInput = 1, kOutput = 2, kFlag = 3 };

struct MoveCondition {
    ElementType type = ElementType::kInput;
    int number = 1;
    bool level = true;  // the axis moves as long as the element has this value
};

class OnlineAxes {
public:
    OnlineAxes(int capacity, OnlineCommandOptions options);

    const OnlineCommandOptions& Options() const { return options_; }

    bool MeasuringMode(int axis) const { return At(axis).measuringMode; }
    void SetMeasuringMode(int axis, bool on) { At(axis).measuringMode = on; }
    bool LimitSwitchMonitoring(int axis) const { return At(axis).limitMonitoring; }
    void SetLimitSwitchMonitoring(int axis, bool on) { At(axis).limitMonitoring = on; }
    // 0AA3: considered in the next movement of the axis (ArmConditionOfMove at its start).
    void SetCondition(int axis, const MoveCondition& condition) { At(axis).nextCondition = condition; }
    std::optional<MoveCondition> PendingCondition(int axis) const { return At(axis).nextCondition; }
    // A movement starts: the condition set for it watches it until it ends.
    void ArmConditionOfMove(int axis);
    // 0A90 / 0A91 start, 0A92 extends: the axis keeps moving until `now` + keepAlive.
    void KeepAlive(int axis, std::chrono::nanoseconds now);
    bool ManualTraverse(int axis) const { return At(axis).keepAliveUntil.has_value(); }
    // 0A93 / 0A9A / 0600 and every other end of the traverse.
    void EndManualTraverse(int axis);
    double MaxFollowingError(int axis) const { return At(axis).maxFollowingError; }

    // Once per controller cycle, axes updated: a manual traverse without keep-alive and a movement whose
    // condition no longer holds brake (ServoAxis::Interrupt); the largest following error is kept;
    // entering ONLINE switches limit switch monitoring on for every axis (5.2.6.22 note).
    void Supervise(std::chrono::nanoseconds now, AxisGroup& axes, const Elements& elements, bool online);
    // Power cycle: everything back to its power-on value.
    void Reset();

private:
    struct Axis {
        bool measuringMode = false;
        bool limitMonitoring = true;
        std::optional<MoveCondition> nextCondition;
        std::optional<MoveCondition> activeCondition;
        bool conditionSeenMoving = false;
        std::optional<std::chrono::nanoseconds> keepAliveUntil;
        double maxFollowingError = 0.0;
    };
    Axis& At(int axis);
    const Axis& At(int axis) const;
    static bool Holds(const MoveCondition& condition, const Elements& elements);
    void Watch(int axis);  // watched_ after a change of the axis's keep-alive or active condition

    OnlineCommandOptions options_;
    std::vector<Axis> axes_;
    // Per axis: a keep-alive or an active condition for Supervise() to follow. Kept beside the records, which
    // the supervision of every cycle then reads only for the axes that have one.
    std::vector<std::uint8_t> watched_;
    bool wasOnline_ = false;
};

}  // namespace pac::sim
