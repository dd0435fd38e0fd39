#include "gpm/io/provenance.hpp"

#include <omp.h>

#include <ctime>
#include <fstream>
#include <string_view>

namespace gpm {

namespace generated {
struct ProgramFingerprint {
  std::string_view program, fingerprint;
};
extern const std::string_view kGitRevision;
extern const std::string_view kCoreFingerprint;
extern const ProgramFingerprint kProgramFingerprints[];
}  // namespace generated

namespace {
std::string g_program;
}

const std::string& git_revision() {
  static const std::string rev(generated::kGitRevision);
  return rev;
}

void set_program(const std::string& name) { g_program = name; }
const std::string& program_name() { return g_program; }

std::string code_fingerprint(const std::string& program) {
  for (const auto* e = generated::kProgramFingerprints; !e->program.empty(); ++e)
    if (e->program == program) return std::string(e->fingerprint);
  return "core-" + std::string(generated::kCoreFingerprint);
}

std::string code_fingerprint() { return code_fingerprint(g_program); }

std::vector<std::string> fingerprinted_programs() {
  std::vector<std::string> v;
  for (const auto* e = generated::kProgramFingerprints; !e->program.empty(); ++e)
    v.emplace_back(e->program);
  return v;
}

std::string machine_summary() {
  std::string cpu = "unknown CPU";
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) {
      const auto c = line.find(':');
      if (c != std::string::npos) cpu = line.substr(line.find_first_not_of(' ', c + 1));
      break;
    }
  char date[16];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  return cpu + ", " + std::to_string(omp_get_max_threads()) + " threads, " + date;
}

}  // namespace gpm
