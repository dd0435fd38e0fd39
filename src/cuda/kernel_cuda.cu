// The CUDA kernels and their host side (see kernel_cuda.hpp; the per-target arithmetic is
// kernel_cuda_body.hpp).
#include "cuda/kernel_cuda.hpp"

#include <cuda_runtime.h>

#include <algorithm>
#include <numeric>
#include <sstream>
#include <utility>

#include "cuda/kernel_cuda_body.hpp"
#include "gpm/error.hpp"
#include "gpm/geometry/cells.hpp"

namespace gpm::cuda {

namespace {

// ---------------------------------------------------------------------------------
// Errors: every CUDA call goes through check(), which names the call and the error.

void check(cudaError_t e, const char* call, const char* file, int line) {
  if (e == cudaSuccess) return;
  (void)cudaGetLastError();  // clear a non-sticky error
  std::ostringstream s;
  s << "CUDA: " << call << " failed: " << cudaGetErrorName(e) << " (" << cudaGetErrorString(e)
    << ") at " << file << ":" << line;
  throw NumericalError(s.str());
}
#define GPM_CUDA_CHECK(call) check((call), #call, __FILE__, __LINE__)

// A device array, freed with its owner.  A failed allocation names what it was for, the
// bytes asked for and the device's free memory.
template <class T>
class DeviceArray {
 public:
  DeviceArray() = default;
  DeviceArray(std::size_t n, const char* what) { allocate(n, what); }
  ~DeviceArray() { release(); }
  DeviceArray(const DeviceArray&) = delete;
  DeviceArray& operator=(const DeviceArray&) = delete;

  void allocate(std::size_t n, const char* what) {
    release();
    if (n == 0) return;
    const cudaError_t e = cudaMalloc(reinterpret_cast<void**>(&p_), n * sizeof(T));
    if (e != cudaSuccess) {
      p_ = nullptr;
      (void)cudaGetLastError();
      std::size_t free_b = 0, total_b = 0;
      (void)cudaMemGetInfo(&free_b, &total_b);
      (void)cudaGetLastError();
      std::ostringstream s;
      s << "CUDA: cannot allocate " << static_cast<double>(n * sizeof(T)) / (1 << 20)
        << " MiB on the device for " << what << ": " << cudaGetErrorString(e) << " ("
        << static_cast<double>(free_b) / (1 << 20) << " MiB free of "
        << static_cast<double>(total_b) / (1 << 20) << ")";
      throw NumericalError(s.str());
    }
    n_ = n;
  }
  void upload(const T* src, std::size_t n) {
    if (n > 0)
      GPM_CUDA_CHECK(cudaMemcpy(p_, src, n * sizeof(T), cudaMemcpyHostToDevice));
  }
  void download(T* dst, std::size_t n, std::size_t offset = 0) const {
    if (n > 0)
      GPM_CUDA_CHECK(cudaMemcpy(dst, p_ + offset, n * sizeof(T), cudaMemcpyDeviceToHost));
  }
  T* get() const { return p_; }
  std::size_t size() const { return n_; }

 private:
  void release() {
    if (p_) (void)cudaFree(p_);
    p_ = nullptr;
    n_ = 0;
  }
  T* p_ = nullptr;
  std::size_t n_ = 0;
};

// A pair of events around one kernel; elapsed() waits for the second.
class EventPair {
 public:
  EventPair() {
    GPM_CUDA_CHECK(cudaEventCreate(&a_));
    const cudaError_t e = cudaEventCreate(&b_);
    if (e != cudaSuccess) (void)cudaEventDestroy(a_);
    GPM_CUDA_CHECK(e);
  }
  ~EventPair() {
    (void)cudaEventDestroy(a_);
    (void)cudaEventDestroy(b_);
  }
  EventPair(const EventPair&) = delete;
  EventPair& operator=(const EventPair&) = delete;
  void start() { GPM_CUDA_CHECK(cudaEventRecord(a_)); }
  void stop() { GPM_CUDA_CHECK(cudaEventRecord(b_)); }
  float elapsed_ms() const {
    GPM_CUDA_CHECK(cudaEventSynchronize(b_));  // a failed kernel reports here
    float ms = 0;
    GPM_CUDA_CHECK(cudaEventElapsedTime(&ms, a_, b_));
    return ms;
  }

