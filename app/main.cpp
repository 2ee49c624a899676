#include <iostream>

#include "app/cli.h"
#include "planner/util/heap_tuning.h"

int main(int argc, char** argv) {
  stanceplan::keep_freed_heap_for_solvers();
  return stanceplan::app::run_cli(argc, argv, std::cout, std::cerr);
}
