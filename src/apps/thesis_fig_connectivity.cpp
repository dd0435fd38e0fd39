// thesis_fig_connectivity: the graph G of Definition 1.8 for the thesis' Figures 1.3–1.4.
//
// Case "connected": a jittered grid with h = 2.4 Δx (no guarantee from Lemma 1.10, which asks
// h > 2 r_c; the search decides, and the data file records the answer).  Case "isolated": the same distribution with every particle
// removed whose distance from a centre inside Ω lies in [ρ, ρ + h): the group within ρ keeps its
// internal edges but no chain of steps shorter than h leaves it, so the h-connectivity fails and
// the breadth-first search from the particles outside Ω (h_connectivity) must not reach it.
#include <cmath>
#include <cstdint>
#include <vector>

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

// The program: options read and checked once; run() builds the two distributions, runs the
// search on each and writes the two files.
class Connectivity {
 public:
  Connectivity(int argc, char** argv)
      : a_("thesis_fig_connectivity",
           "Graph G of the h-connectivity (thesis Def. 1.8, Figs. 1.3-1.4): one distribution that\n"
           "satisfies it and one with an isolated group in Omega; BFS from the particles outside Omega.") {
    a_.output("particles", "", "output TSV of particles (required)")
        .output("edges", "", "output TSV of graph edges (required)")
        .opt("dx", "2^-4", "grid spacing")
        .opt("h-over-dx", "2.4", "influence radius h / dx")
        .opt("centre", "0.3,0.5", "centre of the isolated group (inside Omega)")
        .opt("radius-over-dx", "1.3", "radius rho of the isolated group, in dx")
        .opt("seed", "1", "jitter seed (non-negative integer)");
    a_.parse(argc, argv);
    if (a_.str("particles").empty() || a_.str("edges").empty())
      throw InputError("--particles and --edges are required (see --help)");
    dx_ = a_.positive("dx"), h_ = a_.positive("h-over-dx") * dx_;
    rho_ = a_.positive("radius-over-dx") * dx_;
    c_ = a_.nums("centre");
    if (c_.size() != 2 || !Domain::in_omega(c_[0], c_[1]))
      throw InputError("--centre: need two numbers inside Omega = (0,1)^2, got '" + a_.str("centre") + "'");
    seed_ = a_.seed();
    require_grid_fits_memory(dx_, bytes_per_particle(h_ / dx_), "--dx");
  }

  int run() {
    const Stopwatch wall;
    make_distributions();
    describe();
    for (auto [name, p] : {std::pair<const char*, const Particles*>{"connected", &full_}, {"isolated", &cut_}})
      search(name, *p);
    save(wall.seconds());
    return 0;
  }

 private:
  // The jittered grid, and the same with an isolated group: the annulus ρ ≤ |x − c| < ρ + h
  // dropped.
  void make_distributions() {
    full_ = jittered_grid(dx_, seed_);
    for (std::size_t i = 0; i < full_.size(); ++i) {
      const double d = std::hypot(full_.x[i] - c_[0], full_.y[i] - c_[1]);
      if (d < rho_ || d >= rho_ + h_) cut_.push(full_.x[i], full_.y[i], full_.gi[i], full_.gj[i]);
    }
  }

  // Both files' headers: the options and h.
  void describe() {
    for (TsvTable* t : {&tp_, &te_}) {
      t->set("program", "thesis_fig_connectivity");
      for (auto& [k, v] : a_.values()) t->set(k, v);
      t->set("h", h_);
    }
    tp_.columns = {"case", "x", "y", "in_omega", "hops", "unconnected"};
    te_.columns = {"case", "x1", "y1", "x2", "y2", "unconnected"};
  }

  // The breadth-first search from the particles outside Ω on one distribution: every
  // particle with its hop count, every edge of G, and the verdict in both headers.
  void search(const char* name, const Particles& p) {
    const ConnectivityResult r = h_connectivity(p, h_);
    std::vector<uint8_t> bad(p.size(), 0);
    for (int32_t i : r.unconnected) bad[i] = 1;
    for (std::size_t i = 0; i < p.size(); ++i) {
      TsvRow row = tp_.named_row();
      row["case"] = name, row["x"] = fmt(p.x[i]), row["y"] = fmt(p.y[i]);
      row["in_omega"] = fmt(static_cast<int>(p.in_omega[i])), row["hops"] = fmt(r.hops[i]);
      row["unconnected"] = fmt(static_cast<int>(bad[i]));
      tp_.add_row(row);
    }
    for (auto [i, j] : neighbour_edges(p, h_)) {
      TsvRow row = te_.named_row();
      row["case"] = name, row["x1"] = fmt(p.x[i]), row["y1"] = fmt(p.y[i]);
      row["x2"] = fmt(p.x[j]), row["y2"] = fmt(p.y[j]);
      row["unconnected"] = fmt(static_cast<int>(bad[i]));  // of the edge's first particle
      te_.add_row(row);
    }
    for (TsvTable* t : {&tp_, &te_}) {
      t->set(std::string("N_") + name, fmt(p.size()));
      t->set(std::string("h_connected_") + name, r.connected ? "yes" : "no");
      t->set(std::string("unconnected_") + name, fmt(r.unconnected.size()));
    }
    std::fprintf(stderr, "[thesis_fig_connectivity] %s: N=%zu h-connectivity %s, %zu unconnected\n", name,
                 p.size(), r.connected ? "holds" : "fails", r.unconnected.size());
  }

  void save(double seconds) {
    for (TsvTable* t : {&tp_, &te_}) {
      add_provenance(*t);
      t->set("wall_time_s", seconds);
    }
    te_.save(a_.str("edges"));
    tp_.save(a_.str("particles"));
  }

  Args a_;
  double dx_ = 0, h_ = 0, rho_ = 0;
  std::vector<double> c_;
  uint64_t seed_ = 0;
  Particles full_, cut_;
  TsvTable tp_, te_;
};

int body(int argc, char** argv) { return Connectivity(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("thesis_fig_connectivity", body, argc, argv); }
