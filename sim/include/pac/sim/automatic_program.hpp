// A stand-in for the program a PA-CONTROL runs in AUTOMATIC mode: a few assignment lines a test or a scenario
// sets, run in order once per controller cycle while the program runs (status 11), e.g.
//   "R17 := R1 * 2"   "M257 := M1"   "N17 := N1 + 1"   "FW18 := FW2"
// An operand is a flag Mn, a flag word FWn (16 flags, 6.3), an N register Nn or an R register Rn; the right
// side is one operand, optionally followed by + - * / and a number. A flag takes "value is not 0"; an N register
// or a flag word the value rounded to the nearest integer and clamped to its range. Enough to show a round trip
// through the running controller (docs/sim_modes.md), not a PA-CONTROL language.
#pragma once

#include <string>
#include <vector>

#include "pac/sim/elements.hpp"

namespace pac::sim {

class AutomaticProgram {
public:
    AutomaticProgram() = default;
    // std::invalid_argument naming the line and the reason for a line it cannot read, or an element number
    // outside 1..1024 (1..64 for a flag word).
    explicit AutomaticProgram(const std::vector<std::string>& lines);

    bool Empty() const { return lines_.empty(); }
    std::size_t Size() const { return lines_.size(); }
    // Every line once, in order. An element the controller does not have throws std::out_of_range.
    void Run(Elements& elements) const;

private:
    enum class Kind { kFlag, kFlagWord, kInt, kReal };
    struct Operand {
        Kind kind = Kind::kFlag;
        int number = 0;
    };
    struct Line {
        Operand target;
        Operand source;
        char op = 0;  // 0: plain copy
        double constant = 0.0;
    };

    static Line Parse(const std::string& text);
    static double Read(const Elements& elements, const Operand& operand);
    static void Write(Elements& elements, const Operand& operand, double value);

    std::vector<Line> lines_;
};

}  // namespace pac::sim
