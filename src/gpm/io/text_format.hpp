// printf into a std::string of any length: evidence text that prints its numbers as the report
// shows them (%.2f for a rate, %.3e for an error).  Text only, no number of a data row depends
// on it (io/ outside tsv is outside the code fingerprint: cmake/fingerprint.cmake).
#pragma once
#include <string>

namespace gpm {

std::string format_text(const char* format, ...) __attribute__((format(printf, 1, 2)));

// A message that echoes input names the place, not the payload: every run of more than
// `longest` characters without a space or tab (a cell, a path, an option value) is cut to its
// first `longest` characters and " [... N characters]".  A 10 MB cell makes a line, not 10 MB.
std::string clip_long_words(const std::string& text, std::size_t longest = 200);

}  // namespace gpm
