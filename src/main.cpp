#include "cli/commands.hpp"

int main(int argc, char** argv) {
  return swarmagg::cli::main(argc, argv);
}
