#include "GuiLauncher.hpp"
#include "cli/Cli.hpp"

#include <iostream>

int main(int argc, char** argv) {
    if (dropscope::argumentsOpenGui(argc, argv)) {
        return dropscope::runGui(argc == 2 ? std::optional<std::string>(argv[1]) : std::nullopt, std::cerr);
    }
    return dropscope::runCli(argc, argv, std::cout, std::cerr);
}
