// thesis_fig_distribution: a particle distribution X_{N,H} (jittered grid on Ω_H) and its
// Voronoi decomposition, for the thesis' Figures 1.1–1.2 (a coarse example) and 4.1 (Δx = 2^-5,
// N = 1,521).  Writes the particles (x, y, in Ω) and, optionally, the Voronoi cell edges as
// segments (one row per edge of each clipped cell).

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/voronoi.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/io/progress.hpp"
#include "gpm/studies/define/profile.hpp"

using namespace gpm;

namespace {

// Memory per particle (the table rows dominate): peak RSS / N was 222 bytes at dx = 2^-10,
// 2,070 with the cell edges at 2^-9; half as much again to spare.
constexpr double kParticleBytes = 350, kCellBytes = 3000;

// The program: the options read once; run() makes the particles, writes the Voronoi cells'
// edges if asked, then the particles.
class FigDistribution {
 public:
  FigDistribution(int argc, char** argv)
      : a_("thesis_fig_distribution",
           "Jittered particle distribution on Omega_H and (optionally) its Voronoi cells.") {
    a_.output("particles", "", "output TSV of particles (required)")
        .output("cells", "", "optional output TSV of Voronoi cell edges")
        .opt("dx", "2^-5", "grid spacing")
        .opt("seed", "1", "jitter seed (non-negative integer)");
    a_.parse(argc, argv);
    a_.required("particles");
    dx_ = a_.positive("dx");
    seed_ = a_.seed();
    require_grid_fits_memory(dx_, a_.str("cells").empty() ? kParticleBytes : kCellBytes, "--dx");
  }

  int run() {
    p_ = jittered_grid(dx_, seed_, 0.25, dom_);
    if (!a_.str("cells").empty()) write_cells();
    write_particles();
    return 0;
  }

 private:
  void header(TsvTable& t) const {
    t.set("program", "thesis_fig_distribution");
    for (auto& [k, v] : a_.values()) t.set(k, v);
    t.set("N", fmt(p_.size()));
    t.set("N_omega", fmt(p_.count_in_omega()));
    t.set("H", dom_.H);
    add_provenance(t);
  }

  // Every cell's edges, one row each (the cell's polygon closed).
  void write_cells() {
    const VoronoiCells c = voronoi_cells(p_, dom_, true);
    TsvTable t;
    header(t);
    t.set("area_sum", c.area_sum);
    t.set("covering_radius", c.covering_radius);
    t.columns = {"cell", "x1", "y1", "x2", "y2"};
    for (std::size_t i = 0; i < p_.size(); ++i) {
      const auto b = c.offset[i], e = c.offset[i + 1];
      for (auto k = b; k < e; ++k) {
        const auto k2 = k + 1 < e ? k + 1 : b;
        TsvRow row = t.named_row();
        row["cell"] = fmt(i), row["x1"] = fmt(c.px[k]), row["y1"] = fmt(c.py[k]);
        row["x2"] = fmt(c.px[k2]), row["y2"] = fmt(c.py[k2]);
        t.add_row(row);
      }
    }
    t.set("wall_time_s", wall_.seconds());
    t.save(a_.str("cells"));
  }

  void write_particles() {
    TsvTable t;
    header(t);
    t.columns = {"x", "y", "in_omega"};
    for (std::size_t i = 0; i < p_.size(); ++i) {
      TsvRow row = t.named_row();
      row["x"] = fmt(p_.x[i]), row["y"] = fmt(p_.y[i]), row["in_omega"] = fmt(static_cast<int>(p_.in_omega[i]));
      t.add_row(row);
    }
    t.set("wall_time_s", wall_.seconds());
    t.save(a_.str("particles"));
  }

  Args a_;
  double dx_ = 0;
  uint64_t seed_ = 1;
  const Stopwatch wall_;
  const Domain dom_;
  Particles p_;
};

int body(int argc, char** argv) { return FigDistribution(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("thesis_fig_distribution", body, argc, argv); }
