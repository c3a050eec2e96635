#include "latency.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <vector>

#include "pac/fb_instance.hpp"
#include "pac/st_program.hpp"

namespace pac::bench {

void LatencyRow::Add(int scans, int minimum, bool done) {
    commands++;
    scansMin = std::min(scansMin, scans);
    scansMax = std::max(scansMax, scans);
    minimumMin = std::min(minimumMin, minimum);
    minimumMax = std::max(minimumMax, minimum);
    if (scans != minimum || !done) aboveMinimum++;
}

void LatencyRow::Merge(const LatencyRow& other) {
    commands += other.commands;
    scansMin = std::min(scansMin, other.scansMin);
    scansMax = std::max(scansMax, other.scansMax);
    minimumMin = std::min(minimumMin, other.minimumMin);
    minimumMax = std::max(minimumMax, other.minimumMax);
    aboveMinimum += other.aboveMinimum;
}

namespace {

// Starts `plc` and scans past the CMD interface's first handshake after the PLC cold start (the parked read
// toggled and acknowledged with its end, docs/fb/FB_PAC_Cmd.md "After a PLC cold start"), then 3 scans more:
// no command may go out before it, so a job started earlier would wait for it on top of its own round trip.
void StartPastFirstHandshake(pac::PacRig& plc) {
    plc.Start();
    if (plc.ScanUntil([&] { return plc.Channel().FIRSTREADDONE != 0; }, 10000) < 0) {
        throw std::runtime_error("the CMD interface's first handshake did not end");
    }
    plc.Scan(3);
}

}  // namespace

LatencyRow MeasureCmd(const pac::RigTiming& timing, int commands) {
    pac::PacRig plc(timing);
    auto cmd = PAC_FB(FB_PAC_CMD);
    plc.Call(cmd);
    StartPastFirstHandshake(plc);
    LatencyRow row;
    for (int i = 0; i < commands; ++i) {
        cmd->CODE.value = (i % 2 == 0) ? 0x0906 : 0x1906;  // write, then read back, N register 1
        cmd->PARAM.value = 1;
        cmd->DATA.value = static_cast<DWORD>(i);
        cmd->EXECUTE.value = TRUE;
        plc.Scan();
        const auto edge = plc.Now();
        const int scans = plc.ScanUntil([&] { return cmd->DONE.value || cmd->ERROR.value; }, 10000);
        row.Add(scans, plc.ProtocolMinimumScans(edge), cmd->DONE.value != 0);
        cmd->EXECUTE.value = FALSE;
        plc.Scan(1 + i % 3);  // vary the phase against the controller's cycle
    }
    return row;
}

namespace {

// One element FB of the shared interface, whichever type it is.
class SharedFb {
public:
    virtual ~SharedFb() = default;
    virtual void SetExecute(bool on) = 0;
    virtual bool Done() const = 0;
    virtual bool Final() const = 0;
};

template <class Fb>
class SharedFbOf : public SharedFb {
public:
    SharedFbOf(pac::FbInstance<Fb> fb, UINT number) : fb_(fb) { fb_->NUMBER.value = number; }
    pac::FbInstance<Fb>& Instance() { return fb_; }
    void SetExecute(bool on) override { fb_->EXECUTE.value = on ? TRUE : FALSE; }
    bool Done() const override { return fb_->DONE.value != 0; }
    bool Final() const override { return fb_->DONE.value || fb_->ERROR.value; }

private:
    pac::FbInstance<Fb> fb_;
};

// The fewest scans for commands sent one after the other from `edge`, each in the scan that shows the one
// before it acknowledged.
int ChainedMinimum(const pac::PacRig& plc, std::chrono::nanoseconds edge, int commands) {
    int total = 0;
    for (int i = 0; i < commands; ++i) {
        const int scans = plc.ProtocolMinimumScans(edge);
        total += scans;
        edge += scans * plc.Timing().plcCycle;
    }
    return total;
}

// `fbs` element FBs on `plc`'s CMD interface, FB_PAC_WriteIntReg and FB_PAC_ReadIntReg in turn, each read
// after the write of its register.
std::vector<std::unique_ptr<SharedFb>> SharedFbs(pac::PacRig& plc, int fbs) {
    std::vector<std::unique_ptr<SharedFb>> shared;
    for (int i = 0; i < fbs; ++i) {
        const UINT number = static_cast<UINT>(1 + i / 2);
        if (i % 2 == 0) {
            auto fb = std::make_unique<SharedFbOf<FB_PAC_WRITEINTREG>>(PAC_FB(FB_PAC_WRITEINTREG), number);
            plc.Call(fb->Instance());
            shared.push_back(std::move(fb));
        } else {
            auto fb = std::make_unique<SharedFbOf<FB_PAC_READINTREG>>(PAC_FB(FB_PAC_READINTREG), number);
            plc.Call(fb->Instance());
            shared.push_back(std::move(fb));
        }
    }
    return shared;
}

}  // namespace

LatencyRow MeasureShared(const pac::RigTiming& timing, int fbs, int rounds) {
    pac::PacRig plc(timing);
    const auto shared = SharedFbs(plc, fbs);
    StartPastFirstHandshake(plc);
    const auto allFinal = [&] {
        return std::all_of(shared.begin(), shared.end(), [](const auto& fb) { return fb->Final(); });
    };
    LatencyRow row;
    for (int r = 0; r < rounds; ++r) {
        for (auto& fb : shared) fb->SetExecute(true);
        plc.Scan();
        const auto edge = plc.Now();
        const int scans = plc.ScanUntil(allFinal, 10000);
        const bool done = std::all_of(shared.begin(), shared.end(), [](const auto& fb) { return fb->Done(); });
        row.Add(scans, ChainedMinimum(plc, edge, fbs), done);
        for (auto& fb : shared) fb->SetExecute(false);
        plc.Scan(1 + r % 3);
    }
    return row;
}

SharedRate MeasureSharedRate(const pac::RigTiming& timing, int fbs, int scans) {
    pac::PacRig plc(timing);
    const auto shared = SharedFbs(plc, fbs);
    std::vector<long> done(shared.size(), 0);
    std::vector<bool> execute(shared.size(), false);
    SharedRate rate;
    // The application program, after the FBs in each scan (their inputs of the next scan): a new Execute edge
    // as soon as the last job was final.
    plc.Task().AddProgram([&] {
        for (std::size_t i = 0; i < shared.size(); ++i) {
            if (execute[i] && shared[i]->Final()) {
                done[i] += shared[i]->Done() ? 1 : 0;
                rate.errors += shared[i]->Done() ? 0 : 1;
                execute[i] = false;
            } else if (!execute[i]) {
                execute[i] = true;
            }
            shared[i]->SetExecute(execute[i]);
        }
    });
    StartPastFirstHandshake(plc);
    const auto start = plc.Now();
    std::fill(done.begin(), done.end(), 0);
    rate.errors = 0;
    // The protocol's bound for the same commands: each SEND toggle (parking keeps the flag) acknowledged
    // after the fewest scans the bus and the controller's cycle allow from the scan it was sent in.
    std::chrono::nanoseconds minimum{0};
    bool sendFlag = (plc.ToPac()[6] & 0x80) != 0;
    for (int i = 0; i < scans; ++i) {
        plc.Scan();
        const bool flag = (plc.ToPac()[6] & 0x80) != 0;
        if (flag == sendFlag) continue;
        sendFlag = flag;
        minimum += timing.plcCycle * plc.ProtocolMinimumScans(plc.Now());
    }
    const double seconds = std::chrono::duration<double>(plc.Now() - start).count();
    long all = 0;
    for (long d : done) all += d;
    rate.commandsPerSecond = static_cast<double>(all) / seconds;
    const double bound = std::chrono::duration<double>(minimum).count();
    rate.protocolPerSecond = bound > 0.0 ? static_cast<double>(all + rate.errors) / bound : 0.0;
    rate.fewestPerFb = *std::min_element(done.begin(), done.end());
    rate.mostPerFb = *std::max_element(done.begin(), done.end());
    return rate;
}

}  // namespace pac::bench
