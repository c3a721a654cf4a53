#pragma once
// What kind of CAD file a path holds, decided before any CAD kernel is
// loaded: the name says STEP or IGES, and the first bytes must agree. A wrong
// file gets a plain answer here instead of whatever OpenCASCADE's parser makes
// of it, and `furrow import notes.txt` never loads OpenCASCADE at all.
//
// Failures: InputError naming the file for a name that is not .step .stp
// .iges .igs (any case), a file that is missing, a folder, unreadable, empty,
// or does not start the way its format starts.
#include <string>

namespace furrow::cad {

enum class Format { step, iges };

// The format a file name says; InputError for any other name.
Format format_of(const std::string& path);

// InputError unless the file exists, is readable, is not empty and starts
// like `format`: "ISO-10303-21" (after an optional UTF-8 byte-order mark and
// blank space) for STEP, an 80-column record with 'S' or 'C' in column 73 for
// IGES.
void check_signature(const std::string& path, Format format);

}  // namespace furrow::cad
