// A small on-disk cache of link stiffness results: FEA of a link takes seconds to minutes, and the
// same link is analysed again and again (design loops, the CLI). One text file per result, named
// by a 64-bit hash of everything the result depends on: the mesh (or the surface file and the
// meshing options), the material and the link-stiffness options.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "kinestat/core/status.hpp"
#include "kinestat/elements/material.hpp"
#include "kinestat/fea/link_stiffness.hpp"

namespace kinestat::fea {

// 64-bit FNV-1a of `data`, continuing from `seed` (chain calls to hash several pieces).
std::uint64_t fnv1a(std::string_view data, std::uint64_t seed = 1469598103934665603ull);

// Cache key (16 hex digits) of a result: `mesh_identity` identifies the mesh (e.g. the surface file's
// bytes plus the meshing options, or content_hash of a TetMesh as text); material and options are
// hashed from their values (the progress callback and keep_fields do not change the result).
std::string link_stiffness_cache_key(std::string_view mesh_identity, const Material& material,
                                     const LinkStiffnessOptions& options);

// The file of the entry `key` in `dir`: DIR/KEY.txt.
std::string link_stiffness_cache_path(const std::string& dir, const std::string& key);

// The cached compliance and reference point for `key` in `dir` (derived quantities recomputed;
// no fields, no solver report), or nullopt when absent or unreadable.
std::optional<LinkStiffness> load_cached_link_stiffness(const std::string& dir, const std::string& key);

// Writes DIR/KEY.txt (DIR is created): the compliance in full precision, SI units.
Status store_cached_link_stiffness(const std::string& dir, const std::string& key, const LinkStiffness& result);

}  // namespace kinestat::fea
