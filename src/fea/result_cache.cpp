#include "kinestat/fea/result_cache.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Cholesky>

#include "fea/sha256.hpp"
#include "kinestat/core/atomic_file.hpp"
#include "kinestat/solver/linear_solver_factory.hpp"

namespace kinestat::fea {

namespace {

namespace fs = std::filesystem;

// Version 2 added the key line's label and the checksum; version-1 entries are rejected (and their
// keys, FNV-1a hashes, are no longer asked for anyway).
constexpr const char* kHeader = "kinestat-link-stiffness-cache 2";
constexpr std::size_t kKeyDigits = 32;
// An entry is ~1 KB: anything much larger is not one (and is not read into memory).
constexpr std::size_t kMaxEntryBytes = 64 * 1024;
// Round-off leaves a scaled asymmetry near 1e-15 (direct) or the CG tolerance (iterative): far below.
constexpr double kMaxSymmetryError = 1e-4;

std::string region_text(const Region& r) {
  return fmt::format(
      "{} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} "
      "{:.17g} {:.17g}",
      static_cast<int>(r.kind), r.point.x(), r.point.y(), r.point.z(), r.normal.x(), r.normal.y(), r.normal.z(),
      r.lo.x(), r.lo.y(), r.lo.z(), r.hi.x(), r.hi.y(), r.hi.z(), r.tolerance);
}

Status bad_key(const std::string& key) {
  return Status::Invalid(
      fmt::format("link stiffness cache key '{}' is not {} lowercase hex digits; use "
                  "link_stiffness_cache_key",
                  key, kKeyDigits));
}

// The bytes of the regular file `path`: nullopt and `why` when absent (why empty) or not usable.
std::optional<std::string> read_entry(const std::string& path, std::string& why) {
  std::error_code ec;
  const fs::file_status link = fs::symlink_status(path, ec);
  if (!fs::exists(link)) return std::nullopt;
  if (!fs::is_regular_file(link)) {
    why = "not a regular file";
    return std::nullopt;
  }
  // O_NONBLOCK and O_NOFOLLOW: something swapped in since the check (a FIFO, a link) must not hang or
  // redirect the read; fstat confirms what was opened.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) {
    why = fmt::format("cannot be opened: {}", std::strerror(errno));
    return std::nullopt;
  }
  struct stat info {};
  std::string bytes;
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    why = "not a regular file";
  } else if (static_cast<std::size_t>(info.st_size) > kMaxEntryBytes) {
    why = fmt::format("{} bytes, far more than an entry", info.st_size);
  } else {
    char buffer[4096];
    for (;;) {
      const ssize_t n = ::read(fd, buffer, sizeof buffer);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        why = fmt::format("cannot be read: {}", std::strerror(errno));
        break;
      }
      if (n == 0) break;
      bytes.append(buffer, static_cast<std::size_t>(n));
      if (bytes.size() > kMaxEntryBytes) {
        why = "far more bytes than an entry";
        break;
      }
    }
  }
  ::close(fd);
  if (!why.empty()) return std::nullopt;
  return bytes;
}

// Splits whitespace-separated numbers; false unless every token is one number, entirely.
bool parse_numbers(std::string_view text, std::vector<double>& values) {
  std::size_t i = 0;
  while (i < text.size()) {
    if (std::isspace(static_cast<unsigned char>(text[i]))) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end]))) ++end;
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(text.data() + i, text.data() + end, v);
    if (ec != std::errc() || ptr != text.data() + end) return false;
    values.push_back(v);
    i = end;
  }
  return true;
}

std::string entry_body(const std::string& key, const LinkStiffness& r) {
  std::string body = fmt::format("{}\nkey {}\n{} {} {} {} {}\n", kHeader, key, static_cast<int>(r.reference_model),
                                 r.num_nodes, r.num_elements, r.nodes_per_element, r.num_dofs);
  const Vec3& p = r.cartesian.point;
  const Mat6& C = r.cartesian.compliance;
  body += fmt::format("{:.17g} {:.17g} {:.17g}\n", p.x(), p.y(), p.z());
  for (int i = 0; i < 6; ++i)
    body += fmt::format("{:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g}\n", C(i, 0), C(i, 1), C(i, 2), C(i, 3),
                        C(i, 4), C(i, 5));
  return body;
}

