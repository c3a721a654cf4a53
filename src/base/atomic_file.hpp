#pragma once
// One output that appears whole or not at all: the single-output case of
// output_set.hpp, for library code that writes one file or one folder.
// Commands that write several outputs stage them in one OutputSet instead,
// so that the set is published together.
#include <functional>
#include <string>

namespace furrow {

// Writes `content` to `path` atomically (a temporary sibling renamed into
// place). Creates missing parent directories. Throws InputError naming the
// path when it cannot be written.
void write_file_atomically(const std::string& path, const std::string& content);

// Builds a folder atomically: `fill` receives a fresh temporary folder next to
// `path` and writes into it; on success the folder replaces `path` (an older
// folder there is removed), on an exception the temporary folder is deleted
// and the exception propagates.
void write_folder_atomically(const std::string& path,
                             const std::function<void(const std::string& staging)>& fill);

}  // namespace furrow
