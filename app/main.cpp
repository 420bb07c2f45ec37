#include "cli/Cli.hpp"

#include <iostream>

int main(int argc, char** argv) { return dropscope::runCli(argc, argv, std::cout, std::cerr); }
