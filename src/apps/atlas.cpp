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

int body(int argc, char** argv) {
  Args a("atlas",
         "Accuracy against cost: join a study's errors with the wall times and pair counts\n"
         "its own runs recorded; write the atlas and, per target error, the cheapest\n"
         "configuration observed.");
  a.opt("data", "", "comma-separated data files of one study (same columns)");
  a.opt("study", "", "name of the study (goes into the header)");
  a.opt("task", "", "comma-separated columns that define a task (operator, function); may be empty");
  a.opt("config", "", "comma-separated configuration columns; meta:KEY reads a header value");
  a.opt("level", "level", "level column");
  a.opt("error", "rel_error", "error column");
  a.opt("time", "time_s", "time column, or col+col to add columns (pass + Voronoi)");
  a.opt("pairs", "", "pair-count column (empty: not recorded, written NA)");
  a.opt("filter", "", "keep rows with col=value (comma-separated conditions, all must hold)");
  a.opt("time-note", "", "what the time of a row measures (goes into the header)");
  a.opt("pairs-note", "", "what the pair count of a row counts (goes into the header)");
  a.opt("targets", "1e-2,1e-3,1e-4", "target relative errors of the reading");
  a.output("out", "", "atlas TSV");
  a.output("reading", "", "reading TSV (cheapest configuration per task and target)");
  a.parse(argc, argv);
  for (const char* req : {"data", "study", "config", "out", "reading"})
    if (a.str(req).empty()) throw InputError(std::string("--") + req + " is required");
  const auto t0 = std::chrono::steady_clock::now();
  const auto files = a.list("data");
  const auto task_f = fields(a.str("task").empty() ? std::vector<std::string>{} : a.list("task"));
  const auto conf_f = fields(a.list("config"));
  const auto time_cols = split(a.str("time"), '+');
  const auto targets = a.nums("targets");
  for (double t : targets)
    if (!(t > 0)) throw InputError("--targets: every target must be > 0, got " + fmt(t));
  std::vector<std::pair<std::string, std::string>> conds;
  if (!a.str("filter").empty())
    for (auto& c : a.list("filter")) {
      const auto eq = c.find('=');
      if (eq == std::string::npos) throw InputError("--filter: expected col=value, got '" + c + "'");
      conds.emplace_back(c.substr(0, eq), c.substr(eq + 1));
    }

  // Read every row of every file; keep those that pass the filter and have a finite error.
  std::vector<Point> pts;
  TsvTable first;
  std::vector<std::string> revs, walls;
  std::size_t dropped = 0;
  for (std::size_t fi = 0; fi < files.size(); ++fi) {
    const auto& file = files[fi];
    const TsvTable t = TsvTable::load(file);
    if (fi == 0) first = t;
    revs.push_back(t.get("git_revision").value_or("?"));
    walls.push_back(t.get("wall_time_s").value_or("?"));
    const int lc = t.require_column(a.str("level")), ec = t.require_column(a.str("error"));
    std::vector<int> tc;
    for (auto& c : time_cols) tc.push_back(t.require_column(c));
    const int pc = a.str("pairs").empty() ? -1 : t.require_column(a.str("pairs"));
    std::vector<int> fc;
    for (auto& [c, v] : conds) fc.push_back(t.require_column(c));
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      const auto& r = t.rows[i];
      bool keep = true;
      for (std::size_t k = 0; k < conds.size(); ++k) keep = keep && r[fc[k]] == conds[k].second;
      if (!keep) continue;
      Point p;
      for (auto& f : task_f) p.task_vals.push_back(value(t, r, f, file));
      for (auto& f : conf_f) p.config_vals.push_back(value(t, r, f, file));
      p.task = label(task_f, p.task_vals);
      p.config = label(conf_f, p.config_vals);
      p.level = r[lc];
      p.err = number(t, i, ec);
      p.time = 0;
      for (int c : tc) p.time += number(t, i, c);
      p.pairs = pc < 0 ? std::numeric_limits<double>::quiet_NaN() : number(t, i, pc);
      if (!std::isfinite(p.err) || !std::isfinite(p.time)) {
        ++dropped;
        continue;
      }
      pts.push_back(std::move(p));
    }
  }
  if (pts.empty()) throw InputError("no rows with a finite error and time in " + a.str("data"));

  // Header shared by both outputs: this program's options, the sources' provenance.
  auto header = [&](TsvTable& out) {
    out.set("program", "atlas");
    out.set("study", a.str("study"));
    for (auto& [k, v] : a.values()) out.set(k, v);
    std::vector<std::string> argv_s;
    for (int i = 0; i < argc; ++i) {  // quoted where the shell would split it
      std::string w = argv[i];
      argv_s.push_back(w.find_first_of(" ;()") == std::string::npos ? w : "'" + w + "'");
    }
    out.set("command", join(argv_s, " "));
    for (const char* k : {"profile", "seed"})
      if (auto v = first.get(k)) out.set(k, *v);
    out.set("sources", join(files, ","));
    out.set("source_programs", first.get("program").value_or("?"));
    out.set("source_git_revisions", join(revs, ","));
    out.set("source_wall_time_s", join(walls, ","));
    out.set("rows_dropped_nonfinite", fmt(static_cast<long long>(dropped)));
    add_provenance(out);
  };

  TsvTable atlas;
  header(atlas);
  atlas.columns = {"task", "config", "level", "rel_error", "time_s", "pairs"};
  for (auto& f : task_f) atlas.columns.push_back(f.name);
  for (auto& f : conf_f) atlas.columns.push_back(f.name);
  // By position, not by name (TsvRow): the field columns are named by --task/--config and may
  // repeat a fixed name (--config level), which a named row could not tell apart; the row
  // follows the same order as the column list just above.
  for (auto& p : pts) {
    std::vector<std::string> r = {p.task, p.config, p.level, fmt(p.err), fmt(p.time),
                                  std::isnan(p.pairs) ? "NA" : fmt(p.pairs)};
    r.insert(r.end(), p.task_vals.begin(), p.task_vals.end());
    r.insert(r.end(), p.config_vals.begin(), p.config_vals.end());
    atlas.add_row(std::move(r));
  }

  // The reading: per task and target, the cheapest row reaching the target (ties in time —
  // configurations timed as one unit — go to the smaller error), and the cheapest row of
  // any other configuration, so the reader sees the margin.  Not reached: the smallest
  // error observed, so the table says how far the profile got.
  TsvTable reading;
  header(reading);
  reading.columns = {"task", "target", "reached", "config", "level", "rel_error", "time_s",
                     "pairs", "next_config", "next_time_s", "time_ratio", "reading"};
  std::vector<std::string> tasks;
  for (auto& p : pts)
    if (std::find(tasks.begin(), tasks.end(), p.task) == tasks.end()) tasks.push_back(p.task);
  auto better = [](const Point* a, const Point& b) {
    return !a || b.time < a->time || (b.time == a->time && b.err < a->err);
  };
  for (auto& task : tasks)
    for (double target : targets) {
      const Point* best = nullptr;
      for (auto& p : pts)
        if (p.task == task && p.err <= target && better(best, p)) best = &p;
      if (!best) {
        const Point* low = nullptr;
        for (auto& p : pts)
          if (p.task == task && (!low || p.err < low->err)) low = &p;
        TsvRow row = reading.named_row();
        row["task"] = task, row["target"] = g3(target), row["reached"] = "no";
        row["config"] = low->config, row["level"] = low->level, row["rel_error"] = fmt(low->err);
        row["time_s"] = fmt(low->time), row["pairs"] = std::isnan(low->pairs) ? "NA" : fmt(low->pairs);
        row["next_config"] = "NA", row["next_time_s"] = "NA", row["time_ratio"] = "NA";
        row["reading"] = "not reached; smallest error observed " + g3(low->err) + " (" + low->config +
                         ", level " + low->level + ")";
        reading.add_row(row);
        continue;
      }
      const Point* next = nullptr;
      for (auto& p : pts)
        if (p.task == task && p.err <= target && p.config != best->config && better(next, p))
          next = &p;
      const double ratio = next && best->time > 0 ? next->time / best->time
                                                  : std::numeric_limits<double>::quiet_NaN();
      std::string text = best->config + " at level " + best->level + ": " + g3(best->time) + " s";
      if (!next) text += "; no other choice reaches it";
      else if (next->time == best->time)  // one timed unit covered both
        text += "; " + next->config + " reaches it in the same timed unit";
      else text += "; next other choice " + next->config + " takes " + g3(ratio) + "x as long";
      TsvRow row = reading.named_row();
      row["task"] = task, row["target"] = g3(target), row["reached"] = "yes";
      row["config"] = best->config, row["level"] = best->level, row["rel_error"] = fmt(best->err);
      row["time_s"] = fmt(best->time), row["pairs"] = std::isnan(best->pairs) ? "NA" : fmt(best->pairs);
      row["next_config"] = next ? next->config : "NA", row["next_time_s"] = next ? fmt(next->time) : "NA";
      row["time_ratio"] = g3(ratio), row["reading"] = text;
      reading.add_row(row);
    }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  atlas.set("wall_time_s", fmt(wall));
  reading.set("wall_time_s", fmt(wall));
  atlas.save(a.str("out"));
  reading.save(a.str("reading"));
  std::fprintf(stderr, "atlas %s: %zu rows, %zu tasks -> %s, %s\n", a.str("study").c_str(),
               pts.size(), tasks.size(), a.str("out").c_str(), a.str("reading").c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return run_main("atlas", body, argc, argv); }
