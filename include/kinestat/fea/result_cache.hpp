// A small on-disk cache of link stiffness results: FEA of a link takes seconds to minutes, and the
// same link is analysed again and again (design loops, the CLI). One text file per result, named
// by a SHA-256 of everything the result depends on: the mesh (or the surface file and the meshing
// options), the material and the link-stiffness options. Each entry carries the key it was stored
// under and a SHA-256 checksum of its content; an entry that fails any check is never returned.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "kinestat/core/status.hpp"
#include "kinestat/elements/material.hpp"
#include "kinestat/fea/link_stiffness.hpp"

namespace kinestat::fea {

// Cache key of a result, 32 lowercase hex digits (SHA-256, truncated): `mesh_identity` identifies the
// mesh (e.g. the surface file's bytes plus the meshing options, or content_hash of a TetMesh);
// material and options are hashed from their values (the progress callback and keep_fields do not
// change the result).
std::string link_stiffness_cache_key(std::string_view mesh_identity, const Material& material,
                                     const LinkStiffnessOptions& options);

// Whether `key` has the form of link_stiffness_cache_key's keys (so that it names a file inside the
// cache folder: no '/', no "..").
bool is_link_stiffness_cache_key(std::string_view key);

// The file of the entry `key` in `dir`: DIR/KEY.txt.
std::string link_stiffness_cache_path(const std::string& dir, const std::string& key);

struct CachedLinkStiffness {
  // The cached compliance and reference point (derived quantities recomputed; no fields, no solver
  // report); nullopt when there is no entry or it was rejected.
  std::optional<LinkStiffness> result;
  // Why an entry present was rejected, naming its file: not a regular file, unreadable, cut short,
  // checksum mismatch, another key, a compliance that is not finite, symmetric and positive
  // definite. Empty when the entry was used or is absent.
  std::string rejected;
};

// Looks `key` up in `dir`. Only a regular file is opened (without blocking: a FIFO is rejected), and
// only an entry whose checksum, key and compliance all check out is returned. kInvalidInput for a
// key that is not of the cache's form.
StatusOr<CachedLinkStiffness> load_cached_link_stiffness(const std::string& dir, const std::string& key);

// Writes DIR/KEY.txt (DIR is created): the key, the compliance in full precision (SI units) and a
// checksum, through a temporary file renamed over the entry (core/atomic_file.hpp), so that readers
// never see half an entry. kInvalidInput for a key not of the cache's form or a folder that cannot
// be written.
Status store_cached_link_stiffness(const std::string& dir, const std::string& key, const LinkStiffness& result);

}  // namespace kinestat::fea
