// pac-sim-plc: the library's FBs as a PLC against pac-sim over Modbus TCP (docs/virtual_commissioning.md, "The
// library over Modbus"): a scenario file's steps run by the scenario runner in a real-time scan loop whose
// process image goes through libmodbus to pac-sim; with --compare the same steps run in the process too (the
// simulated controller, the same PLC cycle) and every step must end the same.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace pac::pacsim {

// Exit codes: 0 every step passed (and, with --compare, ended as in the process), 1 a step failed or ended
// otherwise, 2 usage or an invalid scenario, 3 no connection or a broken one.
int RunPlcCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace pac::pacsim
