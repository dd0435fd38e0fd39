// imoto_figs1_4: the pictures of imoto §2–§5 as data.
//   Figures 1 and 4: the jittered particle distribution of §5 at Δx = 2^-5 (N = 1,521);
//   Figure 2:        its Voronoi decomposition of Ω_H (one row per cell edge);
//   Figure 3:        the covering radius of a uniform and a non-uniform distribution with the
//                    same N: the covering disc of the worst cell of each (centre = the Voronoi
//                    vertex farthest from its particle, radius = r_N).
// The non-uniform distribution of Figure 3 is the plain grid pushed through the monotone map
// t ↦ t^kGrade on each axis of Ω_H (dense at the lower left, sparse at the upper right): the
// same nodes, hence the same N, with both dense and sparse regions as in Remark 1.
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/voronoi.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/io/progress.hpp"

using namespace gpm;

namespace {

const int kLevel = 5;          // Δx = 2^-5, the distribution the document draws
const int kFig3Level = 3;      // Δx = 2^-3 for Figure 3 (81 particles: cells stay readable)
const double kGrade = 1.8;     // exponent of the grading map of the non-uniform distribution

// Every edge of every cell, as (distribution, cell, x1, y1, x2, y2) rows (drawn with
// gnuplot's vectors).  By name: the tables' columns are set by the caller.
void add_edges(TsvTable& t, const std::string& tag, const VoronoiCells& c) {
  for (std::size_t i = 0; i + 1 < c.offset.size(); ++i) {
    const uint64_t b = c.offset[i], e = c.offset[i + 1];
    for (uint64_t k = b; k < e; ++k) {
      const uint64_t l = k + 1 < e ? k + 1 : b;
      TsvRow row = t.named_row();
      row["distribution"] = tag, row["cell"] = fmt(i);
      row["x1"] = fmt(c.px[k]), row["y1"] = fmt(c.py[k]), row["x2"] = fmt(c.px[l]), row["y2"] = fmt(c.py[l]);
      t.add_row(row);
    }
  }
}

// The program: the options read and every output path checked before anything is computed;
// run() writes Figures 1/4 and 2, then Figure 3.
class Figures {
 public:
  Figures(int argc, char** argv)
      : args_("imoto_figs1_4",
              "imoto Figures 1-4 as data: the jittered distribution at dx = 2^-5, its Voronoi\n"
              "cells, and the covering discs of a uniform and a graded distribution (same N).") {
    args_.opt("prefix", "", "output path prefix (required): writes <prefix>_particles.tsv,\n"
                            "  <prefix>_voronoi.tsv, <prefix>_fig3_particles.tsv,\n"
                            "  <prefix>_fig3_edges.tsv, <prefix>_fig3_discs.tsv")
        .opt("seed", "1", "jitter seed (non-negative integer)");
    args_.parse(argc, argv);
    prefix_ = args_.required("prefix");
    seed_ = args_.seed();
    std::vector<std::pair<std::string, std::string>> outputs;
    for (const char* f : {"_particles.tsv", "_voronoi.tsv", "_fig3_particles.tsv",
                          "_fig3_edges.tsv", "_fig3_discs.tsv"})
      outputs.emplace_back("--prefix", prefix_ + f);
    check_output_paths(outputs);
  }

  int run() {
    section5_distribution();
    figure3_covering_discs();
    return 0;
  }

 private:
  void header(TsvTable& t, const char* what) const {
    t.set("program", std::string("imoto_figs1_4 ") + what);
    for (auto& [k, v] : args_.values()) t.set(k, v);
    t.set("H", dom_.H);
    add_provenance(t);
  }
  void finish(TsvTable& t, const std::string& suffix) const {
    t.set("wall_time_s", wall_.seconds());
    t.save(prefix_ + suffix);
  }

