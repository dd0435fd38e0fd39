// thesis_fig_connectivity: the graph G of Definition 1.8 for the thesis' Figures 1.3–1.4.
//
// Case "connected": a jittered grid with h = 2.4 Δx (no guarantee from Lemma 1.10, which asks
// h > 2 r_c; the search decides, and the data file records the answer).  Case "isolated": the same distribution with every particle
// removed whose distance from a centre inside Ω lies in [ρ, ρ + h): the group within ρ keeps its
// internal edges but no chain of steps shorter than h leaves it, so the h-connectivity fails and
// the breadth-first search from the particles outside Ω (h_connectivity) must not reach it.
#include <cmath>

#include "gpm/error.hpp"
#include "gpm/geometry/connectivity.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/io/progress.hpp"
#include "gpm/studies/define/profile.hpp"

using namespace gpm;

namespace {

// Memory per particle: the rows of two particle tables and of the edge tables, whose size
// grows as (h/dx)²; peak RSS at dx = 2^-8, h = 2.4 dx was 7.0 kB per particle ≈ 1000 +
// 1000 (h/dx)², taken with half as much again to spare.
double bytes_per_particle(double h_over_dx) { return 1500 + 1500 * h_over_dx * h_over_dx; }

int body(int argc, char** argv) {
  Args a("thesis_fig_connectivity",
         "Graph G of the h-connectivity (thesis Def. 1.8, Figs. 1.3-1.4): one distribution that\n"
         "satisfies it and one with an isolated group in Omega; BFS from the particles outside Omega.");
  a.output("particles", "", "output TSV of particles (required)")
      .output("edges", "", "output TSV of graph edges (required)")
      .opt("dx", "2^-4", "grid spacing")
      .opt("h-over-dx", "2.4", "influence radius h / dx")
      .opt("centre", "0.3,0.5", "centre of the isolated group (inside Omega)")
      .opt("radius-over-dx", "1.3", "radius rho of the isolated group, in dx")
      .opt("seed", "1", "jitter seed (non-negative integer)");
  a.parse(argc, argv);
  if (a.str("particles").empty() || a.str("edges").empty())
    throw InputError("--particles and --edges are required (see --help)");
  const double dx = a.positive("dx"), h = a.positive("h-over-dx") * dx;
  const double rho = a.positive("radius-over-dx") * dx;
  const auto c = a.nums("centre");
  if (c.size() != 2 || !Domain::in_omega(c[0], c[1]))
    throw InputError("--centre: need two numbers inside Omega = (0,1)^2, got '" + a.str("centre") + "'");
  const uint64_t seed = a.seed();
  require_grid_fits_memory(dx, bytes_per_particle(h / dx), "--dx");
  const Stopwatch wall;
  const Particles full = jittered_grid(dx, seed);

  // The distribution with an isolated group: drop the annulus ρ ≤ |x − c| < ρ + h.
  Particles cut;
  for (std::size_t i = 0; i < full.size(); ++i) {
    const double d = std::hypot(full.x[i] - c[0], full.y[i] - c[1]);
    if (d < rho || d >= rho + h) cut.push(full.x[i], full.y[i], full.gi[i], full.gj[i]);
  }

  TsvTable tp, te;
  for (TsvTable* t : {&tp, &te}) {
    t->set("program", "thesis_fig_connectivity");
    for (auto& [k, v] : a.values()) t->set(k, v);
    t->set("h", h);
  }
  tp.columns = {"case", "x", "y", "in_omega", "hops", "unconnected"};
  te.columns = {"case", "x1", "y1", "x2", "y2", "unconnected"};
  for (auto [name, p] : {std::pair<const char*, const Particles*>{"connected", &full},
                         {"isolated", &cut}}) {
    const ConnectivityResult r = h_connectivity(*p, h);
    std::vector<uint8_t> bad(p->size(), 0);
    for (int32_t i : r.unconnected) bad[i] = 1;
    for (std::size_t i = 0; i < p->size(); ++i) {
      TsvRow row = tp.named_row();
      row["case"] = name, row["x"] = fmt(p->x[i]), row["y"] = fmt(p->y[i]);
      row["in_omega"] = fmt(static_cast<int>(p->in_omega[i])), row["hops"] = fmt(r.hops[i]);
      row["unconnected"] = fmt(static_cast<int>(bad[i]));
      tp.add_row(row);
    }
    for (auto [i, j] : neighbour_edges(*p, h)) {
      TsvRow row = te.named_row();
      row["case"] = name, row["x1"] = fmt(p->x[i]), row["y1"] = fmt(p->y[i]);
      row["x2"] = fmt(p->x[j]), row["y2"] = fmt(p->y[j]);
      row["unconnected"] = fmt(static_cast<int>(bad[i]));  // of the edge's first particle
      te.add_row(row);
    }
    for (TsvTable* t : {&tp, &te}) {
      t->set(std::string("N_") + name, fmt(p->size()));
      t->set(std::string("h_connected_") + name, r.connected ? "yes" : "no");
      t->set(std::string("unconnected_") + name, fmt(r.unconnected.size()));
    }
    std::fprintf(stderr, "[thesis_fig_connectivity] %s: N=%zu h-connectivity %s, %zu unconnected\n",
                 name, p->size(), r.connected ? "holds" : "fails", r.unconnected.size());
  }
  for (TsvTable* t : {&tp, &te}) {
    add_provenance(*t);
    t->set("wall_time_s", wall.seconds());
  }
  te.save(a.str("edges"));
  tp.save(a.str("particles"));
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return run_main("thesis_fig_connectivity", body, argc, argv); }
