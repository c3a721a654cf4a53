// A CAD file's format from its name and first bytes (contract in
// cad_file_format.hpp).
#include "io/cad/cad_file_format.hpp"

#include <filesystem>
#include <fstream>

#include "base/error.hpp"
#include "base/text_fields.hpp"

namespace furrow::cad {

Format format_of(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".step" || ext == ".stp") return Format::step;
  if (ext == ".iges" || ext == ".igs") return Format::iges;
  throw InputError(path + ": not a CAD file name (expected .step, .stp, .iges or .igs)");
}

void check_signature(const std::string& path, Format format) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": no such file");
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the file for reading");
  std::string head(4096, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (trim(head).empty()) throw InputError(path + ": the file is empty");
  if (format == Format::step) {
    std::size_t start = head.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;  // UTF-8 BOM
    start = head.find_first_not_of(" \t\r\n", start);
    if (start == std::string::npos || head.compare(start, 12, "ISO-10303-21") != 0)
      throw InputError(path + ": not a STEP file (a STEP file starts with \"ISO-10303-21;\")");
  } else {
    const std::string first_line = head.substr(0, head.find('\n'));
    if (first_line.size() < 73 || (first_line[72] != 'S' && first_line[72] != 'C'))
      throw InputError(path + ": not an IGES file (an IGES file starts with 80-column records, "
                              "the first with 'S' in column 73)");
  }
}

}  // namespace furrow::cad
