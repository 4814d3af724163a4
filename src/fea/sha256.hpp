// SHA-256 through OpenSSL's EVP API, for the result cache's keys and checksums and the mesh content
// hash: a maintained, well-tested hash instead of a hand-written one. Internal to fea.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

struct evp_md_ctx_st;  // OpenSSL's EVP_MD_CTX, kept out of this header

namespace kinestat::fea {

class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;
  void update(const void* data, std::size_t bytes);
  void update(std::string_view text) { update(text.data(), text.size()); }
  std::string hex_digest();  // 64 lowercase hex digits; ends the hash

 private:
  evp_md_ctx_st* ctx_;
};

// SHA-256 of `data`, 64 lowercase hex digits.
std::string sha256_hex(std::string_view data);

}  // namespace kinestat::fea
