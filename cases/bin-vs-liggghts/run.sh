#!/usr/bin/env bash
# The speed check against LIGGGHTS 3.8 on a scene (README.md): bin.prm with `wearsim
# scene-run` and in.bin with LIGGGHTS, on 1 and 2 cores, with and without particle snapshots,
# in ROUNDS rounds whose runs alternate between the two codes; each whole run timed from the
# process's start to its end. Appends to $OUTPUT/times.csv; report.py reads it.
# usage: bash cases/bin-vs-liggghts/run.sh [rounds]   (default 2; about 15 min a round)
#   WEARSIM=build/wearsim  LIGGGHTS=/usr/bin/liggghts  OUTPUT=output/bin-vs-liggghts
set -euo pipefail
cd "$(dirname "$0")/../.."
rounds=${1:-2}
wearsim=$(realpath "${WEARSIM:-build/wearsim}")
liggghts=${LIGGGHTS:-/usr/bin/liggghts}
root=${OUTPUT:-output/bin-vs-liggghts}
here=cases/bin-vs-liggghts
plate=cases/hopper-rim/plate-128-48.stl
for tool in "$wearsim" "$liggghts" mpirun; do
  command -v "$tool" > /dev/null || { echo "run.sh: '$tool' not found" >&2; exit 2; }
done
mkdir -p "$root"
# The engine's time step: 0.2 x the Rayleigh time of the 6 mm particle (G = 1e7 Pa,
# nu = 0.25, 2650 kg/m^3), pi r sqrt(rho / G) / (0.1631 nu + 0.8766); LIGGGHTS takes the same.
dt=$(/usr/bin/python3 -c 'import math; print(repr(0.2 * math.pi * 0.003 * math.sqrt(2650 / 1e7) / (0.1631 * 0.25 + 0.8766)))')
steps=$(/usr/bin/python3 -c "print(round(1.0 / $dt))")
# The plug for LIGGGHTS: a 64-gon disc of 24 mm radius at z = 0, normal up.
/usr/bin/python3 - "$root/plug.stl" <<'PY'
import math, sys
n, r = 64, 0.024
with open(sys.argv[1], "w") as f:
    f.write("solid plug\n")
    for k in range(n):
        a, b = 2 * math.pi * k / n, 2 * math.pi * (k + 1) / n
        f.write("facet normal 0 0 1\nouter loop\nvertex 0 0 0\n")
        f.write(f"vertex {r * math.cos(a)!r} {r * math.sin(a)!r} 0\n")
        f.write(f"vertex {r * math.cos(b)!r} {r * math.sin(b)!r} 0\nendloop\nendfacet\n")
    f.write("endsolid plug\n")
PY
times=$root/times.csv
[ -f "$times" ] || echo "round,code,cores,snapshots,seconds,steps,particles_left,engine" > "$times"
engine=$(git describe --always --dirty 2>/dev/null || echo unknown)

ours() { # <cores> <snapshots 0|1> <round>
  local out=$root/ours-c$1-s$2-r$3 flag=false
  [ "$2" = 1 ] && flag=true
  sed -e "s|set Threads = 2|set Threads = $1|" -e "s|set Directory = .*|set Directory = $out|" \
      -e "s|  set Output interval = 0.05|  set Output interval = 0.05\n  set Particle snapshots = $flag|" \
      "$here/bin.prm" > "$out.prm"
  local t0 t1
  t0=$(date +%s.%N)
  "$wearsim" scene-run --overwrite "$out.prm" > "$out.log" 2>&1
  t1=$(date +%s.%N)
  local left
  left=$(grep -o '^t = [0-9.]* s: [0-9]* particles' "$out.log" | tail -1 | awk '{print $5}')
  echo "$3,ours,$1,$2,$(echo "$t1 - $t0" | bc),$steps,$left,$engine" >> "$times"
}

lig() { # <cores> <snapshots 0|1> <round>
  local out=$root/liggghts-c$1-s$2-r$3
  rm -rf "$out" && mkdir -p "$out"
  local t0 t1
  t0=$(date +%s.%N)
  mpirun --allow-run-as-root -np "$1" "$liggghts" -in "$here/in.bin" -var dt "$dt" \
    -var plate "$plate" -var plug "$root/plug.stl" -var dump "$2" -var out "$out" \
    -var skin "${SKIN:-0.0015}" -log "$out/log.liggghts" > "$out.log" 2>&1
  t1=$(date +%s.%N)
  local left
  left=$(awk '/^ *[0-9]+ +[0-9]+ /{n=$2} END{print n}' "$out/log.liggghts")
  echo "$3,liggghts,$1,$2,$(echo "$t1 - $t0" | bc),$steps,$left,LIGGGHTS 3.8" >> "$times"
}

for round in $(seq 1 "$rounds"); do
  for cores in 1 2; do
    for snap in 0 1; do
      if [ $(( (round + cores + snap) % 2 )) = 0 ]; then
        ours $cores $snap $round; lig $cores $snap $round
      else
        lig $cores $snap $round; ours $cores $snap $round
      fi
      tail -2 "$times"
    done
  done
done
/usr/bin/python3 "$here/report.py" "$times"
