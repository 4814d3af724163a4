// SolveOptions::progress inside msa: the stages of a solve, of buckling and of modes.
#pragma once

#include <string>

#include "kinestat/msa/static_analysis.hpp"

namespace kinestat::msa {

inline void tell(const SolveOptions& opt, const std::string& stage) {
  if (opt.progress) opt.progress(stage);
}

// The caller's Cholesky options, telling its stage (the factorization's flops and memory) to
// opt.progress where they tell nobody.
inline solver::LinearSolverOptions cholesky_options(const SolveOptions& opt) {
  solver::LinearSolverOptions o = opt.cholesky;
  if (!o.progress) o.progress = opt.progress;
  return o;
}

}  // namespace kinestat::msa
