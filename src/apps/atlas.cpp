// atlas — accuracy against cost, from the recorded timings of the studies' own runs.
//
// Reads one or more data files of a study (one row per level and setting, with an error
// column and the wall time the run recorded for that row) and writes
//   --out      the atlas: one row per (task, configuration, level) with rel_error, the
//              recorded time and the pair count, in fixed leading columns that the
//              figure scripts read by position;
//   --reading  for each task and each target error, the cheapest configuration observed
//              that reaches the target (and the next-cheapest other configuration), with
//              a one-line reading generated from the numbers — so the report's prose never
//              types a measured number by hand.
// Nothing is re-timed here: a cost is what the study wrote down.  Where a study timed a
// unit shared by several configurations (one fused pass over all weights), the row carries
// the time of that whole unit and --time-note says so; it is not apportioned by guess.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"

using namespace gpm;

namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == sep) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

// A cell as a number; "NA" (not recorded) as NaN.  Anything else that is no number is an
// error naming file, row and column (TsvTable::number).
double number(const TsvTable& t, std::size_t row, int col) {
  return t.text(row, col) == "NA" ? std::numeric_limits<double>::quiet_NaN() : t.number(row, col);
}

// A configuration column: a data column, or `meta:key` — a `# key = value` header line of
// the file (how the heat tables tell their Δt rules apart).
struct Field {
  std::string name;
  bool from_meta = false;
};

std::vector<Field> fields(const std::vector<std::string>& names) {
  std::vector<Field> out;
  for (auto& n : names) {
    if (n.rfind("meta:", 0) == 0) out.push_back({n.substr(5), true});
    else out.push_back({n, false});
  }
  return out;
}

std::string value(const TsvTable& t, const std::vector<std::string>& row, const Field& f,
                  const std::string& file) {
  if (f.from_meta) {
    auto v = t.get(f.name);
    if (!v) throw InputError("header key '" + f.name + "' not found in " + file);
    std::string compact;  // "0.5 h^2" -> "0.5h^2": one word for the figure scripts
    for (char c : *v)
      if (c != ' ') compact += c;
    return compact;
  }
  return row[t.require_column(f.name)];
}

// Legend label of a configuration: values joined by ',' with spaces removed (gnuplot's
// word() splits on blanks); a short column name (m, θ) is kept as a prefix "m=3".
std::string label(const std::vector<Field>& fs, const std::vector<std::string>& vals) {
  std::vector<std::string> parts;
  for (std::size_t i = 0; i < fs.size(); ++i) {
    std::string v;
    for (char c : vals[i])
      if (c != ' ') v += c;
    parts.push_back(fs[i].name.size() <= 5 ? fs[i].name + "=" + v : v);
  }
  return parts.empty() ? "all" : join(parts, ",");
}

struct Point {
  std::string task, config;
  std::vector<std::string> task_vals, config_vals;
  std::string level;
  double err, time, pairs;
};

