// `wearsim bench dem`: builds a workload (dem/engine/benchmark.h, or the wear tester of
// bench_tester.h), settles it with the floor rotating, warms up, then times `steps` steps per
// repeat. Particle-steps per second = N x timed steps / wall time of the timed loop; the
// median over repeats is reported last. The loop time per particle-step is split by the
// engine's phase timers (System::phase_times: pair, wall and wait averaged over the threads);
// what they leave out is printed as "other". Memory per particle: the engine's arrays
// (System::bytes_per_particle) plus the contact history, 2 x 4 bytes of pair indices and
// 24 of tangential overlap per listed neighbour pair; peak resident memory from getrusage.
// Under mpirun the workload is built on every rank and cut into angular slabs (the engine
// keeps each rank's own); the rate counts the particles of all ranks over the loop time, and
// each timed loop is followed by the ranks' own figures (bench_ranks.h). The phase split,
// memory and contacts are then rank 0's.
#include "coupling/app/bench_command.h"

#include "coupling/app/bench_evolution.h"
#include "coupling/app/bench_fem.h"
#include "coupling/app/bench_ranks.h"
#include "coupling/app/bench_tester.h"
#include "coupling/output/text_format.h"
#include "dem/engine/benchmark.h"
#include "meshes/stopwatch.h"

#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
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

double to_positive(const std::string& flag, const std::string& v) {
  std::size_t used = 0;
  double x = 0;
  try {
    x = std::stod(v, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != v.size() || !(x > 0) || !std::isfinite(x))
    throw std::invalid_argument("wearsim bench: " + flag + " needs a positive number, got '" + v +
                                "'");
  return x;
}

// --scale, --sample, --case, --state, --flow: the options of the tester workload.
void parse_tester_option(TesterBenchOptions& t, const std::string& f, const std::string& v) {
  if (f == "--scale")
    t.scale = to_positive(f, v);
  else if (f == "--sample") {
    if (v != "convex" && v != "plain")
      throw std::invalid_argument("wearsim bench: --sample takes convex or plain, got '" + v + "'");
    t.convex = v == "convex";
  } else if (f == "--case")
    t.case_file = v;
  else if (f == "--state")
    t.state_file = v;
  else
    t.flow_steps = to_count(f, v);
}

struct BenchDemArguments {
  dem::BenchmarkOptions options;
  std::vector<int> thread_counts; ///< timed in turn in every repeat; 0 given means all cores
  TesterBenchOptions tester;      ///< --workload tester only
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
    else if (f == "--walls" && (v == "analytic" || v == "mesh"))
      o.mesh_walls = v == "mesh";
    else if (f == "--walls")
      throw std::invalid_argument("wearsim bench: --walls takes 'analytic' or 'mesh', got '" + v +
                                  "'");
    else if (f == "--scale" || f == "--sample" || f == "--case" || f == "--state" || f == "--flow")
      parse_tester_option(a.tester, f, v);
    else
      throw std::invalid_argument("wearsim bench: unknown option '" + f + "'");
  }
  if (a.tester.any_given() && o.workload != "tester")
    throw std::invalid_argument("wearsim bench: --scale, --sample, --case, --state and --flow "
                                "belong to --workload tester");
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
  const dem::RankLink* link = s.rank_link();
  out << format("workload %s: %.0f particles, %d walls, dt %.4e s, %d ranks x %d threads; "
                "settling %llu steps\n",
                o.workload.c_str(), double(s.n_particles_over_ranks()), s.n_walls(), s.time_step(),
                link ? link->n_ranks() : 1, threads, (unsigned long long)o.settle_steps)
      << std::flush;
  for (std::uint64_t k = 0; k < o.settle_steps; k += 1000)
    s.run(std::min<std::uint64_t>(1000, o.settle_steps - k));
  return clock.seconds();
}

// Nanoseconds per particle-step of one timed loop: the whole loop and the engine's phases.
struct PhaseSplit {
  double total = 0, pair = 0, wall = 0, integration = 0, rebuild = 0, wait = 0; ///< [ns]
};

struct TimedRun {
  double rate = 0; ///< [particle-steps/s]
  PhaseSplit ns;
  std::vector<RankRow> ranks; ///< under mpirun: every rank's share
  bool operator<(const TimedRun& o) const { return rate < o.rate; }
};

PhaseSplit phase_split(const dem::PhaseTimes& t, double loop_seconds, double particle_steps) {
  const double k = 1e9 / std::max(1.0, particle_steps);
  return {loop_seconds * k, t.pair * k, t.wall * k, t.integration * k, t.rebuild * k, t.wait * k};
}

