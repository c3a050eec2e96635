// The 12 bytes of a module in AUTOMATIC mode (manual 2.6): the flag/register interface instead of the axis
// interface. Master -> PA-CONTROL, module k carries FW k, N k and R k, which the controller copies into its
// flags and registers every cycle; PA-CONTROL -> master carries FW 16+k, N 16+k and R 16+k. Where the manual's
// table leaves the byte layout open, both readings are a controller setting (docs/open_points.md).
#pragma once

#include <cstdint>

#include "pac/sim/elements.hpp"
#include "pac/sim/process_image.hpp"

namespace pac::sim {

// The two readings of the table of 2.6.1 / 2.6.2 (docs/open_points.md#the-module-in-automatic-mode-26).
enum class AutomaticLayout {
    kAxisWidths,     // the widths as printed (the default): FW as a 4-byte field (M1..M16 in its low word,
                     // bytes 2..3), not used 4..5, N 16 bits (signed) 6..7, R 8..11
    kShiftedWidths,  // the other reading: FW bytes 0..1, not used 2..3, N 32 bits 4..7, R 8..11
};

// When the controller copies the modules (2.3.4: "in the action loop of the AUTOMATIC interpreter").
enum class AutomaticExchange {
    kWholeMode,      // every AUTOMATIC status, 10..19 (the library's decision)
    kProgramRunning, // only while the program runs (11); otherwise inputs are not copied, the reply is frozen
};

struct AutomaticModuleConfig {
    AutomaticLayout layout = AutomaticLayout::kAxisWidths;
    AutomaticExchange exchange = AutomaticExchange::kWholeMode;
};

// One module's values. `realBits` is the R register's 32 bits as the module carries them: IEEE REAL, or
// DINT x 1000 in the integer format (2.5.3).
struct AutomaticModuleData {
    std::uint16_t flagWord = 0;
    std::int32_t intRegister = 0;
    std::uint32_t realBits = 0;

    static AutomaticModuleData Decode(const Image12& module, AutomaticLayout layout);
    // In kAxisWidths the N register keeps its low 16 bits (a firmware copying into a 16-bit slot).
    Image12 Encode(AutomaticLayout layout) const;
};

// The copies of 2.6.1 / 2.6.2 for module `k` (1..8).
class AutomaticModule {
public:
    static constexpr int kReplyOffset = 16;  // module k answers with FW / N / R 16+k

    explicit AutomaticModule(AutomaticModuleConfig config = {}) : config_(config) {}

    // FW k := bytes, N k, R k (R converted from the integer format when it is in force).
    void CopyIn(int k, const Image12& toPac, Elements& elements, bool integerFormat) const;
    // The module of FW 16+k, N 16+k, R 16+k.
    Image12 CopyOut(int k, const Elements& elements, bool integerFormat) const;

    const AutomaticModuleConfig& Config() const { return config_; }

private:
    AutomaticModuleConfig config_;
};

// The first flag of flag word `word` (FW 1 = M1..M16, 6.3).
inline int FirstFlagOf(int word) { return 16 * (word - 1) + 1; }

}  // namespace pac::sim
