#pragma once
// A QIF document checked by the official QIF 3.0 XSD set (docs/qif.md
// "Validity"): `xmllint --noout --nonet --schema QIFDocument.xsd FILE` run as
// a subprocess, the XSD from shared/ beside the checkout
// (support/shared_standards.hpp). A test that validates fails - it does not
// skip - when the XSD or xmllint (Debian libxml2-utils) is missing.
//
// Offline, xmllint cannot fetch the W3C xmldsig schema QIFDocument.xsd
// imports for its optional Signature and says so in three lines; those are
// the only lines tolerated besides the verdict, so a new warning fails too.
#include <doctest/doctest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

#include "support/run_cli.hpp"
#include "support/shared_standards.hpp"

namespace furrow::test {

struct QifValidation {
  bool valid = false;
  std::string verdict;  // xmllint's last line: "FILE validates" or "FILE fails to validate"
  std::string errors;   // every other line but the xmldsig import's
};

inline QifValidation validate_qif_file(const std::string& path) {
  const std::string xsd = standards_path("standards/qif-3.0/QIFDocument.xsd");
  static const bool have_xmllint = std::system("xmllint --version > /dev/null 2>&1") == 0;
  if (!have_xmllint)
    throw std::runtime_error("xmllint is missing: the QIF tests validate with it (Debian libxml2-utils, "
                             "scripts/install-deps.sh)");
  const std::string log = path + ".xmllint.log";
  const std::string cmd = "xmllint --noout --nonet --schema " + shell_quote(xsd) + " " + shell_quote(path) + " > " +
                          shell_quote(log) + " 2>&1";
  const int raw = std::system(cmd.c_str());
  const int status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  QifValidation v;
  std::istringstream lines(slurp(log));
  for (std::string line; std::getline(lines, line);) {
    if (line == path + " validates" || line == path + " fails to validate") {
      v.verdict = line;
    } else if (line.find("xmldsig-core-schema.xsd") == std::string::npos) {
      v.errors += line + "\n";
    }
  }
  v.valid = status == 0 && v.verdict == path + " validates" && v.errors.empty();
  return v;
}

// CHECKs that the file is valid by the schema, printing xmllint's errors if not.
inline void check_qif_valid_file(const std::string& path) {
  const QifValidation v = validate_qif_file(path);
  CHECK_MESSAGE(v.valid, path << ": " << v.verdict << "\n" << v.errors);
}

// The same for a document in memory, written to `path` first.
inline void check_qif_valid(const std::string& text, const std::string& path) {
  write_text(path, text);
  check_qif_valid_file(path);
}

}  // namespace furrow::test
