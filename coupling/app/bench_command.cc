// `wearsim bench dem`: builds a workload (dem/engine/benchmark.h), settles it with the floor
// rotating, warms up, then times `steps` steps per repeat. Particle-steps per second =
// N x timed steps / wall time of the timed loop; the median over repeats is reported last.
#include "coupling/app/bench_command.h"

#include "coupling/app/bench_fem.h"
#include "coupling/output/progress_line.h"
#include "dem/engine/benchmark.h"
#include "meshes/stopwatch.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>
#include <stdexcept>
#include <thread>

namespace wear::coupling {

namespace {
std::uint64_t to_count(const std::string& flag, const std::string& v) {
  try {
    const long long x = std::stoll(v);
    if (x < 0)
      throw std::invalid_argument("");
    return std::uint64_t(x);
  } catch (const std::exception&) {
    throw std::invalid_argument("wearsim bench: " + flag + " needs a non-negative integer, got '" +
                                v + "'");
  }
}

std::vector<int> parse_thread_counts(const std::string& flag, const std::string& v) {
  std::vector<int> counts;
  std::size_t at = 0;
  while (at <= v.size()) {
    const auto comma = std::min(v.find(',', at), v.size());
    counts.push_back(int(to_count(flag, v.substr(at, comma - at))));
    at = comma + 1;
  }
  return counts;
}

struct BenchDemArguments {
  dem::BenchmarkOptions options;
  std::vector<int> thread_counts; ///< timed in turn in every repeat; 0 given means all cores
};

BenchDemArguments bench_dem_arguments(const std::vector<std::string>& args) {
  BenchDemArguments a;
  auto& o = a.options;
  for (std::size_t k = 1; k < args.size(); k += 2) {
    if (k + 1 >= args.size())
      throw std::invalid_argument("wearsim bench: option " + args[k] + " needs a value");
    const std::string& f = args[k];
    const std::string& v = args[k + 1];
    if (f == "--workload")
      o.workload = v;
    else if (f == "--threads")
      a.thread_counts = parse_thread_counts(f, v);
    else if (f == "--settle")
      o.settle_steps = to_count(f, v);
    else if (f == "--warm")
      o.warm_steps = to_count(f, v);
    else if (f == "--steps")
      o.timed_steps = to_count(f, v);
    else if (f == "--repeats")
      o.repeats = std::max(1, int(to_count(f, v)));
    else
      throw std::invalid_argument("wearsim bench: unknown option '" + f + "'");
  }
  const int all = int(std::thread::hardware_concurrency());
  if (a.thread_counts.empty())
    a.thread_counts.push_back(all);
  for (int& t : a.thread_counts)
    if (t == 0)
      t = all;
  return a;
}

// Sets the workload up and settles it with the floor rotating; returns the wall time [s].
double settle(dem::System& s, const dem::BenchmarkOptions& o, int threads, std::ostream& out) {
  const meshes::Stopwatch clock;
  s.setup();
  out << format("workload %s: %zu particles, %d walls, dt %.4e s, %d threads; settling %llu "
                "steps\n",
                o.workload.c_str(), s.particles.n_real, s.n_walls(), s.time_step(), threads,
                (unsigned long long)o.settle_steps)
      << std::flush;
  for (std::uint64_t k = 0; k < o.settle_steps; k += 1000)
    s.run(std::min<std::uint64_t>(1000, o.settle_steps - k));
  return clock.seconds();
}

// Particle-steps per second of every repeat, per thread count. Repeats interleave the
// thread counts, so each pair of figures shares one time window.
std::map<int, std::vector<double>> timed_rates(dem::System& s, const BenchDemArguments& a,
                                               std::ostream& out) {
  const auto& o = a.options;
  const double n = double(s.particles.n_real);
  std::map<int, std::vector<double>> rates;
  for (int r = 0; r < o.repeats; ++r)
    for (int th : a.thread_counts) {
      s.set_n_threads(th);
      s.run(o.warm_steps);
      const auto n0 = s.n_rebuilds();
      const meshes::Stopwatch clock;
      s.run(o.timed_steps);
      const double secs = clock.seconds();
      const double rate = n * double(o.timed_steps) / secs;
      rates[th].push_back(rate);
      out << format("repeat %d, %d threads: %llu steps in %.3f s, %.4e particle-steps/s, rebuild "
                    "every %.1f steps, %.2f neighbour pairs and %.2f contacts per particle\n",
                    r + 1, th, (unsigned long long)o.timed_steps, secs, rate,
                    double(o.timed_steps) / std::max<double>(1, double(s.n_rebuilds() - n0)),
                    double(s.n_neighbor_pairs()) / n, double(s.n_pair_contacts()) / n)
          << std::flush;
    }
  return rates;
}

// The medians, the settled bed (top, mean angular velocity L_z / sum r^2) and the memory and
// wall-contact figures; last the median rate of the last thread count, for scripts.
void report(dem::System& s, double settle_seconds, std::map<int, std::vector<double>>& rates,
            int last_threads, std::ostream& out) {
  double z_top = 0, lz = 0, r2 = 0;
  for (std::size_t i = 0; i < s.particles.n_real; ++i) {
    const auto& x = s.particles.position[i];
    const auto& v = s.particles.velocity[i];
    z_top = std::max(z_top, x.z);
    lz += x.x * v.y - x.y * v.x;
    r2 += x.x * x.x + x.y * x.y;
  }
  for (auto& [th, v] : rates) {
    std::sort(v.begin(), v.end());
    out << format("median with %d threads: %.4e particle-steps/s\n", th, v[v.size() / 2]);
  }
  const auto& last = rates[last_threads];
  out << format("settle %.1f s; bed top %.4f m, mean bed angular velocity %.3f rad/s; %.0f bytes "
                "per particle plus contact history; %zu particles, %zu near walls with %.2f "
                "candidate faces each\n",
                settle_seconds, z_top, lz / r2, s.bytes_per_particle(), s.particles.n_real,
                s.n_wall_particles(),
                double(s.n_wall_candidates()) / std::max<double>(1, double(s.n_wall_particles())));
  out << format("particle_steps_per_second %.6e\n", last[last.size() / 2]);
}
} // namespace

int run_bench_command(const std::vector<std::string>& args, std::ostream& out) {
  if (!args.empty() && args[0] == "fem")
    return run_bench_fem({args.begin() + 1, args.end()}, out);
  if (args.empty() || args[0] != "dem")
    throw std::invalid_argument("wearsim bench: 'wearsim bench dem [options]' or "
                                "'wearsim bench fem [options]'");
  const BenchDemArguments a = bench_dem_arguments(args);
  const int threads = *std::max_element(a.thread_counts.begin(), a.thread_counts.end());
  omp_set_num_threads(threads);
  dem::System s;
  dem::build_benchmark(s, a.options.workload);
  const double settle_seconds = settle(s, a.options, threads, out);
  auto rates = timed_rates(s, a, out);
  report(s, settle_seconds, rates, a.thread_counts.back(), out);
  return 0;
}

} // namespace wear::coupling
