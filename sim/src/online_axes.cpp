// Per-axis state of the ONLINE commands (see online_axes.hpp and docs/sim_cmd.md).
#include "pac/sim/online_axes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pac::sim {

OnlineAxes::OnlineAxes(int capacity, OnlineCommandOptions options)
    : options_(options), axes_(static_cast<std::size_t>(capacity < 0 ? 0 : capacity)) {
    if (options_.keepAlive <= std::chrono::nanoseconds::zero()) {
        throw std::invalid_argument("OnlineAxes: the keep-alive time must be > 0");
    }
}

OnlineAxes::Axis& OnlineAxes::At(int axis) {
    if (axis < 1 || axis > static_cast<int>(axes_.size())) {
        throw std::out_of_range("OnlineAxes: no axis " + std::to_string(axis));
    }
    return axes_[static_cast<std::size_t>(axis - 1)];
}

const OnlineAxes::Axis& OnlineAxes::At(int axis) const {
    if (axis < 1 || axis > static_cast<int>(axes_.size())) {
        throw std::out_of_range("OnlineAxes: no axis " + std::to_string(axis));
    }
    return axes_[static_cast<std::size_t>(axis - 1)];
}

void OnlineAxes::ArmConditionOfMove(int axis) {
    Axis& a = At(axis);
    a.activeCondition = a.nextCondition;
    a.nextCondition.reset();
    a.conditionSeenMoving = false;
}

void OnlineAxes::KeepAlive(int axis, std::chrono::nanoseconds now) { At(axis).keepAliveUntil = now + options_.keepAlive; }

bool OnlineAxes::Holds(const MoveCondition& condition, const Elements& elements) {
    const BitBank& bank = condition.type == ElementType::kInput    ? elements.inputs
                          : condition.type == ElementType::kOutput ? elements.outputs
                                                                   : elements.flags;
    return bank.Contains(condition.number) && bank.Get(condition.number) == condition.level;
}

void OnlineAxes::Supervise(std::chrono::nanoseconds now, AxisGroup& axes, const Elements& elements, bool online) {
    if (online && !wasOnline_) {
        for (Axis& a : axes_) a.limitMonitoring = true;
    }
    wasOnline_ = online;
    const int count = std::min(static_cast<int>(axes_.size()), axes.Capacity());
    Axis* const records = axes_.data();  // count records and axes: neither looked up with a check per axis
    for (int axis = 1; axis <= count; ++axis) {
        Axis& a = records[axis - 1];
        ServoAxis& motion = axes.MotionInRange(axis);
        // Most axes have neither a manual traverse nor a condition: then their motion is not asked.
        if (a.keepAliveUntil || a.activeCondition) {
            const bool running = motion.JobActive() || motion.Moving();
            if (a.keepAliveUntil) {
                if (!running) {
                    a.keepAliveUntil.reset();
                } else if (now >= *a.keepAliveUntil) {
                    // 5.2.6.10: "If this command is not issued, the respective axis stays still."
                    motion.Interrupt(now);
                    a.keepAliveUntil.reset();
                }
            }
            if (a.activeCondition) {
                if (running) {
                    a.conditionSeenMoving = true;
                    if (!Holds(*a.activeCondition, elements)) {
                        motion.Interrupt(now);  // 5.2.6.23: switching over the element terminates the movement
                        a.activeCondition.reset();
                    }
                } else if (a.conditionSeenMoving) {
                    a.activeCondition.reset();
                }
            }
        }
        const double following = motion.FollowingErrorSize();
        if (following > a.maxFollowingError) a.maxFollowingError = following;
    }
}

void OnlineAxes::Reset() {
    for (Axis& a : axes_) a = Axis{};
    wasOnline_ = false;
}

}  // namespace pac::sim
