#!/usr/bin/env bash
# Runs the modal scene on 1 and on 2 MPI ranks, and on one rank with its nodal
# diameters on 1 and on 3 threads, and compares every frequency: the distributed
# prestress, the nodal diameters spread over the ranks or the threads must not change
# the answer (threads: identical to every printed digit), and rank 1 must have solved
# some of them.
set -euo pipefail
cyclone=$1; mpiexec=$2; scene=$3; out=$4
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
rm -rf "$out"
"$cyclone" run "$scene" --output "$out/np1" > "$out.np1.log" 2>&1
for threads in 1 3; do
  sed "s/^  modal:/  modal:\n    threads: $threads/" "$scene" > "$out.threads$threads.yaml"
  "$cyclone" run "$out.threads$threads.yaml" --output "$out/threads$threads" > "$out.threads$threads.log" 2>&1
done
grep -q "nodal diameters on 3 threads" "$out.threads3.log" || { echo "the nodal diameters were not on 3 threads"; exit 1; }
cmp "$out/threads1/frequencies.csv" "$out/threads3/frequencies.csv" ||
  { echo "3 threads changed the frequencies of 1 thread"; exit 1; }
echo "frequencies on 3 threads identical to 1 thread ($(($(wc -l < "$out/threads1/frequencies.csv") - 1)) rows)"
"$mpiexec" -np 2 --oversubscribe -x OPENBLAS_NUM_THREADS "$cyclone" run "$scene" --output "$out/np2" > "$out.np2.log" 2>&1
grep -q "; rank 1)" "$out.np2.log" || { echo "no nodal diameter was solved on rank 1"; exit 1; }
paste -d, "$out/np1/frequencies.csv" "$out/np2/frequencies.csv" | awk -F, '
  NR == 1 { next }
  { d = ($4 - $8) / $4; if (d < 0) d = -d; if (d > worst) worst = d; rows++ }
  END { printf "%d frequencies, max relative difference 1 vs 2 ranks: %.2e\n", rows, worst;
        exit (rows > 0 && worst < 1e-10) ? 0 : 1 }'
# A nodal diameter that fails on rank 1 (a shift above its lowest eigenvalue) must stop
# every rank with its message, not leave rank 0 waiting for its result.
sed 's/nodal_diameters: \[0, 3, 6\]/nodal_diameters: [6, 3]\n    shift: 1.01e8/; s/speeds_rpm: \[0, 9000\]/speeds_rpm: [0]/' \
  "$scene" > "$out.fail.yaml"
if timeout 300 "$mpiexec" -np 2 --oversubscribe -x OPENBLAS_NUM_THREADS "$cyclone" run "$out.fail.yaml" \
  --output "$out/fail" > "$out.fail.log" 2>&1; then
  echo "the failing scene succeeded"; exit 1
fi
grep -q "nodal diameter 3 (rank 1): CHOLMOD" "$out.fail.log" || { echo "no error naming ND 3 on rank 1"; exit 1; }
echo "a failure on rank 1 stopped both ranks with its message"
# The same failure on one rank with 2 threads: stopped with its message, not hung.
sed "s/^  modal:/  modal:\n    threads: 2/" "$out.fail.yaml" > "$out.fail_threads.yaml"
if timeout 300 "$cyclone" run "$out.fail_threads.yaml" --output "$out/fail_threads" > "$out.fail_threads.log" 2>&1; then
  echo "the failing scene succeeded on threads"; exit 1
fi
grep -q "CHOLMOD" "$out.fail_threads.log" || { echo "no CHOLMOD error on threads"; exit 1; }
echo "a failure on a thread stopped the run with its message"
