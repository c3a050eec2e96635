// libFuzzer target: FB_PAC_AutomaticModule on a 12-byte module (manual 2.6), scan by scan, against whatever the
// input makes the PA-CONTROL's side say (raw bytes, an all-zero module, or nothing new) and whatever another
// writer of the module (FB_PAC_Axis outside AUTOMATIC) leaves in the master's bytes. The input also drives
// every input of the FB: OpStatus (any byte, AUTOMATIC ones often), FlagWord, IntRegister, RealRegister (any
// REAL, NaN and infinities included), IntegerMode, Layout (out-of-range values included), AxisOwnsModule, and
// the PLC cycle. Checked after every scan, against the simulator's own reading of the module
// (AutomaticModuleData, an implementation apart from the FB's):
//   - it writes its module only in the AUTOMATIC statuses 10..19 (InExchange exactly then), else the bytes
//     stay as the other writer left them, and the received outputs hold; except once, in the first scan with
//     a status neither AUTOMATIC nor 0 after it wrote: then the module is all zero if it still held the FB's
//     own image and AxisOwnsModule was FALSE (2.7.1: outside AUTOMATIC the bytes are a control word);
//   - what it sends round-trips: FW, N and R read back from the module are the inputs, or, for a value the
//     field cannot carry, the last value that fitted, with Error: nothing out of range goes out silently, and
//     nothing cut or in the wrong number format (a kept value the layout or format in force cannot carry: 0);
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
#include "real_bits.hpp"

namespace {

using pac::fuzz::FuzzBytes;
using pac::sim::AutomaticLayout;
using pac::sim::AutomaticModuleData;
using pac::sim::Image12;
using pac::test::BitsOf;

// What the FB should put in the R field, worked out apart from it: IEEE bits, or the value x 1000 as DINT
// (2.5.3); nothing for NaN, infinity or a scaled value beyond DINT.
bool RealFits(float value, bool integerMode) {
    if (!std::isfinite(value)) return false;
    if (!integerMode) return true;
    const double scaled = static_cast<double>(value) * 1000.0;
    return scaled >= std::numeric_limits<std::int32_t>::min() && scaled <= std::numeric_limits<std::int32_t>::max();
}

// The REAL the library makes of a received IEEE pattern (F_PAC_DwordToReal, docs/ieee754.md): the value itself
// when finite, the largest REAL of its sign for an infinity, 0.0 for a NaN; never a non-finite REAL.
float FiniteRealOf(std::uint32_t bits) {
    const float value = pac::test::FloatOf(bits);
    if (std::isnan(value)) return 0.0f;
    if (std::isinf(value)) return std::copysign(std::numeric_limits<float>::max(), value);
    return value;
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
        const std::uint8_t op = in_.Byte();
        NextReply(op);
        // From a bit of the reply's byte that reads no more input, so the corpus kept keeps its meaning.
        module_.Data().AXISOWNSMODULE.value = (op & 0x04U) != 0 ? TRUE : FALSE;
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
        if ((bits & 0x20U) != 0) SetLayoutNumber(in_.Below(3));
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
        const std::uint8_t status = fb.OPSTATUS.value;
        if (status != 0) knownStatus_ = status;
        if (!automatic) {
            Image12 expected = before;
            if (holding_ && (knownStatus_ < 10 || knownStatus_ > 19)) {
                holding_ = false;
                if (fb.AXISOWNSMODULE.value == 0 && before == written_) expected = Image12{};
            }
            if (ToPac() != expected) {
                Fail("outside AUTOMATIC the module is not as left, or not cleared when AUTOMATIC ended");
            }
            if (!(Received() == heldOutputs)) Fail("the received outputs changed outside AUTOMATIC");
            if (fb.ERROR.value != 0) Fail("Error outside AUTOMATIC, where nothing is sent");
            return;
        }
        CheckSent();
        CheckReceived();
        written_ = ToPac();
        holding_ = true;
    }

    // What the module carries now against the inputs and the last values that fitted.
    void CheckSent() {
        const auto& fb = module_.Data();
        const AutomaticLayout layout = LayoutInForce();
        const AutomaticModuleData onWire = AutomaticModuleData::Decode(ToPac(), layout);
        if (onWire.Encode(layout) != ToPac()) Fail("the module's unused bytes are not 0");
        if (onWire.flagWord != fb.FLAGWORD.value) Fail("FW on the module is not FlagWord");

        auto intFitsLayout = [layout](std::int32_t n) {
            return layout == AutomaticLayout::kShiftedWidths || (n >= -32768 && n <= 32767);
        };
        const bool intFits = intFitsLayout(fb.INTREGISTER.value);
        if (intFits) sentInt_ = fb.INTREGISTER.value;
        // Kept from the other layout, which this one cannot carry: 0, never cut to 16 bits.
        const std::int32_t n = intFitsLayout(sentInt_) ? sentInt_ : 0;
        if (onWire.intRegister != n) Fail("N on the module is neither IntRegister nor the last that fitted");

        const bool integerMode = fb.INTEGERMODE.value != 0;
        const bool realFits = RealFits(fb.REALREGISTER.value, integerMode);
        if (realFits) sentReal_ = fb.REALREGISTER.value;
        // Kept from the other format, which this one cannot carry: 0.
        CheckRealEncoding(onWire.realBits, RealFits(sentReal_, integerMode) ? sentReal_ : 0.0f, integerMode);
        if ((fb.ERROR.value != 0) != (!intFits || !realFits)) Fail("Error is not 'a value does not fit its field'");
    }

