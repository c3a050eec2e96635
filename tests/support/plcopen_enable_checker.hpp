// The PLCopen output rules of a function block with Enable (PLCopen Motion Control Part 1, "Enable" inputs;
// the library's FB_PAC_Diagnosis), checked after every scan:
//   - Valid and Error exclude each other, and so do Busy and Error;
//   - ErrorID <> 0 exactly when Error;
//   - Busy and Valid only while Enable is TRUE;
//   - in a scan that sees Enable FALSE, Valid, Busy, Error and ErrorID are all clear.
// Reports the first violations with the scan as GoogleTest failures.
#pragma once

#include <cstdint>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace pac::test {

struct EnableOutputs {
    bool enable = false;
    bool valid = false;
    bool busy = false;
    bool error = false;
    unsigned errorId = 0;
};

template <class Fb>
EnableOutputs EnableOutputsOf(const Fb& fb) {
    return {fb->ENABLE.value != 0, fb->VALID.value != 0, fb->BUSY.value != 0, fb->ERROR.value != 0,
            static_cast<unsigned>(fb->ERRORID.value)};
}

class PlcOpenEnableChecker {
public:
    explicit PlcOpenEnableChecker(std::string name) : name_(std::move(name)) {}

    void Check(std::int64_t scan, const EnableOutputs& o) {
        Expect(!(o.valid && o.error), scan, "Valid and Error at once", o);
        Expect(!(o.busy && o.error), scan, "Busy and Error at once", o);
        Expect(o.error == (o.errorId != 0), scan, "ErrorID <> 0 not exactly with Error", o);
        Expect(o.enable || (!o.valid && !o.busy && !o.error && o.errorId == 0), scan,
               "Valid, Busy, Error or ErrorID in a scan that saw Enable FALSE", o);
    }

    int Violations() const { return violations_; }

private:
    void Expect(bool ok, std::int64_t scan, const char* rule, const EnableOutputs& o) {
        if (ok || ++violations_ > 5) return;
        std::ostringstream text;
        text << name_ << ", scan " << scan << ": " << rule << " (Enable " << o.enable << ", Valid " << o.valid
             << ", Busy " << o.busy << ", Error " << o.error << ", ErrorID 16#" << std::hex << o.errorId << ")";
        ADD_FAILURE() << text.str();
    }

    std::string name_;
    int violations_ = 0;
};

}  // namespace pac::test
