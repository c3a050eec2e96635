// Typed access to the PLCopen pins every command FB of the library has: Execute (and FB_PAC_Axis's jog
// inputs), Busy, Done, Error, ErrorID, CommandAborted where the FB has it, and Timeout / EndTimeout.
// The generated C structs hold them as IEC values (BOOL bytes, WORD, TIME); tests read them here as
// bool, std::uint32_t and std::chrono, the same way for every FB, and an FB without a pin simply reads
// FALSE (no CommandAborted) or nothing (no EndTimeout).
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <ostream>
#include <type_traits>
#include <utility>

#include "pac/fb_instance.hpp"
#include "pac/iec_time.hpp"

namespace pac::test {

namespace pins {
template <class Fb, class = void>
struct HasCommandAborted : std::false_type {};
template <class Fb>
struct HasCommandAborted<Fb, std::void_t<decltype(std::declval<const Fb&>().COMMANDABORTED)>> : std::true_type {};

template <class Fb, class = void>
struct HasDone : std::false_type {};
template <class Fb>
struct HasDone<Fb, std::void_t<decltype(std::declval<const Fb&>().DONE)>> : std::true_type {};

template <class Fb, class = void>
struct HasJog : std::false_type {};
template <class Fb>
struct HasJog<Fb, std::void_t<decltype(std::declval<const Fb&>().JOGPOSITIVE),
                              decltype(std::declval<const Fb&>().JOGNEGATIVE)>> : std::true_type {};

template <class Fb, class = void>
struct HasEndTimeout : std::false_type {};
template <class Fb>
struct HasEndTimeout<Fb, std::void_t<decltype(std::declval<const Fb&>().ENDTIMEOUT)>> : std::true_type {};

template <class Fb>
const Fb& Struct(const Fb& fb) {
    return fb;
}
template <class Fb>
const Fb& Struct(const pac::FbInstance<Fb>& fb) {
    return *fb.operator->();
}
}  // namespace pins

// The outputs one scan left.
struct PlcOpenOutputs {
    bool busy = false;
    bool done = false;
    bool error = false;
    bool aborted = false;  // CommandAborted
    std::uint32_t errorId = 0;

    bool Final() const { return done || error || aborted; }
    int Shown() const { return int{busy} + int{done} + int{error} + int{aborted}; }
    // One letter per scan for traces: '-' none, 'B' Busy, 'D' Done, 'E' Error, 'A' CommandAborted,
    // '!' several at once.
    char Letter() const {
        if (Shown() > 1) return '!';
        return busy ? 'B' : done ? 'D' : error ? 'E' : aborted ? 'A' : '-';
    }
    friend bool operator==(const PlcOpenOutputs& a, const PlcOpenOutputs& b) {
        return a.busy == b.busy && a.done == b.done && a.error == b.error && a.aborted == b.aborted &&
               a.errorId == b.errorId;
    }
    friend bool operator!=(const PlcOpenOutputs& a, const PlcOpenOutputs& b) { return !(a == b); }
};

inline std::ostream& operator<<(std::ostream& out, const PlcOpenOutputs& o) {
    const std::pair<bool, const char*> names[] = {
        {o.busy, "Busy"}, {o.done, "Done"}, {o.error, "Error"}, {o.aborted, "CommandAborted"}};
    const char* separator = "";
    for (const auto& [shown, name] : names) {
        if (!shown) continue;
        out << separator << name;
        separator = " + ";
    }
    if (o.Shown() == 0) out << "no final output, not Busy";
    if (o.errorId != 0) out << ", ErrorID 16#" << std::hex << std::uppercase << o.errorId << std::dec << std::nouppercase;
    return out;
}

// Accepts the generated struct or its pac::FbInstance.
template <class Fb>
PlcOpenOutputs OutputsOf(const Fb& instance) {
    const auto& fb = pins::Struct(instance);
    using Struct = std::decay_t<decltype(fb)>;
    PlcOpenOutputs o;
    o.busy = fb.BUSY.value != 0;
    if constexpr (pins::HasDone<Struct>::value) o.done = fb.DONE.value != 0;  // MC_MoveVelocity has none
    o.error = fb.ERROR.value != 0;
    if constexpr (pins::HasCommandAborted<Struct>::value) o.aborted = fb.COMMANDABORTED.value != 0;
    o.errorId = fb.ERRORID.value;
    return o;
}

template <class Fb>
bool IsFinal(const Fb& fb) {
    return OutputsOf(fb).Final();
}

// The inputs that start a job and hold its final output: Execute, and FB_PAC_Axis's jog inputs.
struct CommandInputs {
    bool execute = false;
    bool jogPositive = false;
    bool jogNegative = false;

    static constexpr unsigned kExecute = 1, kJogPositive = 2, kJogNegative = 4;

    bool Any() const { return execute || jogPositive || jogNegative; }
    // The inputs TRUE, as kExecute | kJogPositive | kJogNegative bits.
    unsigned Mask() const {
        return (execute ? kExecute : 0U) | (jogPositive ? kJogPositive : 0U) | (jogNegative ? kJogNegative : 0U);
    }
    unsigned RoseMaskSince(const CommandInputs& before) const { return Mask() & ~before.Mask(); }
    // One of them rose since `before`: a new job may begin in this scan.
    bool RoseSince(const CommandInputs& before) const {
        return (execute && !before.execute) || (jogPositive && !before.jogPositive) ||
               (jogNegative && !before.jogNegative);
    }
};

template <class Fb>
CommandInputs InputsOf(const Fb& instance) {
    const auto& fb = pins::Struct(instance);
    using Struct = std::decay_t<decltype(fb)>;
    CommandInputs in;
    in.execute = fb.EXECUTE.value != 0;
    if constexpr (pins::HasJog<Struct>::value) {
        in.jogPositive = fb.JOGPOSITIVE.value != 0;
        in.jogNegative = fb.JOGNEGATIVE.value != 0;
    }
    return in;
}

template <class Fb>
std::chrono::nanoseconds TimeoutOf(const Fb& instance) {
    return pac::FromIecTime(pins::Struct(instance).TIMEOUT.value);
}

// For FB_PAC_Cmd and the FBs built on it: EndTimeout where the FB has one; the others hand their
// Timeout on as FB_PAC_Cmd's EndTimeout (docs/fb/element_commands.md, parameter_axis_commands.md).
template <class Fb>
std::chrono::nanoseconds CommandEndTimeoutOf(const Fb& instance) {
    const auto& fb = pins::Struct(instance);
    using Struct = std::decay_t<decltype(fb)>;
    if constexpr (pins::HasEndTimeout<Struct>::value) {
        return pac::FromIecTime(fb.ENDTIMEOUT.value);
    } else {
        return TimeoutOf(instance);
    }
}

}  // namespace pac::test