  // Figures 1/4 and 2: the §5 distribution and its Voronoi cells.
  void section5_distribution() const {
    const double dx = std::ldexp(1.0, -kLevel);
    const Particles p = jittered_grid(dx, seed_, 0.25, dom_);
    const VoronoiCells c = voronoi_cells(p, dom_, true);
    TsvTable parts;
    header(parts, "particles");
    parts.set("dx", dx);
    parts.set("N", fmt(p.size()));
    parts.set("N_in_omega", fmt(p.count_in_omega()));
    parts.columns = {"x", "y", "in_omega"};
    for (std::size_t i = 0; i < p.size(); ++i) {
      TsvRow row = parts.named_row();
      row["x"] = fmt(p.x[i]), row["y"] = fmt(p.y[i]), row["in_omega"] = p.in_omega[i] ? "1" : "0";
      parts.add_row(row);
    }
    finish(parts, "_particles.tsv");
    TsvTable vor;
    header(vor, "voronoi");
    vor.set("dx", dx);
    vor.set("N", fmt(p.size()));
    vor.set("area_sum", c.area_sum);
    vor.columns = {"distribution", "cell", "x1", "y1", "x2", "y2"};
    add_edges(vor, "jittered", c);
    finish(vor, "_voronoi.tsv");
  }

  // Figure 3: uniform (plain grid) against graded, same nodes; per distribution its particles,
  // its cells and the covering disc of its worst cell.
  void figure3_covering_discs() const {
    const double dx3 = std::ldexp(1.0, -kFig3Level);
    const Particles uni = jittered_grid(dx3, 0, 0.0, dom_);
    Particles gra;
    for (std::size_t i = 0; i < uni.size(); ++i) {
      auto grade = [&](double s) {
        return dom_.lo() + dom_.side() * std::pow((s - dom_.lo()) / dom_.side(), kGrade);
      };
      gra.push(grade(uni.x[i]), grade(uni.y[i]), uni.gi[i], uni.gj[i]);
    }
    TsvTable f3p, f3e, f3d;
    header(f3p, "fig3 particles");
    header(f3e, "fig3 edges");
    header(f3d, "fig3 discs");
    for (TsvTable* t : {&f3p, &f3e, &f3d}) {
      t->set("dx", dx3);
      t->set("grading", "non-uniform: x -> lo + side*((x-lo)/side)^" + fmt(kGrade) + " per axis");
    }
    f3p.columns = {"distribution", "x", "y"};
    f3e.columns = {"distribution", "cell", "x1", "y1", "x2", "y2"};
    f3d.columns = {"distribution", "N", "worst_x", "worst_y", "centre_x", "centre_y", "r_N"};
    for (auto [tag, q] : {std::pair<const char*, const Particles*>{"uniform", &uni}, {"non-uniform", &gra}}) {
      const VoronoiCells v = voronoi_cells(*q, dom_, true);
      for (std::size_t i = 0; i < q->size(); ++i) {
        TsvRow row = f3p.named_row();
        row["distribution"] = tag, row["x"] = fmt(q->x[i]), row["y"] = fmt(q->y[i]);
        f3p.add_row(row);
      }
      add_edges(f3e, tag, v);
      // The covering disc: centred at the worst cell's vertex farthest from its particle.
      const std::size_t w = v.worst;
      double cx = 0, cy = 0, best = -1;
      for (uint64_t k = v.offset[w]; k < v.offset[w + 1]; ++k) {
        const double d = std::hypot(v.px[k] - q->x[w], v.py[k] - q->y[w]);
        if (d > best) best = d, cx = v.px[k], cy = v.py[k];
      }
      TsvRow disc = f3d.named_row();
      disc["distribution"] = tag, disc["N"] = fmt(q->size());
      disc["worst_x"] = fmt(q->x[w]), disc["worst_y"] = fmt(q->y[w]);
      disc["centre_x"] = fmt(cx), disc["centre_y"] = fmt(cy), disc["r_N"] = fmt(v.covering_radius);
      f3d.add_row(disc);
      std::printf("Figure 3 %-12s N = %zu  r_N = %.6f\n", tag, q->size(), v.covering_radius);
    }
    finish(f3p, "_fig3_particles.tsv");
    finish(f3e, "_fig3_edges.tsv");
    finish(f3d, "_fig3_discs.tsv");
  }

  Args args_;
  std::string prefix_;
  uint64_t seed_ = 1;
  const Domain dom_;
  const Stopwatch wall_;
};

int body(int argc, char** argv) { return Figures(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("imoto_figs1_4", body, argc, argv); }
