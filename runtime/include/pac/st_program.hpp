// Includes the C interface of the translated ST program (POUS.h) into C++. MATIEC's POUS.h has no
// extern "C" guard of its own, so C++ code includes it through this header, whichever backend built it.
#pragma once

extern "C" {
#include "POUS.h"
}
