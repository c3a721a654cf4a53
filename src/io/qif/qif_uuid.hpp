#pragma once
// QPIds without randomness: a QIF document is identified by a UUID
// (QPIdType, QIFDocument.xsd), and Furrow's outputs must be the same bytes
// for the same inputs (docs/architecture.md "Conventions"), so the UUID is
// derived from the SHA-256 of what it identifies: the first 16 bytes of the
// digest with the version nibble set to 8 (RFC 9562 "custom", the layout
// for hash-derived UUIDs that are not SHA-1 name-based) and the RFC 4122
// variant bits. Lower-case 8-4-4-4-12 hex, as QIF writes them.
//
// SHA-256 is computed with OpenSSL here rather than with report/file_digest
// because io/qif sits below report in the module order.
#include <string>

namespace furrow {

// Lower-case hex SHA-256 of `bytes`.
std::string qif_sha256_hex(const std::string& bytes);

// The UUID derived from `bytes` as described above.
std::string uuid_from_content(const std::string& bytes);

}  // namespace furrow
