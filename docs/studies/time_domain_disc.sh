#!/bin/sh
# The default disc in the time domain, for docs/studies/time_domain_disc.md:
#  1. the demo's preload (20 kN over the shroud face): the harmonic balance with H = 5
#     and 10 against the ring integrated in time at the peak (the slow test
#     disc_time_domain; about 6 min);
#  2. a hammering preload (2 kN): the ring integrated in time at 9 frequencies over
#     1400..1560 Hz, each from the last one's end, and the harmonic balance's peaks
#     with H = 1..3 on the same model (disc_time_domain_sweep; about 40 min), with each
#     run's amplitude per period in a csv;
#  3. the hammering preload at 1520 Hz from rest with 2048 steps a period for 1500
#     periods (about 13 min), its amplitude per period drawn as an SVG;
#  4. Hill's method on the harmonic balance's curves (H = 1, 2) at 1500, 1520, 1540 Hz.
# Usage, from the repository after ./scripts/run-tests:
#   sh docs/studies/time_domain_disc.sh [output directory]
set -e
out=${1:-time_domain_disc}
mkdir -p "$out"
here=$(pwd)
cd "$out"
OPENBLAS_NUM_THREADS=1 "$here/build/regression/disc_time_domain" > demo_preload.log 2>&1
OPENBLAS_NUM_THREADS=1 "$here/build/regression/disc_time_domain_sweep" 2000 1400 1560 9 1024 3 1200 \
  hammering_history.csv > hammering.log 2>&1
OPENBLAS_NUM_THREADS=1 "$here/build/regression/disc_time_domain_sweep" 2000 1520 1520 1 2048 0 1500 \
  hammering_1520hz.csv > hammering_1520hz.log 2>&1
python3 "$here/docs/studies/amplitude_history_svg.py" hammering_1520hz.csv hammering_1520hz.svg \
  "2 kN preload, 1520 Hz, 2048 steps a period, from rest"
OPENBLAS_NUM_THREADS=1 "$here/build/regression/disc_time_domain_sweep" 2000 1480 1545 0 1024 2 1200 "" \
  1500,1520,1540 > hammering_hill.log 2>&1
grep -h "harmonic balance\|time domain\|peaks against" demo_preload.log
cat hammering.log hammering_1520hz.log hammering_hill.log
