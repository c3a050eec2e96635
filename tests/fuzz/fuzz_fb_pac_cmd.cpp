// libFuzzer target: FB_PAC_CmdInterface and two FB_PAC_Cmd sharing one CMD channel (manual 2.4), scan by
// scan, against whatever the input makes the PA-CONTROL's side of the module say: replies that follow the
// SEND flag with any END OF PROCESSING / COMMAND ERROR flags and data, raw bytes, an all-zero module (link
// lost), or nothing new. The input also drives both FBs' Execute, Code, Param, Data, Timeout, EndTimeout,
// whether the second FB is called at all, the two-step write and the PLC cycle.
// Checked after every scan: the PLCopen rules of both FBs with their Busy bound Timeout + EndTimeout
// (plcopen_checker.hpp), and that the module never carries more new commands than there were Execute
// edges (a SEND flag toggled away from the RECEIVE flag is a command the PA-CONTROL would execute).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_bytes.hpp"
#include "fuzz_plc.hpp"
#include "pac/fb_instance.hpp"
#include "pac/st_program.hpp"
#include "plcopen_checker.hpp"

namespace {

using pac::fuzz::FuzzBytes;
constexpr std::uint8_t kFlagBit = 0x80;  // byte 6 bit 7: SEND (to PAC) / RECEIVE (from PAC)

// The PA-CONTROL's side of the CMD module, one decision per scan.
class CmdReplies {
public:
    void Next(FuzzBytes& in, const std::array<std::uint8_t, 8>& toPac) {
        const std::uint8_t op = in.Byte();
        switch (op & 3U) {
            case 0:  // nothing new this scan
                break;
            case 1: {  // a reply that follows the SEND flag: acknowledged, flags and data from the input
                const std::uint8_t flags = static_cast<std::uint8_t>(op & 0x60U);  // END OF PROCESSING, ERROR
                reply_[6] = static_cast<std::uint8_t>((toPac[6] & kFlagBit) | flags | (reply_[6] & 0x1FU));
                if ((op & 0x10U) != 0) {
                    for (int i = 0; i < 4; ++i) reply_[static_cast<std::size_t>(i)] = in.Byte();
                    reply_[7] = in.Byte();
                }
                if ((op & 0x80U) != 0) reply_[5] = in.Byte();  // operating status
                break;
            }
            case 2:  // any bytes at all
                for (auto& b : reply_) b = in.Byte();
                break;
            default:  // link lost or controller restarting: all zero
                reply_.fill(0);
                break;
        }
    }
    const std::array<std::uint8_t, 8>& Bytes() const { return reply_; }

private:
    std::array<std::uint8_t, 8> reply_{0, 0, 0, 0, 0, 1, 0x20, 0};  // home position, nothing outstanding
};

class CmdFuzzRun {
public:
    explicit CmdFuzzRun(FuzzBytes& in)
        : in_(in), plc_(in), checkA_("FB_PAC_Cmd A", pac::fuzz::AbortOnViolation()),
          checkB_("FB_PAC_Cmd B", pac::fuzz::AbortOnViolation()) {
        iface_->TWOSTEPWRITE.value = in.Bit() ? TRUE : FALSE;
        plc_.Task().AddProgram([this] { Scan(); });
    }

    void Run() {
        plc_.Run(in_, [this] { return a_->BUSY.value != 0 || b_->BUSY.value != 0; });
    }

private:
    void Scan() {
        const std::uint8_t inputs = in_.Byte();
        const bool callB = (inputs & 0x40U) == 0;
        Drive(a_, inputs & 0x03U);
        if (callB) Drive(b_, (inputs >> 2) & 0x03U);
        replies_.Next(in_, module_);

        ST_PAC_CMDCHANNEL& channel = iface_->CHANNEL.value;
        for (std::size_t i = 0; i < 8; ++i) channel.FROMPAC.table[i] = replies_.Bytes()[i];
        iface_();
        Call(a_);
        if (callB) Call(b_);
        for (std::size_t i = 0; i < 8; ++i) module_[i] = channel.TOPAC.table[i];

        const std::int64_t scan = plc_.Task().ScanCount();
        if (trace_) Trace(callB);
        checkA_.Check(scan, a_, pac::test::CommandBusyBoundOf(a_, plc_.Cycle()));
        if (callB) checkB_.Check(scan, b_, pac::test::CommandBusyBoundOf(b_, plc_.Cycle()));
        CountNewCommands();
    }