 private:
  cudaEvent_t a_{}, b_{};
};

void require_device() {
  const DeviceInfo d = device_info();
  if (d.count == 0)
    throw InputError("no CUDA device: " + d.error +
                     " (the CUDA path needs an NVIDIA GPU; gpm::FusedKernel is the CPU kernel)");
  GPM_CUDA_CHECK(cudaSetDevice(0));
}

// ---------------------------------------------------------------------------------
// Kernels.

constexpr int kThreads = 128;

// One thread per target (targets in cell order): the four sums into out[c·nt + pos].
// The piece tables are indexed by the piece a pair falls in (a run-time index):
// __grid_constant__ lets the threads read them in place from the parameter space (the
// constant cache) instead of each copying ~1 KB to local memory first.
static_assert(sizeof(GridView) + 2 * sizeof(PieceTable) + 64 < 4096,
              "kernel parameters must stay below the 4 KB every CUDA version accepts");
template <unsigned OPS>
__global__ void truncation_kernel(const __grid_constant__ GridView g,
                                  const __grid_constant__ PieceTable w,
                                  const __grid_constant__ PieceTable gq, int gmode,
                                  const double* __restrict__ v, const int32_t* __restrict__ tslot,
                                  const int32_t* __restrict__ tpos, int32_t nt,
                                  double* __restrict__ out) {
  const int32_t it = static_cast<int32_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (it >= nt) return;
  double o[4];
  target_sums<OPS>(g, w, gq, gmode, v, tslot[it], o);
  const std::size_t pos = static_cast<std::size_t>(tpos[it]), n = static_cast<std::size_t>(nt);
  if constexpr ((OPS & kOpInterp) != 0) out[pos] = o[0];
  if constexpr ((OPS & kOpGrad) != 0) {
    out[n + pos] = o[1];
    out[2 * n + pos] = o[2];
  }
  if constexpr ((OPS & kOpLap) != 0) out[3 * n + pos] = o[3];
}

// A study's fused pass: one thread per target, every weight and field (fused_target_sums);
// the weights' tables in device memory (9 weights' tables exceed the 4 KB of parameters),
// the fields as sorted_fields lays them out (field f at fields + f·stride).
__global__ void fused_pass_kernel(const __grid_constant__ GridView g,
                                  const WeightEntry* __restrict__ we, int nw,
                                  const double* __restrict__ fields, int nf, int64_t stride,
                                  const int32_t* __restrict__ tslot,
                                  const int32_t* __restrict__ tpos, int32_t nt,
                                  double* __restrict__ out) {
  const int32_t it = static_cast<int32_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (it >= nt) return;
  const double* v[kMaxFieldsDevice];
  field_pointers(fields, stride, nf, v);
  double o[kMaxWeights * kMaxFieldsDevice * 4];
  fused_target_sums(g, we, nw, v, nf, tslot[it], o);
  const std::size_t pos = static_cast<std::size_t>(tpos[it]), m = static_cast<std::size_t>(nt);
  for (int c = 0; c < nw * nf * 4; ++c) out[static_cast<std::size_t>(c) * m + pos] = o[c];
}

// Eight independent FMA chains per thread, `iters` rounds: the fp64 peak.
__global__ void dfma_kernel(double* out, int iters) {
  const double b = 0.9999999, c = 1e-9;
  double a[8];
  for (int j = 0; j < 8; ++j) a[j] = 1e-6 * (threadIdx.x + j);
  for (int i = 0; i < iters; ++i)
#pragma unroll
    for (int j = 0; j < 8; ++j) a[j] = fma(a[j], b, c);
  double s = 0;
  for (int j = 0; j < 8; ++j) s += a[j];
  out[static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x] = s;  // keeps the work
}

// field[slot[u]] = x[u]: the unknowns into the (otherwise zero) sorted field.
__global__ void scatter_kernel(const double* __restrict__ x, const int32_t* __restrict__ slot,
                               int32_t nu, double* __restrict__ field) {
  const int32_t u = static_cast<int32_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (u < nu) field[slot[u]] = x[u];
}

void launch(unsigned ops, unsigned blocks, const GridView& g, const PieceTable& w,
            const PieceTable& gq, int gmode, const double* v, const int32_t* tslot,
            const int32_t* tpos, int32_t nt, double* out) {
  switch (ops & kOpAll) {
    case 1: truncation_kernel<1><<<blocks, kThreads>>>(g, w, gq, gmode, v, tslot, tpos, nt, out); break;
    case 2: truncation_kernel<2><<<blocks, kThreads>>>(g, w, gq, gmode, v, tslot, tpos, nt, out); break;
    case 3: truncation_kernel<3><<<blocks, kThreads>>>(g, w, gq, gmode, v, tslot, tpos, nt, out); break;
    case 4: truncation_kernel<4><<<blocks, kThreads>>>(g, w, gq, gmode, v, tslot, tpos, nt, out); break;
    case 5: truncation_kernel<5><<<blocks, kThreads>>>(g, w, gq, gmode, v, tslot, tpos, nt, out); break;
    case 6: truncation_kernel<6><<<blocks, kThreads>>>(g, w, gq, gmode, v, tslot, tpos, nt, out); break;
    default: truncation_kernel<7><<<blocks, kThreads>>>(g, w, gq, gmode, v, tslot, tpos, nt, out); break;
  }
  GPM_CUDA_CHECK(cudaGetLastError());  // launch configuration errors
}

unsigned blocks_for(std::size_t n) {
  return static_cast<unsigned>((n + kThreads - 1) / kThreads);
}

}  // namespace

// ---------------------------------------------------------------------------------

DeviceInfo device_info() {
  DeviceInfo d;
  int n = 0;
  const cudaError_t e = cudaGetDeviceCount(&n);
  (void)cudaRuntimeGetVersion(&d.runtime_version);
  (void)cudaDriverGetVersion(&d.driver_version);
  if (e != cudaSuccess || n <= 0) {
    d.error = e != cudaSuccess ? std::string(cudaGetErrorName(e)) + ": " + cudaGetErrorString(e)
                               : std::string("cudaGetDeviceCount reports 0 devices");
    if (d.driver_version == 0) d.error += "; no NVIDIA driver is loaded on this machine";
    (void)cudaGetLastError();
    return d;
  }
  d.count = n;
  cudaDeviceProp prop{};
  if (cudaGetDeviceProperties(&prop, 0) == cudaSuccess) {
    d.name = prop.name;
    d.cc_major = prop.major;
    d.cc_minor = prop.minor;
    d.memory_gib = static_cast<double>(prop.totalGlobalMem) / (1024.0 * 1024.0 * 1024.0);
  }
  (void)cudaGetLastError();
  return d;
}

double fp64_peak_flops() {
  require_device();
  cudaDeviceProp prop{};
  GPM_CUDA_CHECK(cudaGetDeviceProperties(&prop, 0));
  const unsigned blocks = static_cast<unsigned>(prop.multiProcessorCount) * 8, threads = 256;
  const int iters = 1 << 14;
  DeviceArray<double> out(static_cast<std::size_t>(blocks) * threads, "the DFMA results");
  EventPair ev;
  dfma_kernel<<<blocks, threads>>>(out.get(), 64);  // warm-up
  GPM_CUDA_CHECK(cudaGetLastError());
  double best = 0;
  for (int r = 0; r < 3; ++r) {
    ev.start();
    dfma_kernel<<<blocks, threads>>>(out.get(), iters);
    GPM_CUDA_CHECK(cudaGetLastError());
    ev.stop();
    const double s = 1e-3 * ev.elapsed_ms();
    best = std::max(best, 2.0 * 8 * iters * static_cast<double>(blocks) * threads / s);
  }
  return best;
}

struct CudaKernel::Impl {
  double h = 0;
  unsigned ops = 0;
  int cells_per_h = 1;
  CellList cl;  // host copy: slots of the targets, gather of the fields
  PieceTable w, gq;
  int gmode = kGOwnTable;
  GridView dev;  // device pointers
  DeviceArray<double> xs, ys, Vs;
  DeviceArray<int32_t> start;
  // Per-apply buffers, grown as needed.
  mutable DeviceArray<double> field, out;
  mutable DeviceArray<int32_t> tslot, tpos;
  std::unique_ptr<EventPair> ev;  // created once a device is known to exist

