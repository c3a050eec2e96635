// Building blocks of a CommandResult, shared by the files of CommandExecutor.
#pragma once

#include <cstdint>

#include "pac/sim/command_executor.hpp"
#include "pac/sim/command_table.hpp"
#include "pac/sim/image8.hpp"

namespace pac::sim::reply {

inline CommandResult Ack(std::uint32_t data) { return CommandResult{data, error::kNone, true}; }
inline CommandResult Fail(std::uint16_t number, std::uint32_t data = 0) { return CommandResult{data, number, true}; }
inline std::uint16_t LowWord(std::uint32_t data) { return static_cast<std::uint16_t>(data & 0xFFFF); }
inline std::uint32_t Bit(bool value) { return value ? 1U : 0U; }
inline std::uint32_t Real(double value) { return FloatToBits(static_cast<float>(value)); }

}  // namespace pac::sim::reply
