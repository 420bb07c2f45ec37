#include "GuiLauncher.hpp"
#include "cli/Cli.hpp"

#include <csignal>
#include <iostream>

int main(int argc, char** argv) {
    // A file that outgrows the process's file-size limit (ulimit -f) then fails to write with EFBIG, which
    // the writers report and clean up after (whole files or none), instead of the signal killing the process
    // midway and leaving temporary files behind. Python does the same for its module.
    std::signal(SIGXFSZ, SIG_IGN);
    if (dropscope::argumentsOpenGui(argc, argv)) {
        return dropscope::runGui(argc == 2 ? std::optional<std::string>(argv[1]) : std::nullopt, std::cerr);
    }
    return dropscope::runCli(argc, argv, std::cout, std::cerr);
}
