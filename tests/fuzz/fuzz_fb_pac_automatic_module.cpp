// libFuzzer target: FB_PAC_AutomaticModule on a 12-byte module (manual 2.6), scan by scan, against whatever the
// input makes the PA-CONTROL's side say (raw bytes, an all-zero module, or nothing new) and whatever another
// writer of the module (FB_PAC_Axis outside AUTOMATIC) leaves in the master's bytes. The input also drives
// every input of the FB: OpStatus (any byte, AUTOMATIC ones often), FlagWord, IntRegister, RealRegister (any
// REAL, NaN and infinities included), IntegerMode, Layout (out-of-range values included), and the PLC cycle.
// Checked after every scan, against the simulator's own reading of the module (AutomaticModuleData, an
// implementation apart from the FB's):
//   - it writes its module only in the AUTOMATIC statuses 10..19 (InExchange exactly then), else the bytes
//     stay as the other writer left them, and the received outputs hold;
//   - what it sends round-trips: FW, N and R read back from the module are the inputs, or, for a value the
//     field cannot carry, the last value that fitted, with Error: nothing out of range goes out silently;
//   - ErrorID <> 0 exactly when Error, ErrorSource LIBRARY exactly then;
//   - the received outputs are the reply's FW, N, R in the layout and number format in force.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

#include "fuzz_bytes.hpp"
#include "fuzz_plc.hpp"
#include "pac/fb_instance.hpp"
#include "pac/sim/automatic_module.hpp"
#include "pac/st_program.hpp"

namespace {

using pac::fuzz::FuzzBytes;
using pac::sim::AutomaticLayout;
using pac::sim::AutomaticModuleData;
using pac::sim::Image12;

std::uint32_t BitsOf(float value) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

// What the FB should put in the R field, worked out apart from it: IEEE bits, or the value x 1000 as DINT
// (2.5.3); nothing for NaN, infinity or a scaled value beyond DINT.
bool RealFits(float value, bool integerMode) {
    if (!std::isfinite(value)) return false;
    if (!integerMode) return true;
    const double scaled = static_cast<double>(value) * 1000.0;
    return scaled >= std::numeric_limits<std::int32_t>::min() && scaled <= std::numeric_limits<std::int32_t>::max();
}

class AutomaticModuleFuzzRun {
public:
    explicit AutomaticModuleFuzzRun(FuzzBytes& in) : in_(in), plc_(in) {
        plc_.Task().AddProgram([this] { Scan(); });
    }

    void Run() {
        plc_.Run(in_, [] { return false; });  // a cyclic FB: nothing to settle after the input
    }

private:
    void Scan() {
        Drive(in_.Byte());
        NextReply(in_.Byte());
        const Image12 before = ToPac();
        const Outputs heldOutputs = Received();
        module_();
        if (trace_) Trace();
        Check(before, heldOutputs);
    }

    void Drive(std::uint8_t bits) {
        auto& fb = module_.Data();
        if ((bits & 0x01U) != 0) {
            const std::uint8_t status = in_.Byte();
            fb.OPSTATUS.value = (status & 0x80U) != 0 ? status : static_cast<std::uint8_t>(10 + status % 10);
        }
        if ((bits & 0x02U) != 0) fb.FLAGWORD.value = in_.Word();
        if ((bits & 0x04U) != 0) {
            const std::uint32_t raw = in_.Dword();
            // Mostly values an INT carries, so the FW4_N2 layout both accepts and refuses.
            fb.INTREGISTER.value = (raw & 0x80000000U) != 0 ? static_cast<std::int32_t>(raw)
                                                             : static_cast<std::int16_t>(raw & 0xFFFFU);
        }
        if ((bits & 0x08U) != 0) fb.REALREGISTER.value = in_.Real();
        if ((bits & 0x10U) != 0) fb.INTEGERMODE.value = in_.Bit() ? TRUE : FALSE;
        if ((bits & 0x20U) != 0) fb.LAYOUT.value = static_cast<E_PAC_AUTOLAYOUT>(in_.Below(3));
        if ((bits & 0x40U) != 0) {  // the other writer of the module (FB_PAC_Axis) leaves its bytes
            for (auto& b : fb.TOPAC.value.table) b = in_.Byte();
        }
    }

    void NextReply(std::uint8_t op) {
        auto& from = module_.Data().FROMPAC.value.table;
        if ((op & 3U) == 1) {
            for (auto& b : from) b = in_.Byte();
        } else if ((op & 3U) == 2) {
            for (auto& b : from) b = 0;  // link lost, controller booting
        }
    }

    struct Outputs {
        std::uint16_t flagWord;
        std::int32_t intRegister;
        std::uint32_t realBits;
        bool operator==(const Outputs& o) const {
            return flagWord == o.flagWord && intRegister == o.intRegister && realBits == o.realBits;
        }
    };

    Outputs Received() {
        const auto& fb = module_.Data();
        return {fb.RECEIVEDFLAGWORD.value, fb.RECEIVEDINTREGISTER.value, BitsOf(fb.RECEIVEDREALREGISTER.value)};
    }

    Image12 ToPac() {
        Image12 bytes{};
        for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = module_.Data().TOPAC.value.table[i];
        return bytes;
    }

