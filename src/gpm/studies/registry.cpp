#include "gpm/studies/registry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gpm/error.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/io/args.hpp"
#include "gpm/studies/catalog.hpp"
#include "gpm/studies/heat_tables.hpp"
#include "gpm/studies/thesis_truncation.hpp"

namespace gpm {

namespace {

double dx_of(int k) { return std::ldexp(1.0, -k); }
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// --- Reading a data file back: a unit's time is repeated on each of its rows (the first
// is kept), its level and numbers by column name (a non-number: NaN). -----------------------
struct Rows {
  const TsvTable& d;
  RecordedUnits& out;
  int level(const std::vector<std::string>& r) const {
    return static_cast<int>(parse_number(r[d.require_column("level")], "level"));
  }
  double v(const std::vector<std::string>& r, const char* name) const {
    try {
      return parse_number(r[d.require_column(name)], "value");
    } catch (const InputError&) {
      return kNaN;
    }
  }
  const std::string& text(const std::vector<std::string>& r, const char* name) const {
    return r[d.require_column(name)];
  }
  void put(const std::string& var, int k, double s, double work) const {
    out.emplace(std::make_pair(var, k), RecordedUnit{s, work});
  }
};

// --- The studies ----------------------------------------------------------------------------

// imoto §5: one fused pass per (level, m), nine weights.
RegisteredStudy imoto() {
  RegisteredStudy s{"imoto_fig5_table1", {"imoto_fig5_table1"}, {}, {}};
  s.plan = [](UnitPricer& p) {
    for (int k : p.paper() ? imoto_study().levels.paper : imoto_study().levels.quick)
      for (double m : imoto_study().orders)
        p.add_fused("imoto_fig5_table1", "m=" + fmt(m), k, imoto_h(m, dx_of(k)), "imoto9");
  };
  s.recorded = [](const std::string&, const TsvTable& d, const PlannedPairs&, RecordedUnits& out) {
    const Rows rows{d, out};
    for (auto& r : d.rows) rows.put("m=" + rows.text(r, "m"), rows.level(r), rows.v(r, "time_s"), rows.v(r, "pairs"));
  };
  return s;
}

// Thesis Tables 4.1–4.3: one fused pass per (h reading, volumes, level); Voronoi once per level.
RegisteredStudy thesis_truncation(const ThesisTableSpec& t) {
  RegisteredStudy s{t.program, {t.program}, {}, {}};
  s.plan = [&t](UnitPricer& p) {
    std::vector<int> all;
    for (HReading r : t.readings) {
      const auto& lv = p.paper() ? t.paper_levels : (r == HReading::printed ? t.quick_printed : t.quick_scaled);
      all.insert(all.end(), lv.begin(), lv.end());
      for (int k : lv)
        for (const char* vol : {"voronoi", "uniform"})
          if (!(p.paper() && std::string(vol) == "uniform" && k > t.paper_uniform_max_level)) {
            p.add_fused(t.program, h_reading_name(r) + "/" + vol, k, thesis_h(r, t.c, t.p, dx_of(k)), t.mix());
            if (p.paper() && r == HReading::printed && k > t.paper_printed_max_level)
              p.units().back().trimmed = "printed reading stops at 2^-" + fmt(t.paper_printed_max_level);
          }
    }
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    for (int k : all) p.add_voronoi(t.program, "voronoi", k);
  };
  s.recorded = [](const std::string&, const TsvTable& d, const PlannedPairs&, RecordedUnits& out) {
    const Rows rows{d, out};
    for (auto& r : d.rows) {
      const int k = rows.level(r);
      rows.put(rows.text(r, "h_reading") + "/" + rows.text(r, "volumes"), k, rows.v(r, "time_s"),
               rows.v(r, "pairs"));
      const double vs = rows.v(r, "voronoi_s");  // the level's Voronoi time, on each of its rows
      if (vs > 0) {
        auto& slot = out[{"voronoi", k}];
        slot.seconds = std::max(slot.seconds, vs);
        slot.pair_interactions = kNaN;
      }
    }
  };
  return s;
}

// Table 4.4: per (h rule, weight, level) the Laplacian's set-up and a CG solve, its
// iterations carried from 2^-5 as 1/h.
RegisteredStudy poisson() {
  RegisteredStudy s{"thesis_table4_4", {"thesis_table4_4"}, {}, {}};
  s.plan = [](UnitPricer& p) {
    const Calibration& c = p.cal();
    for (int k : p.paper() ? poisson_table().levels.paper : poisson_table().levels.quick)
      for (const char* rule : {"h10", "h15"})
        for (auto& w : pde_weights()) {
          PlanUnit u = p.base("thesis_table4_4", std::string(rule) + "/" + w, k, pde_h(rule, dx_of(k)));
          const bool as = p.is_assembled(u);
          const double its = c.poisson_its.at(std::string(rule) + "/" + w) * pde_h(rule, dx_of(5)) / u.h;
          u.products = its + 2;
          u.method = as ? "assembled" : "matrix_free";
          const double setup = p.laplacian_setup_s(u, as);
          u.time_s = setup + u.products * p.product_s(u, as);
          u.time_before_s = setup + u.products * p.product_before_s(u);
          u.mem_mib = p.pde_mib(u, as);
          u.basis = "setup + (CG its " + fmt(std::round(its)) + " + 2) products";
          p.units().push_back(u);
        }
  };
  s.recorded = [](const std::string&, const TsvTable& d, const PlannedPairs&, RecordedUnits& out) {
    const Rows rows{d, out};
    for (auto& r : d.rows)
      rows.put(rows.text(r, "h_rule") + "/" + rows.text(r, "weight"), rows.level(r), rows.v(r, "seconds"),
               rows.v(r, "nnz") * (rows.v(r, "cg_iterations") + 2));
  };
  return s;
}

// The data file of a heat table under an h rule (the catalog's two readings).
std::string heat_file(const HeatTable& hp, const char* rule) {
  std::string name = "thesis_table" + hp.table + (std::string(rule) == "h15" ? "_h15" : "");
  std::replace(name.begin(), name.end(), '.', '_');
  return name;
}

// Tables 4.5–4.7 under both h rules: K = ⌈T/Δt₀⌉ steps, one product per step (M·U^k, which
// also serves the CG's initial and true residuals) plus (θ > 0) the CG iterations; the
// Laplacian's set-up once per (level, weight), not in the per-row seconds.
RegisteredStudy heat(const HeatTable& hp) {
  RegisteredStudy s{heat_file(hp, "h10"), {heat_file(hp, "h10"), heat_file(hp, "h15")}, {}, {}};
  s.plan = [&hp](UnitPricer& p) {
    for (const char* rule : {"h10", "h15"}) {
      const std::string study = heat_file(hp, rule);
      const std::vector<int> run = heat_levels(hp, p.paper(), rule);
      for (int k : p.paper() ? hp.paper : hp.quick)
        for (auto& w : pde_weights()) {
          const std::string trimmed =
              std::find(run.begin(), run.end(), k) == run.end()
                  ? "h15 reading stops at 2^-" + fmt(hp.paper_h15_max_level) + " (Table 4.4 settles h10)"
                  : "";
          const double h = pde_h(rule, dx_of(k));
          PlanUnit a = p.base(study, "setup/" + w, k, h);
          const bool as = p.is_assembled(a);
          a.method = as ? "assembled" : "matrix_free";
          a.time_s = p.laplacian_setup_s(a, as);
          a.time_before_s = a.time_s;
          a.mem_mib = p.pde_mib(a, as);
          a.recorded = false;
          a.basis = "Laplacian set-up (not in the rows' seconds)";
          a.trimmed = trimmed;
          p.units().push_back(a);
          const double K = p.heat_steps(hp.table, h);
          for (double th : hp.thetas) {
            PlanUnit u = p.base(study, w + "/theta=" + fmt(th), k, h);
            const double its = p.heat_cg_its(hp.table, rule, w, th, h);
            u.products = K * (1 + its);
            u.method = a.method;
            u.time_s = u.products * p.product_s(u, as);
            u.time_before_s = u.products * p.product_before_s(u);
            u.mem_mib = a.mem_mib;
            u.basis = "K=" + fmt(K) + " steps, " + fmt(std::round(its * 10) / 10) + " CG its/step";
            u.trimmed = trimmed;
            p.units().push_back(u);
          }
        }
    }
  };
  // A heat row does not record its non-zeros: its work is the steps done × products per
  // step (from its mean CG iterations) × the plan's non-zeros.
  s.recorded = [](const std::string&, const TsvTable& d, const PlannedPairs& planned, RecordedUnits& out) {
    const Rows rows{d, out};
    for (auto& r : d.rows) {
      const std::string var = rows.text(r, "weight") + "/theta=" + rows.text(r, "theta");
      const int k = rows.level(r);
      const double th = rows.v(r, "theta");
      const double per_step = (th < 1 ? 1 : 0) + (th > 0 ? rows.v(r, "cg_mean_iterations") + 1 : 0);
      auto it = planned.find({var, k});
      rows.put(var, k, rows.v(r, "seconds"),
               it == planned.end() ? kNaN : it->second * rows.v(r, "steps_done") * per_step);
    }
  };
  return s;
}

// core_voronoi: the plain grid once per level, the jittered grid per seed.
RegisteredStudy voronoi() {
  RegisteredStudy s{"core_voronoi", {"core_voronoi"}, {}, {}};
  s.plan = [](UnitPricer& p) {
    for (int k : p.paper() ? voronoi_study().levels.paper : voronoi_study().levels.quick) {
      p.add_voronoi("core_voronoi", "grid", k);
      for (int seed : voronoi_study().seeds) p.add_voronoi("core_voronoi", "jittered/seed=" + fmt(seed), k);
    }
  };
  s.recorded = [](const std::string&, const TsvTable& d, const PlannedPairs&, RecordedUnits& out) {
    const Rows rows{d, out};
    for (auto& r : d.rows) {
      const std::string& dist = rows.text(r, "distribution");
      rows.put(dist == "grid" ? std::string("grid") : dist + "/seed=" + rows.text(r, "seed"), rows.level(r),
               rows.v(r, "time_s"), kNaN);
    }
  };
  return s;
}

}  // namespace

const std::vector<RegisteredStudy>& study_registry() {
  static const std::vector<RegisteredStudy> r = [] {
    std::vector<RegisteredStudy> v = {imoto()};
    for (auto& t : thesis_table_specs()) v.push_back(thesis_truncation(t));
    v.push_back(poisson());
    for (auto& hp : heat_tables()) v.push_back(heat(hp));
    v.push_back(voronoi());
    return v;
  }();
  return r;
}

const RegisteredStudy& registered_study_of_file(const std::string& file) {
  for (auto& s : study_registry())
    if (std::find(s.files.begin(), s.files.end(), file) != s.files.end()) return s;
  throw InputError("no registered study writes the data file '" + file + "'");
}

}  // namespace gpm
