#!/usr/bin/env python3
"""Scaling model of the DEM over MPI ranks (issue 31), fed by one sitting of
scripts/bench_mpi.sh, predicting the s = 1 reference study on 16, 64 and 256 cores.

usage: python3 scripts/scaling_model.py [LOG_DIR] [--latency 2e-6] [--bandwidth 10e9]
                                        [--markdown]

The time of one step on P ranks x T threads (every rank steps together, the slowest sets
the pace):

    t_step = I * (N / P + gamma * n_g) * c / (T * e_T)              computation
             + m * alpha + 2 * alpha * log2(P)                      latency: neighbour
                                                                    messages, the rebuild
                                                                    decision's allreduce
             + b * n_g / beta                                       bandwidth

N particles, c the compute per particle-step on one core (the s = 3 wear tester, measured),
e_T the thread efficiency (measured at T = 2 on the annulus, extrapolated as e_2^log2(T)),
n_g the ghosts a rank receives per step: those within the reach of its lower cut, a band
whose particle count does not depend on P (n_g = k_g N reach / (Theta r_mean), k_g measured
on the annulus), gamma the cost of a ghost relative to a particle (its refresh, packing and
returned forces; its pairs are counted with the receiving rank's own), b the bytes sent per
ghost per step and m the messages per step (both measured), I the load imbalance (largest
over mean computation; measured on sector45k over 4 ranks, a uniform bed). alpha and beta
are the network's latency and bandwidth: assumptions, stated on the command line.

The study at s = 1: both samples, 3 revolutions to steady state and 17 after it, each
revolution 315,000 steps of 1.7 million particles (issue 31), plus one FEM stage per staged
revolution (serial, measured in the study at s = 3; the sample mesh does not depend on s).
The angular slabs must be at least the reach wide at the inner cylinder, which caps the
rank count.
"""
import argparse
import glob
import math
import os
import re
import statistics
import sys

PI = math.pi


def read(path):
    with open(path) as f:
        return f.read()


def rate(text):
    m = re.search(r"^particle_steps_per_second (\S+)", text, re.M)
    if not m:
        raise SystemExit(f"scaling_model: no particle_steps_per_second line: {text[:200]}")
    return float(m.group(1))


def rates_by_threads(text):
    """Median rate per thread count: 'median with T threads: R particle-steps/s'."""
    return {int(t): float(r) for t, r in
            re.findall(r"^median with (\d+) threads: (\S+) particle-steps/s", text, re.M)}


def rank_rows(text):
    """The per-rank table rows: rank, particles, ghosts, rate, MPI share, kB/step, msg/step."""
    rows = re.findall(r"^\s+(\d+)\s+(\d+)\s+(\d+)\s+(\S+)\s+(\S+) %\s+(\S+)\s+(\S+)$", text, re.M)
    return [tuple(float(x) for x in r) for r in rows]


def imbalance(text):
    m = re.findall(r"load imbalance \(largest / mean\): computation (\S+), particles (\S+)", text)
    return [(float(a), float(b)) for a, b in m]


def liggghts_rate(text):
    m = re.search(r"Loop time of (\S+) on (\d+) procs for (\d+) steps with (\d+) atoms", text)
    if not m:
        raise SystemExit("scaling_model: no LIGGGHTS loop time")
    t, _, steps, n = float(m.group(1)), m.group(2), int(m.group(3)), int(m.group(4))
    return n * steps / t


