// plyimpact: explicit finite-element impact analysis of composite laminates.
#include <iostream>

#include "app/application.hpp"

int main(int argc, char** argv) {
  return plyimpact::app::run_application(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