    void CheckRealEncoding(std::uint32_t bits, float r, bool integerMode) {
        if (!integerMode) {
            // -0.0 goes out as 16#00000000 (F_PAC_RealToDword, docs/ieee754.md): the controller sees 0 either way.
            if (bits != (r == 0.0f ? 0U : BitsOf(r))) Fail("R on the module is not the IEEE bits of RealRegister or the last that fitted");
            return;
        }
        const double scaled = static_cast<double>(r) * 1000.0;
        if (std::fabs(static_cast<double>(static_cast<std::int32_t>(bits)) - scaled) > 0.5) {
            Fail("R on the module is not RealRegister or the last that fitted x 1000 to the nearest DINT");
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
            if (BitsOf(got) != BitsOf(FiniteRealOf(wanted.realBits))) Fail("ReceivedRealRegister is not the reply's REAL");
            return;
        }
        // DINT / 1000 rounded to REAL: within half a REAL step of the exact quotient.
        const double exact = static_cast<double>(static_cast<std::int32_t>(wanted.realBits)) / 1000.0;
        if (std::fabs(static_cast<double>(got) - exact) > std::fabs(exact) * 1e-7 + 1e-9) {
            Fail("ReceivedRealRegister is not the reply's DINT / 1000");
        }
    }

    // Layout as a number: 2 is no E_PAC_AutoLayout value, which C++ may not hold in the enumeration type (the
    // ST's C holds any). Every number but the library's default reads as the widths printed (the FB's ELSE).
    void SetLayoutNumber(std::uint32_t number) {
        static_assert(sizeof module_.Data().LAYOUT.value == sizeof number, "an enumeration is 32 bits here");
        std::memcpy(&module_.Data().LAYOUT.value, &number, sizeof number);
    }
    std::uint32_t LayoutNumber() {
        std::uint32_t number;
        std::memcpy(&number, &module_.Data().LAYOUT.value, sizeof number);
        return number;
    }
    AutomaticLayout LayoutInForce() {
        return LayoutNumber() == E_PAC_AUTOLAYOUT__PAC_AUTOLAYOUT_FW2_N4 ? AutomaticLayout::kShiftedWidths
                                                                        : AutomaticLayout::kAxisWidths;
    }

    void Fail(const char* rule) {
        pac::fuzz::Violation("scan " + std::to_string(plc_.Task().ScanCount()) + ": FB_PAC_AutomaticModule: " + rule);
    }

    void Trace() {
        const auto& fb = module_.Data();
        const Image12 to = ToPac();
        std::fprintf(stderr, "scan %lld: OpStatus %u FW %04X N %d R %08X IntMode %d Layout %u | ToPac",
                     static_cast<long long>(plc_.Task().ScanCount()), fb.OPSTATUS.value, fb.FLAGWORD.value,
                     fb.INTREGISTER.value, BitsOf(fb.REALREGISTER.value), fb.INTEGERMODE.value, LayoutNumber());
        for (std::uint8_t b : to) std::fprintf(stderr, " %02X", b);
        std::fprintf(stderr, " | InEx %d Err %d ErrID %04X\n", fb.INEXCHANGE.value, fb.ERROR.value, fb.ERRORID.value);
    }

    FuzzBytes& in_;
    pac::fuzz::FuzzPlc plc_;
    pac::FbInstance<FB_PAC_AUTOMATICMODULE> module_ = PAC_FB(FB_PAC_AUTOMATICMODULE);
    // The last values that fitted, which the fields carry in the layout and number format in force; 0 at first.
    std::int32_t sentInt_ = 0;
    float sentReal_ = 0.0f;
    // The hand-over when AUTOMATIC ends: the last status but 0, and the FB's image while it is on the module.
    std::uint8_t knownStatus_ = 0;
    bool holding_ = false;
    Image12 written_{};
    bool trace_ = pac::fuzz::TraceWanted();
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return pac::fuzz::RunOneInput<AutomaticModuleFuzzRun>(data, size);
}