def measured(log_dir):
    f = lambda pattern: sorted(glob.glob(os.path.join(log_dir, pattern)))
    annulus_t = [rates_by_threads(read(p)) for p in f("ours_annulus_np1_t2_r*.log")]
    annulus_r = [read(p) for p in f("ours_annulus_np2_t1_r*.log")]
    lig = [liggghts_rate(read(p)) for p in f("liggghts_annulus45k_np2_r*.log")]
    if not annulus_t or not annulus_r or not lig:
        raise SystemExit(f"scaling_model: the logs of scripts/bench_mpi.sh are missing in {log_dir}")
    one = statistics.median(r[1] for r in annulus_t)
    two = statistics.median(r[2] for r in annulus_t)
    ranks2 = statistics.median(rate(t) for t in annulus_r)
    rows = [row for t in annulus_r for row in rank_rows(t)]
    ghosts = statistics.median(r[2] for r in rows)
    kb = statistics.median(r[5] for r in rows)
    msgs = statistics.median(r[6] for r in rows)
    mpi_share = statistics.median(r[4] for r in rows) / 100
    sector = {}
    for p in f("ours_sector45k_np*_t*.log"):
        np_, th = map(int, re.search(r"np(\d+)_t(\d+)", p).groups())
        text = read(p)
        sector[(np_, th)] = (rate(text), imbalance(text), rank_rows(text))
    tester = read(os.path.join(log_dir, "ours_tester_s3_t1.log"))
    return {
        "annulus_1x1": one, "annulus_1x2": two, "annulus_2x1": ranks2,
        "liggghts_2": statistics.median(lig), "n_rounds": len(lig),
        "ghosts": ghosts, "bytes_per_ghost": kb * 1e3 / ghosts, "messages": msgs,
        "mpi_share_2": mpi_share, "sector": sector,
        "c": 1.0 / rate(tester),
        "version": re.search(r"^== (\S+) wearsim ([0-9a-f]+(?:-dirty)?)",
                             read(os.path.join(log_dir, "run.log")), re.M).groups(),
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("log_dir", nargs="?", default="/tmp/wear-bench-mpi")
    ap.add_argument("--latency", type=float, default=2e-6, help="alpha [s] per message")
    ap.add_argument("--bandwidth", type=float, default=10e9, help="beta [B/s] per rank")
    ap.add_argument("--ghost-cost", type=float, default=0.1, help="gamma [-]")
    ap.add_argument("--fem-stage", type=float, default=30.0,
                    help="[s] one FEM stage (solve, mesh motion, output) of the study at s = 3 "
                         "(stage 4 of output/reference-study/plain, 2026-11-27: 28 s)")
    a = ap.parse_args()
    m = measured(a.log_dir)

    # Geometry: the annulus bench (d = 7.95 mm, skin 2 mm, 0.29 .. 0.50 m, full circle) and
    # the tester at s = 1 (d_max = 3.35 mm, d_min = 2.0 mm, skin d_min / 4, 150 degrees).
    r_in, r_out = 0.29, 0.50
    r_mean = 0.5 * (r_in + r_out)
    reach_annulus = 7.95e-3 + 2e-3
    k_g = m["ghosts"] / (44448 * reach_annulus / (2 * PI * r_mean))
    n, steps, theta = 1.7e6, 315000, 150 * PI / 180
    reach = 3.35e-3 + 0.25 * 2.0e-3
    n_g = k_g * n * reach / (theta * r_mean)
    p_max = int(math.floor(r_in * theta / reach))
    e2 = m["annulus_1x2"] / (2 * m["annulus_1x1"])
    imb = [i[0][0] for (np_, th), (_, i, _) in m["sector"].items() if np_ == 4 and i]
    imbalance = statistics.median(imb) if imb else 1.0
    c = m["c"]
    revolutions, staged = 2 * 20, 2 * 17

    def step_time(p, t):
        e_t = e2 ** math.log2(t) if t > 1 else 1.0
        compute = (imbalance if p > 1 else 1.0) * (n / p + (a.ghost_cost * n_g if p > 1 else 0)) \
            * c / (t * e_t)
        latency = (m["messages"] * a.latency + 2 * a.latency * math.log2(p)) if p > 1 else 0
        bandwidth = m["bytes_per_ghost"] * n_g / a.bandwidth if p > 1 else 0
        return compute, latency + bandwidth

    out = []
    w = out.append
    w("Measured (one sitting of scripts/bench_mpi.sh, %d rounds, %s, engine %s):"
      % (m["n_rounds"], m["version"][0], m["version"][1]))
    w("")
    w("| input | value |")
    w("|---|---|")
    w("| compute per particle-step, the s = 3 tester on one core, c | %.1f ns |" % (c * 1e9))
    w("| thread efficiency at 2 threads (annulus, 1 rank), e_2 | %.3f |" % e2)
    w("| annulus 2 ranks x 1 thread / 1 rank x 2 threads | %.3f |"
      % (m["annulus_2x1"] / m["annulus_1x2"]))
    w("| annulus 2 ranks x 1 thread / LIGGGHTS 2 ranks | %.2f |"
      % (m["annulus_2x1"] / m["liggghts_2"]))
    w("| ghosts per rank, annulus on 2 ranks (44,448 particles) | %.0f |" % m["ghosts"])
    w("| ghost band factor k_g (measured / N reach / (Theta r_mean)) | %.3f |" % k_g)
    w("| bytes sent per ghost per step, b | %.0f B |" % m["bytes_per_ghost"])
    w("| messages per step, m | %.1f |" % m["messages"])
    w("| time in MPI, annulus on 2 ranks of one host | %.1f %% |" % (100 * m["mpi_share_2"]))
    w("| load imbalance, sector45k on 4 ranks (oversubscribed), I | %.3f |" % imbalance)
    w("")
    w("Assumed: latency alpha = %.1f us per message, bandwidth beta = %.0f GB/s per rank, a ghost "
      "costs gamma = %.2f of a particle, %.0f s per FEM stage (serial), the s = 3 compute per "
      "particle-step at s = 1, e_T = e_2^log2(T)." % (a.latency * 1e6, a.bandwidth / 1e9,
                                                       a.ghost_cost, a.fem_stage))
    w("")
    w("The study at s = 1 (N = 1.7e6, 315,000 steps per revolution, 2 samples x 20 revolutions,"
      " 34 FEM stages); ghosts per rank n_g = %.0f; at most %d angular slabs (reach %.2f mm at "
      "the inner radius)." % (n_g, p_max, reach * 1e3))
    w("")
    w("| cores | ranks x threads | particles per rank | ghosts / own | step [ms] | in MPI | "
      "revolution [h] | study [h] | parallel efficiency |")
    w("|---|---|---|---|---|---|---|---|---|")
    serial = sum(step_time(1, 1))
    for cores in (16, 64, 256):
        best = None
        t = 1
        while t <= cores:
            p = cores // t
            if p <= p_max:
                comp, comm = step_time(p, t)
                if best is None or comp + comm < best[2] + best[3]:
                    best = (p, t, comp, comm)
            t *= 2
        p, t, comp, comm = best
        step = comp + comm
        rev_h = step * steps / 3600
        study_h = rev_h * revolutions + staged * a.fem_stage / 3600
        w("| %d | %d x %d | %.0f | %.3f | %.2f | %.1f %% | %.2f | %.1f | %.2f |"
          % (cores, p, t, n / p, n_g / (n / p), step * 1e3, 100 * comm / step, rev_h, study_h,
             serial / (cores * step)))
    text = "\n".join(out)
    print(text)


if __name__ == "__main__":
    main()
