#include <iostream>

#include "kinestat/cli/app.hpp"

int main(int argc, char** argv) {
  return kinestat::cli::run(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
