#pragma once
// Rewrites the CRTN and PREF fields of every type 142 (curve on a
// parametric surface) in an IGES file's text, so that one file written by
// OpenCASCADE can be read in every combination other writers use
// (docs/formats.md "IGES boundaries"): CRTN says how the curve was made
// (0 unspecified, 1 projection, 2 intersection, 3 isoparametric), PREF
// which representation to prefer (0 unspecified, 1 parameter space, 2
// model space, 3 both alike).
//
// Only the first Parameter Data line of each entity is read and written
// (a type 142 is six short fields); the line keeps its columns 65-80.
// Throws std::logic_error when a 142 does not fit that form, so a test
// never silently checks a file it did not rewrite.
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace furrow::test {

struct CurveOnSurfaceFields {
  int rewritten = 0;        // type 142 entities rewritten
  int model_space_only = 0;  // of which with PPTR 0 (no parameter-space curve)
};

inline CurveOnSurfaceFields set_curve_on_surface_fields(std::string& text, int crtn, int pref) {
  CurveOnSurfaceFields counts;
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  for (std::string& line : lines) {
    if (line.size() < 73 || line[72] != 'P' || line.compare(0, 4, "142,") != 0) continue;
    // Fields 142, CRTN, SPTR, PPTR, CPTR, PREF, then ';' or further fields.
    std::vector<std::size_t> commas;
    for (std::size_t k = 0; k < 64 && commas.size() < 5; ++k)
      if (line[k] == ',') commas.push_back(k);
    if (commas.size() < 5) throw std::logic_error("type 142 over more than one line: " + line);
    std::size_t end = commas[4] + 1;
    while (end < 64 && line[end] != ',' && line[end] != ';') ++end;
    if (end >= 64) throw std::logic_error("type 142 PREF not ended on its line: " + line);
    const std::string pptr = line.substr(commas[2] + 1, commas[3] - commas[2] - 1);
    const std::string data = "142," + std::to_string(crtn) + line.substr(commas[1], commas[4] - commas[1] + 1) +
                             std::to_string(pref) + line.substr(end, 64 - end);
    std::string trimmed = data;
    while (trimmed.size() > 64 && trimmed.back() == ' ') trimmed.pop_back();
    if (trimmed.size() > 64) throw std::logic_error("rewritten type 142 too long: " + data);
    line = trimmed + std::string(64 - trimmed.size(), ' ') + line.substr(64);
    ++counts.rewritten;
    if (std::stoi(pptr) == 0) ++counts.model_space_only;
  }
  std::string out;
  for (const std::string& line : lines) out += line + "\n";
  text = std::move(out);
  return counts;
}

}  // namespace furrow::test
