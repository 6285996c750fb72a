// Entry point of the niwa CLI (native and WASM under node): a thin wrapper over RunCli.
#include <iostream>
#include <string>
#include <vector>

#include "cli.h"
#include "process_heap.h"

int main(int argc, char** argv) {
  niwa::KeepFreedMemoryForReuse();
  std::vector<std::string> args(argv + 1, argv + argc);
  return niwa::RunCli(args, std::cout, std::cerr);
}
