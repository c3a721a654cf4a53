#include "base/atomic_file.hpp"

#include "base/output_set.hpp"

namespace furrow {

void write_file_atomically(const std::string& path, const std::string& content) {
  OutputSet out;
  out.file(path, content);
  out.publish();
}

void write_folder_atomically(const std::string& path,
                             const std::function<void(const std::string& staging)>& fill) {
  OutputSet out;
  fill(out.folder(path));
  out.publish();
}

}  // namespace furrow
