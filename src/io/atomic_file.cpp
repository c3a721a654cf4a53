#include "io/atomic_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "geometry/error.hpp"

namespace furrow {

namespace fs = std::filesystem;

namespace {

std::string temporary_sibling(const fs::path& target) {
  // pid + counter: unique within a process and across concurrent runs.
  static int counter = 0;
  return (target.parent_path() /
          ("." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
           std::to_string(counter++)))
      .string();
}

void ensure_parent(const fs::path& target) {
  const fs::path parent = target.parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) throw InputError(target.string() + ": cannot create folder " + parent.string() + ": " +
                           ec.message());
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& content) {
  const fs::path target(path);
  if (target.filename().empty()) throw InputError(path + ": not a file name");
  ensure_parent(target);
  const std::string tmp = temporary_sibling(target);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path + ": cannot write the file");
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) {
      out.close();
      std::remove(tmp.c_str());
      throw InputError(path + ": writing failed (disk full?)");
    }
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw InputError(path + ": cannot move the finished file into place: " + ec.message());
  }
}

void write_folder_atomically(const std::string& path,
                             const std::function<void(const std::string& staging)>& fill) {
  fs::path target(path);
  if (target.filename().empty()) target = target.parent_path();  // "reports/demo/"
  ensure_parent(target);
  const fs::path staging = temporary_sibling(target);
  std::error_code ec;
  fs::create_directories(staging, ec);
  if (ec) throw InputError(path + ": cannot create a folder: " + ec.message());
  try {
    fill(staging.string());
  } catch (...) {
    fs::remove_all(staging, ec);
    throw;
  }
  // Swap: move any old folder aside first, so the target is never half old,
  // half new; then drop the old one.
  fs::path old;
  if (fs::exists(target)) {
    old = temporary_sibling(target);
    fs::rename(target, old, ec);
    if (ec) {
      fs::remove_all(staging, ec);
      throw InputError(path + ": cannot replace the existing folder: " + ec.message());
    }
  }
  fs::rename(staging, target, ec);
  if (ec) {
    fs::remove_all(staging, ec);
    if (!old.empty()) fs::rename(old, target, ec);
    throw InputError(path + ": cannot move the finished folder into place");
  }
  if (!old.empty()) fs::remove_all(old, ec);
}

void check_not_overwriting_input(const std::string& output, const std::string& input) {
  std::error_code ec;
  if (fs::exists(output, ec) && fs::exists(input, ec) && fs::equivalent(output, input, ec))
    throw InputError(output + ": the output would overwrite the input " + input);
}

}  // namespace furrow