  // Targets (original indices) → their slots in cell order and output positions.
  void order_targets(const std::vector<int32_t>& targets, std::vector<int32_t>& slot,
                     std::vector<int32_t>& pos) const {
    const std::size_t n = cl.size();
    std::vector<int32_t> s(targets.size());
    for (std::size_t i = 0; i < targets.size(); ++i) {
      const int32_t t = targets[i];
      if (t < 0 || static_cast<std::size_t>(t) >= n) {
        std::ostringstream m;
        m << "CUDA kernel: target index " << t << " is not a particle (N = " << n << ")";
        throw InputError(m.str());
      }
      s[i] = cl.slot()[t];
    }
    pos.resize(targets.size());
    std::iota(pos.begin(), pos.end(), 0);
    std::stable_sort(pos.begin(), pos.end(), [&](int32_t a, int32_t b) { return s[a] < s[b]; });
    slot.resize(targets.size());
    for (std::size_t i = 0; i < pos.size(); ++i) slot[i] = s[pos[i]];
  }

  // Uploads the target lists and makes room for nt results.
  void prepare(const std::vector<int32_t>& slot, const std::vector<int32_t>& pos) const {
    const std::size_t nt = slot.size();
    if (tslot.size() < nt) tslot.allocate(nt, "the target slots");
    if (tpos.size() < nt) tpos.allocate(nt, "the target positions");
    if (out.size() < 4 * nt) out.allocate(4 * nt, "the results");
    tslot.upload(slot.data(), nt);
    tpos.upload(pos.data(), nt);
  }

