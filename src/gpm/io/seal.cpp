#include "gpm/io/seal.hpp"

#include <cstdint>
#include <cstdio>

namespace gpm {

namespace {
// FNV-1a, 64 bits, over the first `n` cells each followed by a tab: not a secret, a tripwire.
std::string fnv_seal(const std::vector<std::string>& row, std::size_t n) {
  uint64_t h = 1469598103934665603ull;
  auto feed = [&](const std::string& cell) {
    for (unsigned char c : cell) h = (h ^ c) * 1099511628211ull;
    h = (h ^ static_cast<unsigned char>('\t')) * 1099511628211ull;
  };
  for (std::size_t i = 0; i < n && i < row.size(); ++i) feed(row[i]);
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}
}  // namespace

std::string row_seal(const std::vector<std::string>& row) {
  return fnv_seal(row, row.empty() ? 0 : row.size() - 1);  // every cell but the seal
}

std::string row_seal_without_checked(const std::vector<std::string>& row) {
  return fnv_seal(row, row.size() >= 2 ? row.size() - 2 : 0);
}

}  // namespace gpm
