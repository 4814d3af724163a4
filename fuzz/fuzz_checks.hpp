// What the harnesses check of every reader's answer (docs/reliability.md, "Fuzzing"): a refusal
// says why, and a structure that reads is solved or refused with a message. A check that fails
// aborts, which libFuzzer and the replay runs report as a finding.
#pragma once

#include <cstdlib>

#include "kinestat/core/status.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/msa/structure.hpp"

namespace kinestat::fuzz {

// True when `r` is a refusal; aborts when the refusal has no message.
template <class T>
bool refused(const StatusOr<T>& r) {
  if (r.ok()) return false;
  if (r.status().message().empty()) std::abort();
  return true;
}

// A structure reader's answer: a refusal with a message, or a model; models of up to 30 nodes (so
// that each input stays fast) are solved, and a failed solve must say why.
inline void check_structure(const StatusOr<msa::Structure>& s) {
  if (refused(s) || s->nodes().size() > 30) return;
  const msa::Solution sol = msa::solve(*s);
  if (!sol.status.ok() && sol.status.message().empty()) std::abort();
}

}  // namespace kinestat::fuzz
