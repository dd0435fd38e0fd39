#include "gpm/studies/runner.hpp"

#include <cstdarg>
#include <cstdio>

#include "gpm/error.hpp"
#include "gpm/io/tsv.hpp"

namespace gpm {

StudyRunner::StudyRunner(std::string program, std::string summary, std::string profile_help,
                         Kind kind)
    : program_(std::move(program)), args_(program_, std::move(summary)), kind_(kind) {
  args_.output("out", "", "data file (required)")
      .opt("profile", "quick", profile_help)
      .opt("levels", "", "comma-separated levels k (dx = 2^-k); default: the profile's");
  if (kind_ == Kind::units) args_.opt("seed", "1", "jitter seed (non-negative integer)");
}

void StudyRunner::parse(int argc, char** argv) {
  if (kind_ == Kind::units) add_cache_options(args_);
  args_.parse(argc, argv);
  out_ = args_.required("out");
  profile_ = parse_profile(args_.str("profile"));
  if (kind_ == Kind::units) {
    mode_ = cache_mode(args_);
    seed_ = args_.seed();
  }
  start_ = std::chrono::steady_clock::now();
}

std::vector<int> StudyRunner::levels(const std::vector<int>& quick,
                                     const std::vector<int>& paper, int lo, int hi) const {
  return levels_option(args_, profile_, quick, paper, lo, hi);
}

LevelCache& StudyRunner::open(std::vector<std::pair<std::string, std::string>> params,
                              std::vector<std::string> columns, int key_columns) {
  cache_ = std::make_unique<LevelCache>(out_, std::move(params), std::move(columns),
                                        key_columns, mode_);
  if (cache_->reused() > 0)
    std::fprintf(stderr, "[%s] reusing %zu stored rows of %s\n", program_.c_str(),
                 cache_->reused(), out_.c_str());
  return *cache_;
}

void StudyRunner::expect(double work, const char* unit) {
  progress_ = std::make_unique<Progress>(program_, work, unit, 0.0);
}

void StudyRunner::unit_done(double work, const std::string& line) {
  cache_->table().set("wall_time_s", elapsed_s());
  cache_->table().set("peak_rss_mib", peak_rss_mib());
  cache_->save();
  std::fprintf(stderr, "[%s] %s\n", program_.c_str(), line.c_str());
  done_ += work;
  if (progress_) progress_->update(done_);
}

void StudyRunner::save_level(TsvTable& t, double work, const std::string& line) {
  t.set("wall_time_s", elapsed_s());
  t.set("peak_rss_mib", peak_rss_mib());
  t.save(out_);
  std::fprintf(stderr, "[%s] %s\n", program_.c_str(), line.c_str());
  done_ += work;
  if (progress_) progress_->update(done_);
}

bool StudyRunner::finish() {
  if (progress_) progress_->finish();
  if (!cache_) return true;
  cache_->finish();
  if (!cache_->writes()) return false;
  if (cache_->rows().empty()) throw InputError("no level selected: nothing to write to " + out_);
  std::printf("%s: wrote %s (%zu rows, %zu reused, %.1f s)\n", program_.c_str(), out_.c_str(),
              cache_->rows().size(), cache_->reused(), elapsed_s());
  return true;
}

double StudyRunner::elapsed_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::string line_printf(const char* format, ...) {
  char buf[1024];
  va_list ap;
  va_start(ap, format);
  std::vsnprintf(buf, sizeof buf, format, ap);
  va_end(ap);
  return buf;
}

}  // namespace gpm