std::string g3(double v) {
  if (std::isnan(v)) return "NA";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// The program: options, then the rows of the study's files, then the two tables.
class Atlas {
 public:
  Atlas(int argc, char** argv)
      : a_("atlas",
           "Accuracy against cost: join a study's errors with the wall times and pair counts\n"
           "its own runs recorded; write the atlas and, per target error, the cheapest\n"
           "configuration observed."),
        argc_(argc), argv_(argv) {
    a_.opt("data", "", "comma-separated data files of one study (same columns)");
    a_.opt("study", "", "name of the study (goes into the header)");
    a_.opt("task", "", "comma-separated columns that define a task (operator, function); may be empty");
    a_.opt("config", "", "comma-separated configuration columns; meta:KEY reads a header value");
    a_.opt("level", "level", "level column");
    a_.opt("error", "rel_error", "error column");
    a_.opt("time", "time_s", "time column, or col+col to add columns (pass + Voronoi)");
    a_.opt("pairs", "", "pair-count column (empty: not recorded, written NA)");
    a_.opt("filter", "", "keep rows with col=value (comma-separated conditions, all must hold)");
    a_.opt("time-note", "", "what the time of a row measures (goes into the header)");
    a_.opt("pairs-note", "", "what the pair count of a row counts (goes into the header)");
    a_.opt("targets", "1e-2,1e-3,1e-4", "target relative errors of the reading");
    a_.output("out", "", "atlas TSV");
    a_.output("reading", "", "reading TSV (cheapest configuration per task and target)");
    a_.parse(argc, argv);
    for (const char* req : {"data", "study", "config", "out", "reading"})
      if (a_.str(req).empty()) throw InputError(std::string("--") + req + " is required");
    files_ = a_.list("data");
    task_f_ = fields(a_.str("task").empty() ? std::vector<std::string>{} : a_.list("task"));
    conf_f_ = fields(a_.list("config"));
    time_cols_ = split(a_.str("time"), '+');
    targets_ = a_.nums("targets");
    for (double t : targets_)
      if (!(t > 0)) throw InputError("--targets: every target must be > 0, got " + fmt(t));
    if (!a_.str("filter").empty())
      for (auto& c : a_.list("filter")) {
        const auto eq = c.find('=');
        if (eq == std::string::npos) throw InputError("--filter: expected col=value, got '" + c + "'");
        conds_.emplace_back(c.substr(0, eq), c.substr(eq + 1));
      }
  }

  int run() {
    read_points();
    TsvTable atlas = atlas_table(), reading = reading_table();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    atlas.set("wall_time_s", fmt(wall));
    reading.set("wall_time_s", fmt(wall));
    atlas.save(a_.str("out"));
    reading.save(a_.str("reading"));
    std::fprintf(stderr, "atlas %s: %zu rows, %zu tasks -> %s, %s\n", a_.str("study").c_str(),
                 pts_.size(), tasks_.size(), a_.str("out").c_str(), a_.str("reading").c_str());
    return 0;
  }

 private:
  Args a_;
  int argc_;
  char** argv_;
  const std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
  std::vector<std::string> files_, time_cols_;
  std::vector<Field> task_f_, conf_f_;
  std::vector<double> targets_;
  std::vector<std::pair<std::string, std::string>> conds_;  // --filter's (column, value)
  std::vector<Point> pts_;
  TsvTable first_;  // the first file (its profile and seed go into the header)
  std::vector<std::string> revs_, walls_, tasks_;
  std::size_t dropped_ = 0;

  // Every row of every file that passes the filter and has a finite error and time.
  void read_points() {
    for (std::size_t fi = 0; fi < files_.size(); ++fi) {
      const auto& file = files_[fi];
      const TsvTable t = TsvTable::load(file);
      if (fi == 0) first_ = t;
      revs_.push_back(t.get("git_revision").value_or("?"));
      walls_.push_back(t.get("wall_time_s").value_or("?"));
      const int lc = t.require_column(a_.str("level")), ec = t.require_column(a_.str("error"));
      std::vector<int> tc;
      for (auto& c : time_cols_) tc.push_back(t.require_column(c));
      const int pc = a_.str("pairs").empty() ? -1 : t.require_column(a_.str("pairs"));
      std::vector<int> fc;
      for (auto& [c, v] : conds_) fc.push_back(t.require_column(c));
      for (std::size_t i = 0; i < t.rows.size(); ++i) {
        const auto& r = t.rows[i];
        bool keep = true;
        for (std::size_t k = 0; k < conds_.size(); ++k) keep = keep && r[fc[k]] == conds_[k].second;
        if (!keep) continue;
        Point p;
        for (auto& f : task_f_) p.task_vals.push_back(value(t, r, f, file));
        for (auto& f : conf_f_) p.config_vals.push_back(value(t, r, f, file));
        p.task = label(task_f_, p.task_vals);
        p.config = label(conf_f_, p.config_vals);
        p.level = r[lc];
        p.err = number(t, i, ec);
        p.time = 0;
        for (int c : tc) p.time += number(t, i, c);
        p.pairs = pc < 0 ? std::numeric_limits<double>::quiet_NaN() : number(t, i, pc);
        if (!std::isfinite(p.err) || !std::isfinite(p.time)) {
          ++dropped_;
          continue;
        }
        pts_.push_back(std::move(p));
      }
    }
    if (pts_.empty()) throw InputError("no rows with a finite error and time in " + a_.str("data"));

    for (auto& p : pts_)
      if (std::find(tasks_.begin(), tasks_.end(), p.task) == tasks_.end()) tasks_.push_back(p.task);
  }

  // The header both outputs share: this program's options, the sources' provenance.
  void header(TsvTable& out) const {
    out.set("program", "atlas");
    out.set("study", a_.str("study"));
    for (auto& [k, v] : a_.values()) out.set(k, v);
    std::vector<std::string> argv_s;
    for (int i = 0; i < argc_; ++i) {  // quoted where the shell would split it
      std::string w = argv_[i];
      argv_s.push_back(w.find_first_of(" ;()") == std::string::npos ? w : "'" + w + "'");
    }
    out.set("command", join(argv_s, " "));
    for (const char* k : {"profile", "seed"})
      if (auto v = first_.get(k)) out.set(k, *v);
    out.set("sources", join(files_, ","));
    out.set("source_programs", first_.get("program").value_or("?"));
    out.set("source_git_revisions", join(revs_, ","));
    out.set("source_wall_time_s", join(walls_, ","));
    out.set("rows_dropped_nonfinite", fmt(static_cast<long long>(dropped_)));
    add_provenance(out);
  }

  // One row per (task, configuration, level).
  TsvTable atlas_table() const {
    TsvTable t;
    header(t);
    t.columns = {"task", "config", "level", "rel_error", "time_s", "pairs"};
    for (auto& f : task_f_) t.columns.push_back(f.name);
    for (auto& f : conf_f_) t.columns.push_back(f.name);
    // By position, not by name (TsvRow): the field columns are named by --task/--config and may
    // repeat a fixed name (--config level), which a named row could not tell apart; the row
    // follows the same order as the column list just above.
    for (auto& p : pts_) {
      std::vector<std::string> r = {p.task, p.config, p.level, fmt(p.err), fmt(p.time),
                                    std::isnan(p.pairs) ? "NA" : fmt(p.pairs)};
      r.insert(r.end(), p.task_vals.begin(), p.task_vals.end());
      r.insert(r.end(), p.config_vals.begin(), p.config_vals.end());
      t.add_row(std::move(r));
    }

    return t;
  }

  // Per task and target, the cheapest row reaching the target (ties in time — configurations
  // timed as one unit — go to the smaller error), and the cheapest row of any other
  // configuration, so the reader sees the margin.  Not reached: the smallest error observed,
  // so the table says how far the profile got.
  TsvTable reading_table() const {
    TsvTable t;
    header(t);
    t.columns = {"task", "target", "reached", "config", "level", "rel_error", "time_s",
                       "pairs", "next_config", "next_time_s", "time_ratio", "reading"};
    auto better = [](const Point* a, const Point& b) {
      return !a || b.time < a->time || (b.time == a->time && b.err < a->err);
    };
    for (auto& task : tasks_)
      for (double target : targets_) {
        const Point* best = nullptr;
        for (auto& p : pts_)
          if (p.task == task && p.err <= target && better(best, p)) best = &p;
        if (!best) {
          const Point* low = nullptr;
          for (auto& p : pts_)
            if (p.task == task && (!low || p.err < low->err)) low = &p;
          TsvRow row = t.named_row();
          row["task"] = task, row["target"] = g3(target), row["reached"] = "no";
          row["config"] = low->config, row["level"] = low->level, row["rel_error"] = fmt(low->err);
          row["time_s"] = fmt(low->time), row["pairs"] = std::isnan(low->pairs) ? "NA" : fmt(low->pairs);
          row["next_config"] = "NA", row["next_time_s"] = "NA", row["time_ratio"] = "NA";
          row["reading"] = "not reached; smallest error observed " + g3(low->err) + " (" + low->config +
                           ", level " + low->level + ")";
          t.add_row(row);
          continue;
        }
        const Point* next = nullptr;
        for (auto& p : pts_)
          if (p.task == task && p.err <= target && p.config != best->config && better(next, p))
            next = &p;
        const double ratio = next && best->time > 0 ? next->time / best->time
                                                    : std::numeric_limits<double>::quiet_NaN();
        std::string text = best->config + " at level " + best->level + ": " + g3(best->time) + " s";
        if (!next) text += "; no other choice reaches it";
        else if (next->time == best->time)  // one timed unit covered both
          text += "; " + next->config + " reaches it in the same timed unit";
        else text += "; next other choice " + next->config + " takes " + g3(ratio) + "x as long";
        TsvRow row = t.named_row();
        row["task"] = task, row["target"] = g3(target), row["reached"] = "yes";
        row["config"] = best->config, row["level"] = best->level, row["rel_error"] = fmt(best->err);
        row["time_s"] = fmt(best->time), row["pairs"] = std::isnan(best->pairs) ? "NA" : fmt(best->pairs);
        row["next_config"] = next ? next->config : "NA", row["next_time_s"] = next ? fmt(next->time) : "NA";
        row["time_ratio"] = g3(ratio), row["reading"] = text;
        t.add_row(row);
      }
    return t;
  }
};

int body(int argc, char** argv) { return Atlas(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("atlas", body, argc, argv); }
