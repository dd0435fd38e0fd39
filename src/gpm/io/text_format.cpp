#include "gpm/io/text_format.hpp"

#include <cstdarg>
#include <cstdio>

namespace gpm {

std::string format_text(const char* f, ...) {
  va_list args, again;
  va_start(args, f);
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, f, args);  // the length first, then the text
  va_end(args);
  const std::size_t len = static_cast<std::size_t>(n > 0 ? n : 0);
  std::string s(len + 1, '\0');
  std::vsnprintf(s.data(), s.size(), f, again);
  va_end(again);
  s.resize(len);
  return s;
}

std::string clip_long_words(const std::string& text, std::size_t longest) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    std::size_t j = i;
    while (j < text.size() && text[j] != ' ' && text[j] != '\t') ++j;
    if (j - i > longest)
      out.append(text, i, longest) += " [... " + std::to_string(j - i) + " characters]";
    else
      out.append(text, i, j - i);
    if (j < text.size()) out += text[j++];
    i = j;
  }
  return out;
}

}  // namespace gpm
