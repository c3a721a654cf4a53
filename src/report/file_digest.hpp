#pragma once
// SHA-256 digests for traceability: a QA report names every input file by
// its digest, so anyone can prove later which part, plan and measurements a
// verdict was made from. Computed with OpenSSL's EVP interface.
#include <string>

namespace furrow {

// Lower-case hex digest of bytes.
std::string sha256_hex(const std::string& bytes);

}  // namespace furrow