  // The kernel over nt prepared targets with the sorted field `v` (device); its time.
  double run(const double* v, std::size_t nt, unsigned run_ops) const {
    if (nt > static_cast<std::size_t>(INT32_MAX))
      throw InputError("CUDA kernel: more than 2^31 - 1 targets");
    ev->start();
    launch(run_ops, blocks_for(nt), dev, w, gq, gmode, v, tslot.get(), tpos.get(),
           static_cast<int32_t>(nt), out.get());
    ev->stop();
    return ev->elapsed_ms();
  }
};

CudaKernel::CudaKernel(const Particles& p, const std::vector<double>& V,
                       const WeightFunction& w, double h, unsigned ops, int cells_per_h)
    : impl_(std::make_unique<Impl>()) {
  require_positive(h, "influence radius h");
  if (V.size() != p.size()) throw InputError("CUDA kernel: V and the particles differ in length");
  if (cells_per_h < 1) throw InputError("CUDA kernel: cells_per_h must be >= 1");
  if (p.size() > static_cast<std::size_t>(INT32_MAX))
    throw InputError("CUDA kernel: more than 2^31 - 1 particles");
  ops &= kOpAll;
  if (ops == 0) throw InputError("CUDA kernel: no operator requested");
  Impl& I = *impl_;
  I.h = h;
  I.ops = ops;
  I.cells_per_h = cells_per_h;
  I.w = piece_table(w, 0);
  I.gq = piece_table(w, 2);
  if ((ops & kOpInterp) && I.w.negative_power)
    throw InputError("weight '" + w.name + "' is unbounded at r = 0: no interpolant with it");
  I.gmode = g_mode(I.gq, ops);
  require_device();  // after the input checks: bad input is reported as such everywhere
  I.ev = std::make_unique<EventPair>();

  I.cl = CellList(p.x, p.y, h / cells_per_h);
  const std::vector<double> Vs = I.cl.gather(V, 0.0);
  const std::size_t n = I.cl.size();
  I.xs.allocate(n, "the particle x coordinates");
  I.ys.allocate(n, "the particle y coordinates");
  I.Vs.allocate(n, "the volumes");
  I.start.allocate(I.cl.start().size(), "the cell offsets");
  I.xs.upload(I.cl.xs(), n);
  I.ys.upload(I.cl.ys(), n);
  I.Vs.upload(Vs.data(), n);
  I.start.upload(I.cl.start().data(), I.cl.start().size());
  I.dev = grid_view(I.cl, nullptr, h);
  I.dev.xs = I.xs.get();
  I.dev.ys = I.ys.get();
  I.dev.Vs = I.Vs.get();
  I.dev.start = I.start.get();
  I.field.allocate(n, "the field");
}

CudaKernel::~CudaKernel() = default;
CudaKernel::CudaKernel(CudaKernel&&) noexcept = default;
CudaKernel& CudaKernel::operator=(CudaKernel&&) noexcept = default;

std::size_t CudaKernel::n_particles() const { return impl_->cl.size(); }
double CudaKernel::h() const { return impl_->h; }
unsigned CudaKernel::ops() const { return impl_->ops; }
int CudaKernel::cells_per_h() const { return impl_->cells_per_h; }

CudaResult CudaKernel::apply(const std::vector<int32_t>& targets,
                             const std::vector<double>& v) const {
  const Impl& I = *impl_;
  if (v.size() != I.cl.size())
    throw InputError("CUDA kernel: the field's size differs from the number of particles");
  CudaResult r;
  const std::size_t nt = targets.size();
  std::vector<int32_t> slot, pos;
  I.order_targets(targets, slot, pos);
  if (nt == 0) return r;
  I.prepare(slot, pos);
  const std::vector<double> vs = I.cl.gather(v, 0.0);
  I.field.upload(vs.data(), I.cl.size());
  r.kernel_ms = I.run(I.field.get(), nt, I.ops);
  if (I.ops & kOpInterp) r.interp.resize(nt), I.out.download(r.interp.data(), nt, 0);
  if (I.ops & kOpGrad) {
    r.grad_x.resize(nt), I.out.download(r.grad_x.data(), nt, nt);
    r.grad_y.resize(nt), I.out.download(r.grad_y.data(), nt, 2 * nt);
  }
  if (I.ops & kOpLap) r.lap.resize(nt), I.out.download(r.lap.data(), nt, 3 * nt);
  return r;
}

// ---------------------------------------------------------------------------------

struct CudaLaplacian::Impl {
  CudaKernel k;
  std::vector<int32_t> omega;
  DeviceArray<int32_t> omega_slot;  // unknown → sorted slot
  mutable DeviceArray<double> x;
  mutable double last_ms = 0;
  Impl(const Particles& p, const std::vector<double>& V, const WeightFunction& w, double h,
       int cells_per_h)
      : k(p, V, w, h, kOpLap, cells_per_h) {}
};

CudaLaplacian::CudaLaplacian(const Particles& p, const std::vector<double>& V,
                             const WeightFunction& w, double h, int cells_per_h)
    : impl_(std::make_unique<Impl>(p, V, w, h, cells_per_h)) {
  Impl& L = *impl_;
  const CudaKernel::Impl& K = *L.k.impl_;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.in_omega[i]) L.omega.push_back(static_cast<int32_t>(i));
  if (L.omega.empty()) throw InputError("CUDA Laplacian: no particle in Omega");
  const std::size_t nu = L.omega.size();
  // Targets = the unknowns, in cell order; the field outside Ω stays 0 on the device.
  std::vector<int32_t> slot, pos;
  K.order_targets(L.omega, slot, pos);
  K.prepare(slot, pos);
  std::vector<int32_t> uslot(nu);
  for (std::size_t u = 0; u < nu; ++u) uslot[u] = K.cl.slot()[L.omega[u]];
  L.omega_slot.allocate(nu, "the unknowns' slots");
  L.omega_slot.upload(uslot.data(), nu);
  L.x.allocate(nu, "the unknowns");
  GPM_CUDA_CHECK(cudaMemset(K.field.get(), 0, K.field.size() * sizeof(double)));
}

