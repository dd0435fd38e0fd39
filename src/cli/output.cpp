#include <cerrno>
#include <cstring>
#include <iostream>
#include <stdexcept>

#include "cli/commands.hpp"
#include "gpm/io/provenance.hpp"

namespace gpm::cli {

// The reason of a failed write is read from errno at once, before later calls can overwrite it.
void print(const TsvTable& t) {
  t.write(std::cout);
  if (!std::cout.flush())
    throw std::runtime_error(std::string("cannot write to standard output: ") +
                             std::strerror(errno));
}

TsvTable header_from(const Args& a, const std::string& sub) {
  TsvTable t;
  t.set("program", "gpm " + sub);
  for (auto& [k, v] : a.values()) t.set(k, v);
  add_provenance(t);
  return t;
}

const char* yes(bool b) { return b ? "yes" : "no"; }

}  // namespace gpm::cli
