#include "scenario.hpp"

namespace pac::scenario {

const std::vector<std::string>& McCommandNames() {
    static const std::vector<std::string> names = {"MC_Home", "MC_MoveAbsolute", "MC_MoveRelative", "MC_Halt",
                                                   "MC_Stop"};
    return names;
}

const char* ToString(FaultKind kind) {
    switch (kind) {
        case FaultKind::kPowerCycle:
            return "power_cycle";
        case FaultKind::kFreezeLink:
            return "freeze_link";
        case FaultKind::kThawLink:
            return "thaw_link";
        case FaultKind::kZeroLink:
            return "zero_link";
        case FaultKind::kSystemError:
            return "system_error";
        case FaultKind::kSetInput:
            return "set_input";
    }
    return "?";
}

const char* ToString(LinkSide side) {
    switch (side) {
        case LinkSide::kToPac:
            return "to_pac";
        case LinkSide::kFromPac:
            return "from_pac";
        case LinkSide::kBoth:
            return "both";
    }
    return "?";
}

}  // namespace pac::scenario
