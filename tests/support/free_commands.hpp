// The commands the free-program tests send (CMD interface and RS232 port alike), each with values no other
// command of the test used, so that the controller's ledger tells whose command it executed: writes of N1..N4
// with a serial number, reads of N100..N103 (which hold kFreeReadBase + n and are never written, so an answer
// names its register), absolute moves of axis 1 or 2 to a position of their own, stops of an axis, status reads.
#pragma once

#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "pac/sim/cmd_frame.hpp"
#include "pac/sim/command_table.hpp"
#include "pac/sim/exchange_log.hpp"
#include "real_bits.hpp"

namespace pac::test {

struct FreeCommand {
    std::uint16_t code = 0;
    std::uint16_t param = 0;
    std::uint32_t data = 0;

    bool operator==(const FreeCommand& o) const { return code == o.code && param == o.param && data == o.data; }
};

constexpr int kFreeReadRegisters = 100;  // N100..N103
constexpr std::int32_t kFreeReadBase = 70000;

inline std::string Describe(const FreeCommand& c) {
    std::ostringstream out;
    out << std::hex << std::uppercase << c.code << " parameter " << std::dec << c.param << " data " << c.data;
    return out.str();
}

// The answer a read of the preset registers must carry: the register's own value.
inline bool IsFreeRead(const FreeCommand& c) { return c.code == pac::sim::code::kGetIntReg; }
inline std::uint32_t FreeReadAnswer(const FreeCommand& c) {
    return static_cast<std::uint32_t>(kFreeReadBase + c.param - kFreeReadRegisters);
}

// The next command of a test, drawn from `random`; `serial` counts the commands drawn so far.
inline FreeCommand NextFreeCommand(std::mt19937_64& random, int& serial) {
    namespace code = pac::sim::code;
    auto draw = [&random](std::uint32_t n) { return std::uniform_int_distribution<std::uint32_t>(0, n - 1)(random); };
    ++serial;
    switch (draw(8)) {
        case 0:
        case 1:
            return {code::kPutIntReg, static_cast<std::uint16_t>(1 + draw(4)), static_cast<std::uint32_t>(serial)};
        case 2:
        case 3:
            return {code::kGetIntReg, static_cast<std::uint16_t>(kFreeReadRegisters + draw(4)), 0};
        case 4:
        case 5:
            return {code::kPosAxisAbsolute, static_cast<std::uint16_t>(1 + draw(2)),
                    BitsOf(static_cast<float>(serial) * 0.125F + 0.0625F)};
        case 6:
            return {code::kStopAxis, static_cast<std::uint16_t>(1 + draw(2)), 0};
        default:
            return {code::kGetState, 0, 0};
    }
}

// The commands a controller took on its CMD interface (a SEND flag change it recognised), oldest first, read
// on from its exchange log (which must keep every record of the test); each may be claimed by one FB's Done.
class CmdLedger {
public:
    // Reads the records added since the last call.
    const std::vector<FreeCommand>& Read(const pac::sim::ExchangeLog& log) {
        const auto& records = log.Records();
        for (; read_ < records.size(); ++read_) {
            if (!records[read_].newCommand) continue;
            const auto frame = pac::sim::CommandFrame::Decode(records[read_].toPac.Cmd());
            commands_.push_back({frame.code, frame.parameter, frame.data});
            claimed_.push_back(false);
            records_.push_back(read_);
        }
        return commands_;
    }
    std::size_t Size() const { return commands_.size(); }
    // Claims the first unclaimed `command` from index `from` on; false if there is none.
    bool Claim(std::size_t from, const FreeCommand& command) { return ClaimIndex(from, command) >= 0; }
    // The same, with the index of the command claimed (-1: none).
    long ClaimIndex(std::size_t from, const FreeCommand& command) {
        for (std::size_t k = from; k < commands_.size(); ++k) {
            if (claimed_[k] || !(commands_[k] == command)) continue;
            claimed_[k] = true;
            return static_cast<long>(k);
        }
        return -1;
    }
    // The exchange log's record of the cycle that took command `k`.
    std::size_t RecordOf(std::size_t k) const { return records_[k]; }
    // "; 906 parameter 1 data 5; A87 ...": the commands from index `from` on, for a failure's text.
    std::string DescribeFrom(std::size_t from) const {
        std::string text;
        for (std::size_t k = from; k < commands_.size(); ++k) text += "; " + Describe(commands_[k]);
        return text;
    }

private:
    std::vector<FreeCommand> commands_;
    std::vector<bool> claimed_;
    std::vector<std::size_t> records_;
    std::size_t read_ = 0;
};

// What the controller reported for a move command (0A87, 0A89) it took in the log's record `taken`: the
// acknowledgement (RECEIVE = its SEND flag, no command error, still processing) with the start position, and the
// END OF PROCESSING report with the end position, both before the next command it took.
struct MoveReport {
    bool acknowledged = false;
    bool ended = false;
    float start = 0.0F;
    float end = 0.0F;
};

inline MoveReport MoveReports(const pac::sim::ExchangeLog& log, std::size_t taken) {
    const auto& records = log.Records();
    const bool send = pac::sim::CommandFrame::Decode(records[taken].toPac.Cmd()).send;
    MoveReport report;
    for (std::size_t r = taken; r < records.size(); ++r) {
        if (r > taken && records[r].newCommand) break;
        const auto reply = pac::sim::ReplyFrame::Decode(records[r].fromPac.Cmd());
        if (reply.receiveFlag != send) continue;
        if (!report.acknowledged) {
            if (reply.commandErrorFlag || reply.endOfProcessing) break;
            report.acknowledged = true;
            report.start = FloatOf(reply.ackData);
        } else if (reply.endOfProcessing) {
            report.ended = true;
            report.end = FloatOf(reply.ackData);
            break;
        }
    }
    return report;
}

}  // namespace pac::test