CudaLaplacian::~CudaLaplacian() = default;
CudaLaplacian::CudaLaplacian(CudaLaplacian&&) noexcept = default;
CudaLaplacian& CudaLaplacian::operator=(CudaLaplacian&&) noexcept = default;

std::size_t CudaLaplacian::n_unknowns() const { return impl_->omega.size(); }
const std::vector<int32_t>& CudaLaplacian::omega() const { return impl_->omega; }
double CudaLaplacian::last_kernel_ms() const { return impl_->last_ms; }

void CudaLaplacian::apply(const std::vector<double>& x, std::vector<double>& y) const {
  const Impl& L = *impl_;
  const CudaKernel::Impl& K = *L.k.impl_;
  const std::size_t nu = L.omega.size();
  if (x.size() != nu) {
    std::ostringstream m;
    m << "CUDA Laplacian: vector of size " << x.size() << ", expected " << nu << " unknowns";
    throw InputError(m.str());
  }
  L.x.upload(x.data(), nu);
  scatter_kernel<<<blocks_for(nu), kThreads>>>(L.x.get(), L.omega_slot.get(),
                                               static_cast<int32_t>(nu), K.field.get());
  GPM_CUDA_CHECK(cudaGetLastError());
  L.last_ms = K.run(K.field.get(), nu, kOpLap);
  y.resize(nu);
  K.out.download(y.data(), nu, 3 * nu);
}

