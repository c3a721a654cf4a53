#include "io/qif/qif_uuid.hpp"

#include <openssl/evp.h>

#include <array>
#include <stdexcept>

namespace furrow {

namespace {

std::array<unsigned char, 32> sha256(const std::string& bytes) {
  std::array<unsigned char, 32> digest{};
  unsigned int length = 0;
  if (EVP_Digest(bytes.data(), bytes.size(), digest.data(), &length, EVP_sha256(), nullptr) != 1 ||
      length != digest.size())
    throw std::runtime_error("SHA-256 failed (OpenSSL EVP_Digest)");
  return digest;
}

const char kHex[] = "0123456789abcdef";

}  // namespace

std::string qif_sha256_hex(const std::string& bytes) {
  const auto d = sha256(bytes);
  std::string out;
  for (unsigned char c : d) {
    out += kHex[c >> 4];
    out += kHex[c & 15];
  }
  return out;
}

std::string uuid_from_content(const std::string& bytes) {
  auto d = sha256(bytes);
  d[6] = static_cast<unsigned char>((d[6] & 0x0f) | 0x80);  // version 8
  d[8] = static_cast<unsigned char>((d[8] & 0x3f) | 0x80);  // variant 10xx
  std::string out;
  for (int i = 0; i < 16; ++i) {
    if (i == 4 || i == 6 || i == 8 || i == 10) out += '-';
    out += kHex[d[i] >> 4];
    out += kHex[d[i] & 15];
  }
  return out;
}

}  // namespace furrow