// The entry's result, or nullopt and `why`.
std::optional<LinkStiffness> parse_entry(const std::string& bytes, const std::string& key, std::string& why) {
  // The last line is "sha256 HEX" of everything before it.
  constexpr std::string_view kChecksum = "sha256 ";
  const std::size_t mark = bytes.rfind(std::string("\n") + std::string(kChecksum));
  if (mark == std::string::npos || bytes.empty() || bytes.back() != '\n') {
    why = bytes.rfind(kHeader, 0) == 0 ? "cut short (no checksum line)" : "not a cache entry of this version";
    return std::nullopt;
  }
  const std::string body = bytes.substr(0, mark + 1);
  const std::string stored = bytes.substr(mark + 1 + kChecksum.size(), bytes.size() - mark - 2 - kChecksum.size());
  if (stored != sha256_hex(body)) {
    why = "checksum mismatch (the file was changed or damaged after it was written)";
    return std::nullopt;
  }
  const std::string key_line = std::string(kHeader) + "\nkey " + key + "\n";
  if (body.rfind(kHeader + std::string("\n"), 0) != 0) {
    why = "not a cache entry of this version";
    return std::nullopt;
  }
  if (body.compare(0, key_line.size(), key_line) != 0) {
    why = "stored under another key (the file was copied or renamed)";
    return std::nullopt;
  }
  std::vector<double> v;
  if (!parse_numbers(std::string_view(body).substr(key_line.size()), v) || v.size() != 5 + 3 + 36) {
    why = "its numbers do not parse";
    return std::nullopt;
  }
  for (int i = 0; i < 5; ++i)
    if (!(v[i] >= 0.0 && v[i] <= std::numeric_limits<int>::max() && v[i] == std::floor(v[i]))) {
      why = "its mesh counts are not counts";
      return std::nullopt;
    }
  if (v[0] > static_cast<double>(ReferenceModel::kStiffBody)) {
    why = "an unknown reference model";
    return std::nullopt;
  }
  LinkStiffness r;
  r.reference_model = static_cast<ReferenceModel>(static_cast<int>(v[0]));
  r.num_nodes = static_cast<int>(v[1]);
  r.num_elements = static_cast<int>(v[2]);
  r.nodes_per_element = static_cast<int>(v[3]);
  r.num_dofs = static_cast<int>(v[4]);
  const Vec3 point(v[5], v[6], v[7]);
  Mat6 C;
  for (int i = 0; i < 36; ++i) C(i / 6, i % 6) = v[8 + i];
  if (!point.allFinite() || !C.allFinite()) {
    why = "its reference point or compliance is not finite";
    return std::nullopt;
  }
  if (!(C.diagonal().array() > 0.0).all()) {
    why = "its compliance is not positive definite (a diagonal term is not positive)";
    return std::nullopt;
  }
  if (const double e = scaled_symmetry_error(C); !(e <= kMaxSymmetryError)) {
    why = fmt::format("its compliance is not symmetric (scaled asymmetry {:.2e})", e);
    return std::nullopt;
  }
  // Scaled to a unit diagonal: translations (m/N) and rotations (rad/(N m)) differ by orders.
  const Vec6 s = C.diagonal().cwiseSqrt().cwiseInverse();
  const Mat6 scaled = s.asDiagonal() * (0.5 * (C + C.transpose())) * s.asDiagonal();
  if (Eigen::LLT<Mat6>(scaled).info() != Eigen::Success) {
    why = "its compliance is not positive definite";
    return std::nullopt;
  }
  set_compliance(r, C, point);
  return r;
}

}  // namespace

std::string link_stiffness_cache_path(const std::string& dir, const std::string& key) {
  return (fs::path(dir) / (key + ".txt")).string();
}

bool is_link_stiffness_cache_key(std::string_view key) {
  return key.size() == kKeyDigits && key.find_first_not_of("0123456789abcdef") == std::string_view::npos;
}

std::string link_stiffness_cache_key(std::string_view mesh_identity, const Material& m, const LinkStiffnessOptions& o) {
  const Vec3 p = o.reference_point.value_or(Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
  std::string values = fmt::format(
      "{}|E {:.17g} G {:.17g}|clamp {}|reference {}|model {} ratio {:.17g}|point {} {:.17g} {:.17g} {:.17g}|"
      "ordering {} pivot {:.17g}",
      kHeader, m.E, m.G, region_text(o.clamp), region_text(o.reference), static_cast<int>(o.reference_model),
      o.stiff_body_ratio, o.reference_point.has_value(), p.x(), p.y(), p.z(), static_cast<int>(o.solver.ordering),
      o.solver.singular_pivot_ratio);
  // An iterative result is only as accurate as its tolerance: not interchangeable with a direct one.
  if (const double tolerance = solver::solution_tolerance(o.solver); tolerance > 0.0)
    values += fmt::format("|cg rtol {:.17g}", tolerance);
  // The identity's length first: no identity and values can be split differently to the same text.
  Sha256 h;
  h.update(fmt::format("{}\n", mesh_identity.size()));
  h.update(mesh_identity);
  h.update(values);
  return h.hex_digest().substr(0, kKeyDigits);
}

StatusOr<CachedLinkStiffness> load_cached_link_stiffness(const std::string& dir, const std::string& key) {
  if (!is_link_stiffness_cache_key(key)) return bad_key(key);
  const std::string path = link_stiffness_cache_path(dir, key);
  CachedLinkStiffness found;
  std::string why;
  std::optional<std::string> bytes = read_entry(path, why);
  if (bytes) found.result = parse_entry(*bytes, key, why);
  if (!why.empty()) found.rejected = fmt::format("{}: cache entry ignored: {}", path, why);
  return found;
}

Status store_cached_link_stiffness(const std::string& dir, const std::string& key, const LinkStiffness& r) {
  if (!is_link_stiffness_cache_key(key)) return bad_key(key);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec)
    return Status::Invalid(fmt::format("{}: cannot create the link stiffness cache folder: {}", dir, ec.message()));
  const std::string path = link_stiffness_cache_path(dir, key);
  // Not an entry (a FIFO, a link) but in its place: removed, since writing into it could block or
  // go elsewhere, while write_file_atomically would write into it rather than replace it.
  if (const fs::file_status s = fs::symlink_status(path, ec); fs::exists(s) && !fs::is_regular_file(s))
    fs::remove(path, ec);
  const std::string body = entry_body(key, r);
  return write_text_file_atomically(path, body + "sha256 " + sha256_hex(body) + "\n");
}

}  // namespace kinestat::fea
