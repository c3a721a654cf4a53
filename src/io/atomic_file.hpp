#pragma once
// Output files that appear whole or not at all.
//
// Every file Furrow writes goes to a temporary name in the same directory and
// is renamed into place when complete (rename is atomic on POSIX within one
// file system), so a crash or a failed run never leaves a half-written output
// and a reader never sees one. Folder outputs (plans, reports) are staged the
// same way: built in a sibling temporary folder, then swapped in.
#include <functional>
#include <string>

namespace furrow {

// Writes `content` to `path` atomically. Creates missing parent directories.
// Throws InputError naming the path when it cannot be written.
void write_file_atomically(const std::string& path, const std::string& content);

// Builds a folder atomically: `fill` receives a fresh temporary folder next to
// `path` and writes into it; on success the folder replaces `path` (an older
// folder there is removed), on an exception the temporary folder is deleted
// and the exception propagates.
void write_folder_atomically(const std::string& path,
                             const std::function<void(const std::string& staging)>& fill);

// Refuses to overwrite an input: throws InputError when `output` names the
// same file as `input` (same path after resolving links).
void check_not_overwriting_input(const std::string& output, const std::string& input);

}  // namespace furrow
