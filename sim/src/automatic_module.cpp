// The flag/register module of AUTOMATIC mode (see automatic_module.hpp).
#include "pac/sim/automatic_module.hpp"

#include <cmath>
#include <limits>

#include "pac/sim/axis_module.hpp"
#include "pac/sim/image8.hpp"

namespace pac::sim {

AutomaticModuleData AutomaticModuleData::Decode(const Image12& module, AutomaticLayout layout) {
    AutomaticModuleData d;
    if (layout == AutomaticLayout::kShiftedWidths) {
        d.flagWord = ReadWordAt(module, 0);
        d.intRegister = static_cast<std::int32_t>(ReadDword(module, 4));
    } else {
        d.flagWord = ReadWordAt(module, 2);
        d.intRegister = static_cast<std::int16_t>(ReadWordAt(module, 6));
    }
    d.realBits = ReadDword(module, 8);
    return d;
}

Image12 AutomaticModuleData::Encode(AutomaticLayout layout) const {
    Image12 module{};
    if (layout == AutomaticLayout::kShiftedWidths) {
        WriteWordAt(module, 0, flagWord);
        WriteDword(module, 4, static_cast<std::uint32_t>(intRegister));
    } else {
        WriteWordAt(module, 2, flagWord);
        WriteWordAt(module, 6, static_cast<std::uint16_t>(static_cast<std::uint32_t>(intRegister) & 0xFFFFu));
    }
    WriteDword(module, 8, realBits);
    return module;
}

void AutomaticModule::CopyIn(int k, const Image12& toPac, Elements& elements, bool integerFormat) const {
    const AutomaticModuleData d = AutomaticModuleData::Decode(toPac, config_.layout);
    elements.flags.SetWord(FirstFlagOf(k), d.flagWord);
    elements.intRegisters.SetInt(k, d.intRegister);
    elements.realRegisters.SetReal(k, static_cast<float>(DecodeModulePosition(d.realBits, integerFormat)));
}

Image12 AutomaticModule::CopyOut(int k, const Elements& elements, bool integerFormat) const {
    const int n = kReplyOffset + k;
    AutomaticModuleData d;
    d.flagWord = elements.flags.Word(FirstFlagOf(n));
    d.intRegister = elements.intRegisters.GetInt(n);
    d.realBits = EncodeModulePosition(static_cast<double>(elements.realRegisters.GetReal(n)), integerFormat);
    return d.Encode(config_.layout);
}

}  // namespace pac::sim