std::string split_text(const PhaseSplit& s) {
  const double other = s.total - s.pair - s.wall - s.integration - s.rebuild - s.wait;
  return format("%.1f ns per particle-step: pair kernel %.1f, walls %.1f, integration %.1f, "
                "list rebuild %.1f, waits %.1f, other %.1f",
                s.total, s.pair, s.wall, s.integration, s.rebuild, s.wait, other);
}

// Rate and phase split of every repeat, per thread count. Repeats interleave the thread
// counts, so each pair of figures shares one time window.
std::map<int, std::vector<TimedRun>> timed_runs(dem::System& s, const BenchDemArguments& a,
                                                dem::MpiRankLink* ranks, std::ostream& out) {
  const auto& o = a.options;
  const double n = double(s.n_particles_over_ranks());
  std::map<int, std::vector<TimedRun>> runs;
  for (int r = 0; r < o.repeats; ++r)
    for (int th : a.thread_counts) {
      s.set_n_threads(th);
      s.run(o.warm_steps);
      const auto n0 = s.n_rebuilds();
      s.reset_phase_times();
      if (ranks)
        ranks->reset_traffic();
      const meshes::Stopwatch clock;
      s.run(o.timed_steps);
      double secs = clock.seconds();
      std::vector<RankRow> rows;
      if (ranks) {
        rows = gather_rank_rows(s, *ranks, secs);
        for (const RankRow& w : rows) // the slowest rank's loop is the run's
          secs = std::max(secs, w.loop_seconds);
      }
      const double steps = n * double(o.timed_steps);
      // The phases per particle-step of this rank's own particles (rank 0's, printed).
      const double own_steps = double(s.particles.n_real) * double(o.timed_steps);
      TimedRun run{steps / secs, phase_split(s.phase_times(), secs, own_steps), std::move(rows)};
      out << format("repeat %d, %d threads: %llu steps in %.3f s, %.4e particle-steps/s, rebuild "
                    "every %.1f steps, %.2f neighbour pairs and %.2f contacts per particle\n"
                    "  %s\n",
                    r + 1, th, (unsigned long long)o.timed_steps, secs, run.rate,
                    double(o.timed_steps) / std::max<double>(1, double(s.n_rebuilds() - n0)),
                    double(s.n_neighbor_pairs()) / double(s.particles.n_real),
                    double(s.n_pair_contacts()) / double(s.particles.n_real),
                    split_text(run.ns).c_str())
          << std::flush;
      if (!run.ranks.empty())
        print_rank_table(run.ranks, o.timed_steps, out);
      runs[th].push_back(std::move(run));
    }
  return runs;
}

// The engine's arrays, the contact history and the process's peak resident memory.
void report_memory(const dem::System& s, std::ostream& out) {
  const double n = double(std::max<std::size_t>(1, s.particles.n_real));
  const double pairs = double(s.n_neighbor_pairs()) / n;
  const double history = pairs * (2 * 4 + 24);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double peak = double(usage.ru_maxrss) * 1024; // Linux gives kilobytes
  out << format("memory per particle: %.0f bytes of engine arrays + %.0f of contact history "
                "(%.2f neighbour pairs x (2 x 4 + 24) bytes) = %.0f bytes; peak resident "
                "memory of the process %.1f MB (%.0f bytes per particle)\n",
                s.bytes_per_particle(), history, pairs, s.bytes_per_particle() + history,
                peak / 1048576, peak / n);
}

// Pair contacts and wall contacts per particle as the last force evaluation left them; the
// wall contacts are the filled history slots of the exported state (after the peak memory
// was read: the export is a copy).
void report_contacts(const dem::System& s, std::ostream& out) {
  if (!s.clumps().empty()) { // a bed of clumps has no state export: pairs only
    out << format("contacts per particle: %.3f pair contacts; %zu particles (members of %zu "
                  "clumps)\n",
                  double(s.n_pair_contacts()) /
                      double(std::max<std::size_t>(1, s.particles.n_real)),
                  s.particles.n_real, s.clumps().size());
    return;
  }
  const auto state = s.export_state();
  const std::size_t n_near = state.wall_particles.size();
  const std::size_t per = n_near > 0 ? state.slot_wall.size() / n_near : 0;
  std::size_t n_wall = 0;
  for (std::size_t q = 0; q < n_near; ++q)
    for (std::size_t k = 0; k < per && state.slot_wall[q * per + k] >= 0; ++k)
      ++n_wall;
  const double n = double(std::max<std::size_t>(1, s.particles.n_real));
  out << format("contacts per particle: %.3f pair contacts, %.3f wall contacts; %zu particles, "
                "%zu near walls with %.2f candidate faces each\n",
                double(s.n_pair_contacts()) / n, double(n_wall) / n, s.particles.n_real, n_near,
                double(s.n_wall_candidates()) / std::max<double>(1, double(n_near)));
}

