#!/usr/bin/env bash
# The rim study (cases/hopper-rim/README.md): the bin discharging through an orifice of 36
# and 48 mm (6 and 8 particle diameters) in a plate from STL whose rim is a 32-gon or a
# 128-gon (the plates of make_plates.py), seeds 1 to N (default 6), one run at a time on 2
# threads. Writes a case file per run into output/hopper-rim/cases/, each run into
# output/hopper-rim/<n>-<D>-s<seed>;
# a run whose folder holds a finished series is skipped, so the script resumes a study.
# Then: /usr/bin/python3 cases/hopper-rim/report.py
#   usage: [WEARSIM=path/to/wearsim] [DIAMETERS="36 48"] bash cases/hopper-rim/run.sh [N]
# (DIAMETERS: the orifices in mm to run, of 36 and 48)
set -euo pipefail
cd "$(dirname "$0")/../.."
n_seeds=${1:-6}
out=output/hopper-rim
mkdir -p "$out/cases"
for seed in $(seq 1 "$n_seeds"); do
  for d_mm in ${DIAMETERS:-36 48}; do
    case $d_mm in 36|48) ;; *) echo "run.sh: DIAMETERS: no plate for $d_mm mm (36 or 48)" >&2; exit 2 ;; esac
    for n in 32 128; do
      run="$n-$d_mm-s$seed"
      if [ -f "$out/$run/scene_series.csv" ] &&
         awk -F, 'NR > 1 { t = $1 } END { exit !(t >= 1.3 - 1e-6) }' "$out/$run/scene_series.csv"; then
        continue
      fi
      prm="$out/cases/$run.prm"
      cat > "$prm.tmp" <<PRM
INCLUDE cases/hopper-rim/base.prm
subsection Scene
  subsection Wall floor
    set File = cases/hopper-rim/ring-$n-$d_mm.stl
  end
  subsection Wall plug
    set Radius = $(awk "BEGIN { print $d_mm / 2000 + 0.008 }")
  end
end
subsection DEM
  set Seed = $seed
end
subsection Output
  set Directory = $out/$run
end
PRM
      mv "$prm.tmp" "$prm"
      echo "run $run ($(date -u +%H:%M:%S))"
      "${WEARSIM:-build/wearsim}" scene-run --overwrite "$prm" > "$out/$run.log" 2>&1
    done
  done
done