// ---------------------------------------------------------------------------------

struct CudaFusedPass::Impl {
  CudaKernel k;  // the particles, cells and target ordering (its own weight unused)
  std::vector<WeightEntry> entries;
  DeviceArray<WeightEntry> we;
  mutable DeviceArray<double> fields, out;
  Impl(const Particles& p, const std::vector<double>& V, const WeightFunction& w0, double h,
       int cells_per_h)
      : k(p, V, w0, h, kOpLap, cells_per_h) {}
};

CudaFusedPass::CudaFusedPass(const Particles& p, const std::vector<double>& V, double h,
                             const std::vector<std::pair<WeightFunction, unsigned>>& weights,
                             int cells_per_h) {
  if (weights.empty() || weights.size() > static_cast<std::size_t>(kMaxWeights))
    throw InputError("CUDA fused pass: between 1 and " + std::to_string(kMaxWeights) +
                     " weights, got " + std::to_string(weights.size()));
  std::vector<WeightEntry> entries;
  for (auto& [w, ops] : weights) {
    if ((ops & kOpAll) == 0) throw InputError("CUDA fused pass: no operator for weight '" + w.name + "'");
    const WeightEntry e = weight_entry(w, ops);
    if ((e.ops & kOpInterp) && e.w.negative_power)
      throw InputError("weight '" + w.name + "' is unbounded at r = 0: no interpolant with it");
    entries.push_back(e);
  }
  impl_ = std::make_unique<Impl>(p, V, weights.front().first, h, cells_per_h);
  impl_->entries = entries;
  impl_->we.allocate(entries.size(), "the weights' tables");
  impl_->we.upload(entries.data(), entries.size());
}

CudaFusedPass::~CudaFusedPass() = default;
CudaFusedPass::CudaFusedPass(CudaFusedPass&&) noexcept = default;
CudaFusedPass& CudaFusedPass::operator=(CudaFusedPass&&) noexcept = default;

CudaPassResult CudaFusedPass::apply(const std::vector<int32_t>& targets,
                                    const std::vector<std::vector<double>>& fields) const {
  const Impl& I = *impl_;
  const CudaKernel::Impl& K = *I.k.impl_;
  const std::size_t n = K.cl.size();
  if (fields.empty() || fields.size() > static_cast<std::size_t>(kMaxFieldsDevice))
    throw InputError("CUDA fused pass: between 1 and " + std::to_string(kMaxFieldsDevice) +
                     " fields, got " + std::to_string(fields.size()));
  for (auto& f : fields)
    if (f.size() != n)
      throw InputError("CUDA fused pass: a field's size differs from the number of particles");
  CudaPassResult r;
  r.nw = static_cast<int>(I.entries.size());
  r.nf = static_cast<int>(fields.size());
  r.nt = targets.size();
  std::vector<int32_t> slot, pos;
  K.order_targets(targets, slot, pos);
  if (r.nt == 0) return r;
  if (r.nt > static_cast<std::size_t>(INT32_MAX))
    throw InputError("CUDA fused pass: more than 2^31 - 1 targets");
  K.prepare(slot, pos);
  const SortedFields sorted = sorted_fields(K.cl, fields);
  if (I.fields.size() < sorted.data.size()) I.fields.allocate(sorted.data.size(), "the fields");
  I.fields.upload(sorted.data.data(), sorted.data.size());
  const std::size_t ncol = static_cast<std::size_t>(r.nw * r.nf * 4);
  if (I.out.size() < ncol * r.nt) I.out.allocate(ncol * r.nt, "the pass's results");
  K.ev->start();
  fused_pass_kernel<<<blocks_for(r.nt), kThreads>>>(
      K.dev, I.we.get(), r.nw, I.fields.get(), r.nf, sorted.stride, K.tslot.get(),
      K.tpos.get(), static_cast<int32_t>(r.nt), I.out.get());
  GPM_CUDA_CHECK(cudaGetLastError());
  K.ev->stop();
  r.kernel_ms = K.ev->elapsed_ms();
  r.data.resize(ncol * r.nt);
  I.out.download(r.data.data(), r.data.size());
  return r;
}

}  // namespace gpm::cuda
