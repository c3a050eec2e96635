// The two C globals that the generated code's interface requires the harness to define. They are
// the only globals of the runtime; SimClock owns the value of __CURRENT_TIME.
#include "pac/iec_time.hpp"

extern "C" {
TIME __CURRENT_TIME = {0, 0};
BOOL __DEBUG = 0;
}
