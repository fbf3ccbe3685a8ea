#include <iostream>

#include "commands.hpp"

int main(int argc, char** argv) {
  return mink::cli::run(argc, argv, {std::cin, std::cout, std::cerr});
}