    void Check(const Image12& before, const Outputs& heldOutputs) {
        const auto& fb = module_.Data();
        const bool automatic = fb.OPSTATUS.value >= 10 && fb.OPSTATUS.value <= 19;
        if ((fb.INEXCHANGE.value != 0) != automatic) Fail("InExchange is not OpStatus in 10..19");
        if ((fb.ERRORID.value != 0) != (fb.ERROR.value != 0)) Fail("ErrorID <> 0 is not Error");
        const auto wantedSource = fb.ERROR.value != 0 ? E_PAC_ERRORSOURCE__PAC_ERRSRC_LIBRARY : E_PAC_ERRORSOURCE__PAC_ERRSRC_NONE;
        if (fb.ERRORSOURCE.value != wantedSource) Fail("ErrorSource does not go with Error");
        if (!automatic) {
            if (ToPac() != before) Fail("the module was written outside AUTOMATIC");
            if (!(Received() == heldOutputs)) Fail("the received outputs changed outside AUTOMATIC");
            if (fb.ERROR.value != 0) Fail("Error outside AUTOMATIC, where nothing is sent");
            return;
        }
        CheckSent();
        CheckReceived();
    }

    // What the module carries now against the inputs; `sent_` is the last value of each field that fitted.
    void CheckSent() {
        const auto& fb = module_.Data();
        const AutomaticLayout layout = LayoutInForce();
        const AutomaticModuleData onWire = AutomaticModuleData::Decode(ToPac(), layout);
        if (onWire.Encode(layout) != ToPac()) Fail("the module's unused bytes are not 0");
        if (onWire.flagWord != fb.FLAGWORD.value) Fail("FW on the module is not FlagWord");

        const std::int32_t n = fb.INTREGISTER.value;
        const bool intFits = layout == AutomaticLayout::kShiftedWidths || (n >= -32768 && n <= 32767);
        if (intFits) sentInt_ = n;
        if (onWire.intRegister != sentInt_) Fail("N on the module is neither IntRegister nor the last that fitted");

        const float r = fb.REALREGISTER.value;
        const bool integerMode = fb.INTEGERMODE.value != 0;
        const bool realFits = RealFits(r, integerMode);
        if (realFits) {
            CheckRealEncoding(onWire.realBits, r, integerMode);
        } else if (onWire.realBits != sentRealBits_) {
            Fail("R on the module is neither RealRegister nor the last that fitted");
        }
        sentRealBits_ = onWire.realBits;
        if ((fb.ERROR.value != 0) != (!intFits || !realFits)) Fail("Error is not 'a value does not fit its field'");
    }

    void CheckRealEncoding(std::uint32_t bits, float r, bool integerMode) {
        if (!integerMode) {
            if (bits != BitsOf(r)) Fail("R on the module is not RealRegister's IEEE bits");
            return;
        }
        const double scaled = static_cast<double>(r) * 1000.0;
        if (std::fabs(static_cast<double>(static_cast<std::int32_t>(bits)) - scaled) > 0.5) {
            Fail("R on the module is not RealRegister x 1000 to the nearest DINT");
        }
    }

    void CheckReceived() {
        const auto& fb = module_.Data();
        Image12 reply{};
        for (std::size_t i = 0; i < reply.size(); ++i) reply[i] = fb.FROMPAC.value.table[i];
        const AutomaticModuleData wanted = AutomaticModuleData::Decode(reply, LayoutInForce());
        if (fb.RECEIVEDFLAGWORD.value != wanted.flagWord) Fail("ReceivedFlagWord is not the reply's FW");
        if (fb.RECEIVEDINTREGISTER.value != wanted.intRegister) Fail("ReceivedIntRegister is not the reply's N");
        const float got = fb.RECEIVEDREALREGISTER.value;
        if (fb.INTEGERMODE.value == 0) {
            if (BitsOf(got) != wanted.realBits) Fail("ReceivedRealRegister is not the reply's IEEE bits");
            return;
        }
        // DINT / 1000 rounded to REAL: within half a REAL step of the exact quotient.
        const double exact = static_cast<double>(static_cast<std::int32_t>(wanted.realBits)) / 1000.0;
        if (std::fabs(static_cast<double>(got) - exact) > std::fabs(exact) * 1e-7 + 1e-9) {
            Fail("ReceivedRealRegister is not the reply's DINT / 1000");
        }
    }

    // Every Layout but the library's default reads as the widths printed (the FB's ELSE).
    AutomaticLayout LayoutInForce() {
        return module_.Data().LAYOUT.value == E_PAC_AUTOLAYOUT__PAC_AUTOLAYOUT_FW2_N4 ? AutomaticLayout::kShiftedWidths
                                                                                     : AutomaticLayout::kAxisWidths;
    }

    void Fail(const char* rule) {
        pac::fuzz::Violation("scan " + std::to_string(plc_.Task().ScanCount()) + ": FB_PAC_AutomaticModule: " + rule);
    }

    void Trace() {
        const auto& fb = module_.Data();
        const Image12 to = ToPac();
        std::fprintf(stderr, "scan %lld: OpStatus %u FW %04X N %d R %08X IntMode %d Layout %d | ToPac",
                     static_cast<long long>(plc_.Task().ScanCount()), fb.OPSTATUS.value, fb.FLAGWORD.value,
                     fb.INTREGISTER.value, BitsOf(fb.REALREGISTER.value), fb.INTEGERMODE.value,
                     static_cast<int>(fb.LAYOUT.value));
        for (std::uint8_t b : to) std::fprintf(stderr, " %02X", b);
        std::fprintf(stderr, " | InEx %d Err %d ErrID %04X\n", fb.INEXCHANGE.value, fb.ERROR.value, fb.ERRORID.value);
    }

    FuzzBytes& in_;
    pac::fuzz::FuzzPlc plc_;
    pac::FbInstance<FB_PAC_AUTOMATICMODULE> module_ = PAC_FB(FB_PAC_AUTOMATICMODULE);
    std::int32_t sentInt_ = 0;        // the FB's N field starts at 0
    std::uint32_t sentRealBits_ = 0;  // and its R field
    bool trace_ = pac::fuzz::TraceWanted();
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return pac::fuzz::RunOneInput<AutomaticModuleFuzzRun>(data, size);
}
