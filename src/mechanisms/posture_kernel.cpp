#include "kinestat/mechanisms/posture_kernel.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "kinestat/core/threads.hpp"

namespace kinestat::mechanisms {

void set_stiffness(PostureResult& r, const Mat6& K, const Mat6& C) {
  r.stiffness = K;
  r.compliance = C;
  r.indices = cartesian_indices(K);
}

const char* to_string(PostureStatus s) {
  switch (s) {
    case PostureStatus::kOk:
      return "ok";
    case PostureStatus::kUnreachable:
      return "unreachable";
    case PostureStatus::kSingular:
      return "singular";
    case PostureStatus::kFailed:
      return "failed";
    case PostureStatus::kNearSingular:
      return "near-singular";
  }
  return "unknown";
}

void evaluate_postures(const PostureKernel& kernel, const std::vector<Vec3>& points,
                       std::vector<PostureResult>& results, int threads,
                       const std::function<void(std::size_t, std::size_t)>& progress, PointOrder order) {
  results.resize(points.size());
  evaluate_postures(
      kernel, points, [&](std::size_t i, const PostureResult& r) { results[i] = r; }, threads, progress, order);
}

void evaluate_postures(const PostureKernel& kernel, const std::vector<Vec3>& points,
                       const std::function<void(std::size_t, const PostureResult&)>& visit, int threads,
                       const std::function<void(std::size_t, std::size_t)>& progress, PointOrder order) {
  const std::size_t total = points.size();
  using Clock = std::chrono::steady_clock;
  std::atomic<std::size_t> done{0};
  std::mutex report_mutex;
  auto last_report = Clock::now();
  // One kernel per worker thread: a kernel keeps mutable buffers (not thread-safe by contract).
  tbb::enumerable_thread_specific<std::unique_ptr<PostureKernel>> local([&] { return kernel.clone(); });
  // Chunks of kPathChunk postures: small enough to balance, large enough that scheduling (and, on a
  // path, the chunk's first posture solved from scratch) costs little. Fixed, not TBB's adaptive
  // ranges, so that a path's warm starts do not depend on the threads.
  const std::size_t chunks = (total + kPathChunk - 1) / kPathChunk;
  auto body = [&](const tbb::blocked_range<std::size_t>& r) {
    PostureKernel& k = *local.local();
    std::size_t count = 0;
    for (std::size_t c = r.begin(); c != r.end(); ++c) {
      const std::size_t begin = c * kPathChunk, end = std::min(total, begin + kPathChunk);
      for (std::size_t i = begin; i != end; ++i)
        visit(i, order == PointOrder::kPath && i != begin ? k.evaluate_next(points[i]) : k.evaluate(points[i]));
      count += end - begin;
    }
    const std::size_t now_done = done += count;
    if (progress && report_mutex.try_lock()) {
      const auto now = Clock::now();
      if (now - last_report > std::chrono::milliseconds(100)) {
        last_report = now;
        progress(now_done, total);
      }
      report_mutex.unlock();
    }
  };
  const tbb::blocked_range<std::size_t> range(0, chunks, 1);
  tbb::task_arena arena(threads > 0 ? threads : available_cpus());
  arena.execute([&] { tbb::parallel_for(range, body); });
  if (progress) progress(total, total);
}

}  // namespace kinestat::mechanisms
