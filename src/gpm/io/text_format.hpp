// printf into a std::string of any length: evidence text that prints its numbers as the report
// shows them (%.2f for a rate, %.3e for an error).  Text only, no number of a data row depends
// on it (cmake/fingerprint.cmake lists it as io_only).
#pragma once
#include <string>

namespace gpm {

std::string format_text(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace gpm
