// docs/sim_bus.md, "Tests": a library FB against the simulated PA-CONTROL over the simulated bus.
#include "pac/fb_instance.hpp"
#include "pac/scan_test.hpp"
#include "pac/sim/bus.hpp"
#include "pac/sim/pa_control.hpp"
#include "pac/sim/pac_runner.hpp"
#include "pac/st_program.hpp"

// doc-example begin
class MyTest : public pac::ScanTest {};

TEST_F(MyTest, ReadsN2) {
    pac::sim::Bus bus;                                  // zero latency both ways
    pac::sim::PaControl pac(bus);                       // boots in 50 ms, cycles every 10 ms
    pac::sim::PacRunner runner(pac);
    runner.AttachTo(task_);                             // first: the controller runs before the PLC
    pac.Io().intRegisters.SetInt(2, 12345678);
    auto interface = PAC_FB(FB_PAC_CMDINTERFACE);
    auto read = PAC_FB(FB_PAC_READINTREG);
    task_.AddProgram([&] {
        const auto now = task_.Clock().Now();
        ST_PAC_CMDCHANNEL& channel = interface->CHANNEL.value;
        const pac::sim::Image8 fromPac = bus.ReadFromPac(now).Cmd();
        for (int i = 0; i < 8; ++i) channel.FROMPAC.table[i] = fromPac[i];
        interface();
        read->CHANNEL.value = channel;
        read();
        channel = read->CHANNEL.value;
        pac::sim::Image8 toPac{};
        for (int i = 0; i < 8; ++i) toPac[i] = channel.TOPAC.table[i];
        bus.WriteToPac(now, toPac);
    });
    ASSERT_TRUE(RunUntil([&] { return interface->OPSTATUS.value == 1; }, 100, "home position"));  // booted
    read->NUMBER.value = 2;
    read->EXECUTE.value = TRUE;
    ASSERT_TRUE(RunUntil([&] { return read->DONE.value != 0; }, 200, "Done"));
    EXPECT_EQ(read->VALUE.value, 12345678);
}
// doc-example end