    void Trace(bool callB) {
        auto show = [](pac::FbInstance<FB_PAC_CMD>& fb) {
            std::fprintf(stderr, " | Ex %d %c id %X st %d T %lld/%lld ms", fb->EXECUTE.value,
                         pac::test::OutputsOf(fb).Letter(), fb->ERRORID.value, static_cast<int>(fb->STATE.value),
                         static_cast<long long>(pac::FromIecTime(fb->TIMEOUT.value).count() / 1000000),
                         static_cast<long long>(pac::FromIecTime(fb->ENDTIMEOUT.value).count() / 1000000));
        };
        std::fprintf(stderr, "scan %lld (cycle %lld ms): to %02X%02X from %02X%02X st %d", static_cast<long long>(plc_.Task().ScanCount()),
                     static_cast<long long>(plc_.Cycle().count() / 1000000), module_[6], module_[7], replies_.Bytes()[6],
                     replies_.Bytes()[7], replies_.Bytes()[5]);
        show(a_);
        if (callB) show(b_);
        std::fprintf(stderr, "\n");
    }

    // bit 0: Execute; bit 1: new Code, Param, Data and times from the input, with an Execute edge to an idle FB: the
    // Busy bound is the job's Timeout and EndTimeout, so a program does not change them while it runs.
    void Drive(pac::FbInstance<FB_PAC_CMD>& fb, unsigned bits) {
        const bool execute = (bits & 1U) != 0;
        const bool edge = execute && fb->EXECUTE.value == 0;
        if (edge) ++edges_;
        fb->EXECUTE.value = execute ? TRUE : FALSE;
        if (edge && fb->BUSY.value == 0 && (bits & 2U) != 0) {
            fb->CODE.value = in_.Word();
            fb->PARAM.value = in_.Word();
            fb->DATA.value = in_.Dword();
            fb->TIMEOUT.value = pac::fuzz::ShortTime(in_);
            fb->ENDTIMEOUT.value = pac::fuzz::ShortTime(in_);
        }
    }

    void Call(pac::FbInstance<FB_PAC_CMD>& fb) {
        ST_PAC_CMDCHANNEL& channel = iface_->CHANNEL.value;
        fb->CHANNEL.value = channel;
        fb();
        channel = fb->CHANNEL.value;
    }

    // A SEND flag that changes to differ from the RECEIVE flag the PLC reads is a new command for the
    // PA-CONTROL; bringing SEND back to RECEIVE (resynchronising) is none, and neither is the parked read (190B
    // without parameter or data, a read without effect), which the interface toggles after a cold start.
    void CountNewCommands() {
        const bool send = (module_[6] & kFlagBit) != 0;
        const bool receive = (replies_.Bytes()[6] & kFlagBit) != 0;
        bool parked = (module_[6] & 0x7FU) == 0x19 && module_[7] == 0x0B;
        for (int i = 0; i < 6; ++i) parked = parked && module_[i] == 0;
        if (send != lastSend_ && send != receive && !parked) ++sent_;
        lastSend_ = send;
        if (sent_ > edges_) {
            pac::fuzz::Violation("scan " + std::to_string(plc_.Task().ScanCount()) + ": " + std::to_string(sent_) +
                                 " commands sent for " + std::to_string(edges_) + " Execute edges");
        }
    }

    FuzzBytes& in_;
    pac::fuzz::FuzzPlc plc_;
    pac::FbInstance<FB_PAC_CMDINTERFACE> iface_ = PAC_FB(FB_PAC_CMDINTERFACE);
    pac::FbInstance<FB_PAC_CMD> a_ = PAC_FB(FB_PAC_CMD);
    pac::FbInstance<FB_PAC_CMD> b_ = PAC_FB(FB_PAC_CMD);
    CmdReplies replies_;
    std::array<std::uint8_t, 8> module_{};
    pac::test::PlcOpenChecker checkA_;
    pac::test::PlcOpenChecker checkB_;
    bool trace_ = pac::fuzz::TraceWanted();
    int edges_ = 0;
    int sent_ = 0;
    bool lastSend_ = false;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return pac::fuzz::RunOneInput<CmdFuzzRun>(data, size);
}
