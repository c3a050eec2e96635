// pac-sim's time: the steady clock's time since pac-sim started, the simulated controllers' "now".
#pragma once

#include <chrono>

namespace pac::pacsim {

class WallClock {
public:
    std::chrono::nanoseconds Now() const {
        return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start_);
    }

private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace pac::pacsim
