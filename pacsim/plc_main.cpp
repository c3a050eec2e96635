// pac-sim-plc: the library's FBs against pac-sim over Modbus TCP in real time (docs/virtual_commissioning.md).
#include <iostream>

#include "plc_cli.hpp"

int main(int argc, char** argv) {
    return pac::pacsim::RunPlcCli(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
