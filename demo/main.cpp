// The main job: runs ST compiled by the selected backend, scan by scan on the simulated clock, and
// prints a timeline of every scan in which an output changed.
#include <cstdio>

#include "pac/st_program.hpp"
#include "pac/fb_instance.hpp"
#include "pac/plc_task.hpp"
#include "pac/sim_clock.hpp"

int main() {
    using namespace std::chrono_literals;
    pac::SimClock clock;
    pac::PlcTask task(clock, 10ms);
    auto blink = PAC_FB(FB_DEMOBLINK);
    bool lastLamp = false;
    task.AddProgram([&] {
        blink->ENABLE.value = task.ScanCount() < 30;
        blink();
    });
    std::printf("%6s %8s %7s %5s %8s\n", "scan", "t [ms]", "Enable", "Lamp", "Toggles");
    for (int scan = 0; scan < 36; ++scan) {
        task.Scan();
        bool lamp = blink->LAMP.value;
        if (scan == 0 || lamp != lastLamp) {
            std::printf("%6lld %8lld %7d %5d %8u\n", static_cast<long long>(task.ScanCount()),
                        static_cast<long long>(clock.Now().count() / 1000000), blink->ENABLE.value, lamp,
                        static_cast<unsigned>(blink->TOGGLES.value));
        }
        lastLamp = lamp;
    }
    return 0;
}
