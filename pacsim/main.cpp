// pac-sim: simulated PA-CONTROLs in real time behind Modbus TCP (docs/virtual_commissioning.md).
#include <csignal>
#include <iostream>
#include <pthread.h>

#include "server_cli.hpp"

int main(int argc, char** argv) {
    // Before any thread starts, so every thread inherits the mask and the run takes the signals in one place.
    // The default action, even where the parent ignores them (a shell's background job): a signal ignored at
    // generation never reaches the wait for it.
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    sigset_t stop;
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stop, nullptr);
    std::signal(SIGPIPE, SIG_IGN);  // a client gone while a reply is on its way: an error return, not a signal
    return pac::pacsim::RunCli(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
