#include <exception>
#include <iostream>
#include <new>

#include "kinestat/cli/app.hpp"
#include "kinestat/solver/blas_threads.hpp"

// The library reports failures as Status; what still escapes as an exception (std::bad_alloc from an
// allocation no size estimate foresaw, an exception from a third-party library) becomes a message and
// exit status 1 instead of an abort (docs/reliability.md).
int main(int argc, char** argv) {
  kinestat::solver::release_idle_blas_threads();  // a run may take less than their 0.1 s of spinning
  try {
    return kinestat::cli::run(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
  } catch (const std::bad_alloc&) {
    std::cerr << "kinestat: out of memory; the model or an option asks for more memory than this machine has "
                 "(see docs/reliability.md, limits)\n";
  } catch (const std::exception& e) {
    std::cerr << "kinestat: internal failure: " << e.what() << "\n";
  }
  return kinestat::cli::kExitInternal;
}
