#include "gpm/studies/judge/snapshot.hpp"

#include <algorithm>
#include <filesystem>

namespace gpm {

bool StoreSnapshot::has(const std::string& name) const {
  auto it = present_.find(name);
  if (it == present_.end()) it = present_.emplace(name, std::filesystem::is_regular_file(path(name))).first;
  return it->second;
}

const TsvTable& StoreSnapshot::table(const std::string& name, bool whole_rows) const {
  auto it = tables_.find(name);
  // Read without the whole-row check once, so a file asked for both ways is read once.
  if (it == tables_.end()) it = tables_.emplace(name, TsvTable::load(path(name), false)).first;
  if (whole_rows) it->second.require_whole_rows();
  return it->second;
}

std::vector<std::string> StoreSnapshot::data_files() const {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir_)) {
    const std::string name = e.path().filename().string();
    if (e.is_regular_file() && name[0] != '.' && name.size() > 4 && name.ends_with(".tsv")) files.push_back(name);
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace gpm
