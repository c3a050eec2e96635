// pac-sim's command line (docs/virtual_commissioning.md): the simulated PA-CONTROLs of a configuration file in
// real time behind Modbus TCP until SIGINT (Ctrl-C) or SIGTERM, or --seconds have passed.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace pac::pacsim {

constexpr int kExitOk = 0;
constexpr int kExitInvalid = 2;  // invalid configuration or usage
constexpr int kExitFailed = 3;   // cannot listen, or an internal error

// SIGINT and SIGTERM must be blocked in the calling thread (main() does it first): the run waits for them.
int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace pac::pacsim
