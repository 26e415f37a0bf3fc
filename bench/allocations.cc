// Heap allocations of the Calibrator in the steady state, per IMU sample, per odometer sample
// and per GNSS epoch: malloc and its kin (operator new and Eigen both call them) counted around
// each add*() call, fed in time order from a simulated drive (without truth.csv: the live check
// against a truth is evaluation). A call during which a rover epoch left the calibrator's queue
// did that epoch's work and counts for the epoch; the others count for their sample. The first
// third of the drive (initialization, the first windows) is left out. Prints the mean and the
// largest count per kind, per estimator.
// With --where: also where the IMU and odometer samples' allocations come from, per estimator, as
// the most frequent call stacks (symbols need the -rdynamic this target is linked with).
// Usage: giocal_allocations [--preset config/sim/paper.yaml] [--seed N] [--where]
#include <execinfo.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <new>
#include <string>
#include <vector>

#include "common/calibration/calibration_inputs.h"
#include "replay/estimator_factory.h"
#include "simulated_inputs.h"

namespace {
std::atomic<long long> g_allocations{0};
// --where: the stacks of the allocations inside the call being counted (a fixed buffer, filled
// without allocating; backtrace() is primed before the first count).
constexpr int kDepth = 8, kStacks = 4096;
bool g_recording = false;
int g_recorded = 0;
void* g_stacks[kStacks][kDepth];
int g_depths[kStacks];

__attribute__((noinline)) void record() {
  if (!g_recording || g_recorded >= kStacks) return;
  g_recording = false;  // backtrace() itself must not recurse into here
  g_depths[g_recorded] = backtrace(g_stacks[g_recorded], kDepth);
  ++g_recorded;
  g_recording = true;
}
}  // namespace

// Every heap allocation of the process goes through these (the bench's own included, which is
// why only the calls' differences are read): malloc and its kin, which operator new and Eigen's
// dynamic matrices both call, interposed over glibc's.
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
void __libc_free(void*);

void* malloc(std::size_t n) {
  ++g_allocations;
  record();
  return __libc_malloc(n);
}
void* calloc(std::size_t k, std::size_t n) {
  ++g_allocations;
  record();
  return __libc_calloc(k, n);
}
void* realloc(void* p, std::size_t n) {
  ++g_allocations;
  record();
  return __libc_realloc(p, n);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t n) {
  ++g_allocations;
  record();
  *out = __libc_memalign(alignment, n);
  return *out ? 0 : 12;  // ENOMEM
}
void* aligned_alloc(std::size_t alignment, std::size_t n) {
  ++g_allocations;
  record();
  return __libc_memalign(alignment, n);
}
void free(void* p) { __libc_free(p); }
}

using namespace giocal;

namespace {

struct Tally {
  long long calls = 0, allocations = 0, worst = 0;
  void add(long long n) {
    ++calls;
    allocations += n;
    worst = std::max(worst, n);
  }
  double mean() const {
    return calls ? static_cast<double>(allocations) / static_cast<double>(calls) : 0.0;
  }
};

struct Tallies {
  Tally imu, odom, epoch;
  std::map<std::vector<void*>, long long> stacks;  // --where: sample calls' allocation stacks
};

Tallies feed(const CalibrationInputs& in, Calibrator& c, double steady_from, bool where) {
  Tallies t;
  size_t ko = 0, kr = 0, kb = 0;
  Tally ignored;
  const auto counted = [&](Tally& own, double at, const auto& call) {
    const size_t pending = c.health().pending_epochs;  // health() allocates: outside the count
    const long long before = g_allocations.load();
    g_recorded = 0;
    g_recording = where && at >= steady_from;
    call();
    g_recording = false;
    const long long n = g_allocations.load() - before;
    if (at < steady_from) return;
    const bool epoch = c.health().pending_epochs < pending;
    (epoch ? t.epoch : own).add(n);
    if (epoch || &own == &ignored) return;  // the stacks are the IMU's and odometer's
    for (int k = 0; k < g_recorded; ++k)
      ++t.stacks[std::vector<void*>(g_stacks[k] + 2, g_stacks[k] + g_depths[k])];
  };
  for (const ImuSample& s : in.imu) {
    while (ko < in.odom.size() && in.odom[ko].t <= s.t) {
      const OdomSample& o = in.odom[ko++];
      counted(t.odom, o.t, [&] { c.addOdometer(o); });
    }
    while (kr < in.rover.epochs.size() && in.rover.epochs[kr].t <= s.t) {
      const ObsEpoch& e = in.rover.epochs[kr++];
      counted(ignored, e.t, [&] { c.addRover(e); });
    }
    while (kb < in.base.epochs.size() && in.base.epochs[kb].t <= s.t) {
      const ObsEpoch& e = in.base.epochs[kb++];
      counted(ignored, e.t, [&] { c.addBase(e); });
    }
    counted(t.imu, s.t, [&] { c.addImu(s); });
  }
  return t;
}

}  // namespace

void printStacks(const std::map<std::vector<void*>, long long>& stacks) {
  std::vector<std::pair<long long, const std::vector<void*>*>> order;
  for (const auto& [stack, n] : stacks) order.push_back({n, &stack});
  std::sort(order.begin(), order.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  for (size_t k = 0; k < std::min<size_t>(order.size(), 12); ++k) {
    std::printf("  %lld allocations from:\n", order[k].first);
    const std::vector<void*>& frames = *order[k].second;
    char** names = backtrace_symbols(frames.data(), static_cast<int>(frames.size()));
    for (size_t f = 0; f < frames.size(); ++f) std::printf("    %s\n", names ? names[f] : "?");
    std::free(names);
  }
}

int main(int argc, char** argv) {
  bool where = false;
  for (int k = 1; k < argc; ++k) {
    if (std::strcmp(argv[k], "--where") == 0) {
      where = true;
      for (int j = k; j + 1 < argc; ++j) argv[j] = argv[j + 1];
      --argc;
      break;
    }
  }
  void* prime[1];
  backtrace(prime, 1);  // loads what backtrace() needs before anything is counted
  const bench::PresetSeed ps = bench::presetAndSeed(argc, argv);
  CalibrationInputs in = bench::simulatedInputs(ps, "giocal_allocations");
  in.description.truth.clear();  // no live check against a truth: robot work only
  const double t0 = in.imu.front().t, t1 = in.imu.back().t;
  const double steady_from = t0 + (t1 - t0) / 3.0;
  std::printf(
      "%s seed %llu: %zu IMU, %zu odometer samples, %zu GNSS epochs; counted from +%.0f s\n",
      ps.preset.c_str(), static_cast<unsigned long long>(ps.seed), in.imu.size(), in.odom.size(),
      in.rover.epochs.size(), steady_from - t0);
  std::printf("%-4s %-16s %10s %12s %10s\n", "est", "per", "calls", "mean allocs", "max");
  for (const char* est : {"ekf", "fgo"}) {
    auto c = makeCalibrator(est, in.description, in.base_e, CalibrationOptions{}, {}, nullptr);
    c->addNavigation(in.nav);
    const Tallies t = feed(in, *c, steady_from, where);
    c->finish();
    for (const auto& [name, tally] : {std::pair<const char*, const Tally&>{"IMU sample", t.imu},
                                      {"odometer sample", t.odom},
                                      {"GNSS epoch", t.epoch}}) {
      std::printf("%-4s %-16s %10lld %12.1f %10lld\n", est, name, tally.calls, tally.mean(),
                  tally.worst);
    }
    if (!t.stacks.empty()) printStacks(t.stacks);
  }
  return 0;
}
