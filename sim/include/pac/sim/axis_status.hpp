// The values cmd_get_status_axis (1910, manual 5.2.4.22) reports for an axis.
#pragma once

#include <cstdint>

namespace pac::sim {

enum class AxisStatus : std::uint16_t {
    kInPosition = 0,   // standing, in position
    kMoving = 1,
    kStopped = 2,      // standing still, was stopped
    kMalfunction = 4,  // standing still, with malfunction
};

}  // namespace pac::sim