// The medians with their phase split, the settled bed (top, mean angular velocity
// L_z / sum r^2), memory and contacts. Returns the median rate per thread count.
std::map<int, double> report(dem::System& s, double settle_seconds,
                             std::map<int, std::vector<TimedRun>>& runs, std::ostream& out) {
  double z_top = 0, sums[2] = {0, 0}; // L_z, sum r^2
  for (std::size_t i = 0; i < s.particles.n_real; ++i) {
    const auto& x = s.particles.position[i];
    const auto& v = s.particles.velocity[i];
    z_top = std::max(z_top, x.z);
    sums[0] += x.x * v.y - x.y * v.x;
    sums[1] += x.x * x.x + x.y * x.y;
  }
  dem::RankLink* link = s.rank_link();
  if (link) {
    link->max_over_ranks(&z_top, 1);
    link->sum_in_rank_order(sums, 2);
  }
  const double lz = sums[0], r2 = sums[1];
  std::map<int, double> medians;
  for (auto& [th, v] : runs) {
    std::sort(v.begin(), v.end());
    const TimedRun& m = v[v.size() / 2];
    medians[th] = m.rate;
    out << format("median with %d threads: %.4e particle-steps/s; %s\n", th, m.rate,
                  split_text(m.ns).c_str());
  }
  out << format("settle %.1f s; bed top %.4f m, mean bed angular velocity %.3f rad/s\n",
                settle_seconds, z_top, lz / r2);
  if (link)
    for (const auto& [th, v] : runs)
      out << format("median with %d threads per rank: load imbalance %.3f (computation, "
                    "largest / mean over the ranks)\n",
                    th, compute_imbalance(v[v.size() / 2].ranks));
  if (link)
    out << "rank 0's share: ";
  report_memory(s, out);
  if (!link) // over ranks a state export holds rank 0's wall slots only: no bed-wide count
    report_contacts(s, out);
  return medians;
}
} // namespace

int run_bench_command(const std::vector<std::string>& args, std::ostream& out_to,
                      dem::MpiRankLink* ranks) {
  std::ostream silent(nullptr); // the ranks after the first compute without a word
  std::ostream& out = ranks && ranks->rank() > 0 ? silent : out_to;
  if (!args.empty() && args[0] == "fem")
    return run_bench_fem({args.begin() + 1, args.end()}, out);
  if (!args.empty() && args[0] == "evolution")
    return run_bench_evolution({args.begin() + 1, args.end()}, out);
  if (args.empty() || args[0] != "dem")
    throw std::invalid_argument("wearsim bench: 'wearsim bench dem [options]', "
                                "'wearsim bench fem [options]' or 'wearsim bench evolution "
                                "[options]'");
  const BenchDemArguments a = bench_dem_arguments(args);
  const int threads = *std::max_element(a.thread_counts.begin(), a.thread_counts.end());
  omp_set_num_threads(threads);
  TesterWorkload tester;
  dem::System workload;
  double settle_seconds = 0;
  dem::SlabDecomposition slabs;
  if (a.options.workload == "tester") {
    if (ranks && ranks->n_ranks() > 1)
      throw std::invalid_argument("wearsim bench: --workload tester runs on one process; under "
                                  "mpirun use the annulus or a sector, or `wearsim dem`");
    tester = tester_workload(a.tester, a.options.settle_steps > 0, threads, settle_seconds, out);
  } else {
    dem::build_benchmark(workload, a.options);
    if (ranks && ranks->n_ranks() > 1) {
      slabs = dem::benchmark_slabs(workload, ranks->n_ranks());
      workload.set_rank_link(ranks, &slabs);
    }
    settle_seconds = settle(workload, a.options, threads, out);
  }
  dem::System& s = tester.scene ? tester.scene->engine_for_timing() : workload;
  auto runs = timed_runs(s, a, ranks && ranks->n_ranks() > 1 ? ranks : nullptr, out);
  const auto medians = report(s, settle_seconds, runs, out);
  if (tester.scene)
    report_tester(tester, medians, out);
  out << format("particle_steps_per_second %.6e\n", medians.at(a.thread_counts.back()));
  return 0;
}

} // namespace wear::coupling
