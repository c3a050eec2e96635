// Per-axis state of the ONLINE commands (see online_axes.hpp and docs/sim_cmd.md).
#include "pac/sim/online_axes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pac::sim {

OnlineAxes::OnlineAxes(int capacity, OnlineCommandOptions options)
    : options_(options),
      axes_(static_cast<std::size_t>(capacity < 0 ? 0 : capacity)),
      watched_(axes_.size(), 0) {
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
    Watch(axis);
}

void OnlineAxes::KeepAlive(int axis, std::chrono::nanoseconds now) {
    At(axis).keepAliveUntil = now + options_.keepAlive;
    Watch(axis);
}

void OnlineAxes::EndManualTraverse(int axis) {
    At(axis).keepAliveUntil.reset();
    Watch(axis);
}

void OnlineAxes::Watch(int axis) {
    const Axis& a = At(axis);
    watched_[static_cast<std::size_t>(axis - 1)] = a.keepAliveUntil.has_value() || a.activeCondition.has_value();
}

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
        const auto k = static_cast<std::size_t>(axis - 1);
        ServoAxis& motion = axes.MotionInRange(axis);
        // Most axes have neither a manual traverse nor a condition: then neither their record (watched_ says
        // so, in one cache line for all axes) nor their motion is asked.
        if (watched_[k]) {
            Axis& a = records[k];
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
            watched_[k] = a.keepAliveUntil.has_value() || a.activeCondition.has_value();
        }
        // The largest following error is never below 0: an axis without one leaves its record alone.
        const double following = motion.FollowingErrorSize();
        if (following > 0.0 && following > records[k].maxFollowingError) records[k].maxFollowingError = following;
    }
}

void OnlineAxes::Reset() {
    for (Axis& a : axes_) a = Axis{};
    watched_.assign(axes_.size(), 0);
    wasOnline_ = false;
}

}  // namespace pac::sim
