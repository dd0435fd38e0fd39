#include "gpm/io/seal.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>

namespace gpm {

namespace {
constexpr uint64_t kOffset = 1469598103934665603ull, kPrime = 1099511628211ull;

// FNV-1a, 64 bits, continued from `h` over the first `n` cells each followed by a tab: not a
// secret, a tripwire.
uint64_t feed_cells(uint64_t h, const std::vector<std::string>& row, std::size_t n) {
  auto feed = [&](const std::string& cell) {
    for (unsigned char c : cell) h = (h ^ c) * kPrime;
    h = (h ^ static_cast<unsigned char>('\t')) * kPrime;
  };
  for (std::size_t i = 0; i < n && i < row.size(); ++i) feed(row[i]);
  return h;
}
std::string hex(uint64_t h) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}
std::size_t but_seal(const std::vector<std::string>& row) { return row.empty() ? 0 : row.size() - 1; }
}  // namespace

std::string sealed_name(const std::string& path) { return std::filesystem::path(path).stem().string(); }

std::string row_seal(const std::vector<std::string>& row, const std::string& path) {
  return hex(feed_cells(feed_cells(kOffset, {sealed_name(path)}, 1), row, but_seal(row)));
}

std::string header_seal(const HeaderLines& meta, const std::string& path) {
  uint64_t h = feed_cells(kOffset, {sealed_name(path)}, 1);
  for (const auto& [key, value] : meta)
    if (key != "header_seal") h = feed_cells(h, {key, value}, 2);
  return hex(h);
}

std::string header_seal_problem(const HeaderLines& meta, const std::string& path) {
  const std::string* have = nullptr;
  for (const auto& [key, value] : meta)
    if (key == "header_seal") have = &value;
  if (!have) return "its header carries no header_seal line";
  if (*have != header_seal(meta, path))
    return "its header's seal does not match its lines and this file's name (a header line edited after "
           "it was written?)";
  return "";
}

std::string row_seal_unbound(const std::vector<std::string>& row) {
  return hex(feed_cells(kOffset, row, but_seal(row)));
}

std::string row_seal_without_checked(const std::vector<std::string>& row) {
  return hex(feed_cells(kOffset, row, row.size() >= 2 ? row.size() - 2 : 0));
}

}  // namespace gpm
