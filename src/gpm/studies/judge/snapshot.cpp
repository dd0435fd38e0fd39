#include "gpm/studies/judge/snapshot.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>

#include "gpm/error.hpp"
#include "gpm/io/seal.hpp"
#include "gpm/studies/define/registry.hpp"

namespace gpm {

namespace {

// The registry's store file of this name (with its study), or none.
std::pair<const RegisteredStudy*, const StoreFile*> registered(const std::string& name) {
  for (const RegisteredStudy& s : study_registry())
    for (const StoreFile& f : s.store_files)
      if (f.name + ".tsv" == name) return {&s, &f};
  return {nullptr, nullptr};
}

// The options that choose a reading or a realization, with the programs' defaults.
const std::map<std::string, std::string>& reading_options() {
  static const std::map<std::string, std::string> o = {
      {"--table", ""}, {"--seed", "1"}, {"--volumes", "lattice"}, {"--h-rule", "h10"},
      {"--dt-rule", "fit"}, {"--jitter", "0.25"}};
  return o;
}

// Those options of an argument list, as given.
std::map<std::string, std::string> reading_of(const std::vector<std::string>& args) {
  std::map<std::string, std::string> out;
  for (std::size_t i = 0; i + 1 < args.size(); ++i)
    if (reading_options().count(args[i])) out[args[i]] = args[i + 1], ++i;
  return out;
}

// The door's checks of a registered file (above); StoreMismatch on the first failure.
void check_store_file(const std::string& path, const TsvTable& t, const RegisteredStudy& study,
                      const StoreFile& file) {
  const std::string program = t.get("program").value_or("");
  if (program != study.program)
    throw StoreMismatch(path + ": its header names the program '" + program + "', the registry's entry '" +
                        study.program + "'");
  std::vector<std::string> cmd;
  std::istringstream in(t.get("command").value_or(""));
  for (std::string w; in >> w;) cmd.push_back(w);
  const auto ran = reading_of(cmd), want = reading_of(study.command_args(file.args));
  for (const auto& [opt, def] : reading_options()) {
    const auto a = ran.find(opt), b = want.find(opt);
    const std::string got = a == ran.end() ? def : a->second, expected = b == want.end() ? def : b->second;
    if (got != expected)
      throw StoreMismatch(path + ": written with " + opt + " " + (got.empty() ? "(none)" : got) +
                          ", but the registry's file is " + opt + " " + (expected.empty() ? "(none)" : expected) +
                          " (a file of another reading or realization under this name?)");
  }
  if (t.columns.empty() || t.columns.back() != "seal")
    throw StoreMismatch(path + ": its rows carry no seal column");
  if (const std::string problem = header_seal_problem(t.meta, path); !problem.empty())
    throw StoreMismatch(path + ": " + problem);
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    if (t.rows[r].size() != t.columns.size() || t.rows[r].back() != row_seal(t.rows[r], path))
      throw StoreMismatch(path + ": data row " + std::to_string(r + 1) +
                          ": its seal does not match its cells and this file's name (edited after it was "
                          "written, pasted from another file, or the file renamed?)");
}

}  // namespace

bool StoreSnapshot::has(const std::string& name) const {
  auto it = present_.find(name);
  if (it == present_.end()) it = present_.emplace(name, std::filesystem::is_regular_file(path(name))).first;
  if (!it->second && checks_ == StoreChecks::store)
    if (auto [study, file] = registered(name); study)
      throw StoreMismatch(path(name) + ": missing (a store file of the registry's study " + study->name + ")");
  return it->second;
}

const TsvTable& StoreSnapshot::table(const std::string& name, bool whole_rows) const {
  auto it = tables_.find(name);
  // Read without the whole-row check once, so a file asked for both ways is read once.
  if (it == tables_.end()) {
    TsvTable t = TsvTable::load(path(name), false);
    if (checks_ == StoreChecks::store)
      if (auto [study, file] = registered(name); study) {
        t.require_whole_rows();  // a malformed row stays an input error, named as before
        check_store_file(path(name), t, *study, *file);
      }
    it = tables_.emplace(name, std::move(t)).first;
  }
  if (whole_rows) it->second.require_whole_rows();
  return it->second;
}

const TsvTable& PublishedTables::file(const std::string& name) const {
  auto it = tables_.find(name);
  if (it == tables_.end()) {
    const std::string path = dir_ + "/" + name;
    if (!std::filesystem::exists(path)) throw InputError("no published file " + path);
    it = tables_.emplace(name, TsvTable::load(path)).first;
  }
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
