#!/bin/sh
# The demo's disc at the seed's mesh size (mesh_size 1.25: 111 308 nodes, 334k DOF, 321
# shroud pairs): the static, prestress and reduced-model stages and the friction curve,
# one BLAS thread, with the peak memory sampled every 5 s; the run is stopped where it
# passes LIMIT_GB (default 18 of this machine's 24). For
# docs/studies/thesis_scale_chain.md. Usage, from the repository after ./scripts/run-tests:
#   sh docs/studies/thesis_scale_chain.sh [output directory] [patches] [contact_dofs]
# (contact_dofs: nodes, the default, or patch_means: the models retain each patch's mean
# motions instead of every face node)
set -e
cyclone=${CYCLONE:-build/drivers/cyclone}
out=${1:-thesis_scale_chain}
patches=${2:-27}
contact_dofs=${3:-nodes}
limit_kb=$(( ${LIMIT_GB:-18} * 1048576 ))
mkdir -p "$out"
"$cyclone" print-demo-scene > "$out/demo.yaml"
python3 - "$out" "$patches" "$contact_dofs" <<'PY'
import sys, yaml
out, patches, contact_dofs = sys.argv[1], int(sys.argv[2]), sys.argv[3]
scene = yaml.safe_load(open(out + "/demo.yaml"))
c = scene["cyclone"]
c["analysis"] = ["static", "disc_response"]
c["output_directory"] = out + "/run"
c["mesh"]["shrouded_sector"]["mesh_size"] = 1.25
c["reduced_model"]["check_frequencies"] = 0
c["reduced_model"]["contact_dofs"] = contact_dofs
c["disc_response"]["contact"]["patches"] = patches
for key in ("studies", "peak_studies", "peak_stress"):
    c["disc_response"].pop(key, None)
yaml.safe_dump(scene, open(out + "/thesis.yaml", "w"), sort_keys=False)
PY
OPENBLAS_NUM_THREADS=1 "$cyclone" run "$out/thesis.yaml" > "$out/run.log" 2>&1 &
pid=$!
while kill -0 $pid 2>/dev/null; do
  rss=$(ps -o rss= -p $pid || true)
  [ -n "$rss" ] && echo "$(date +%T) $rss" >> "$out/rss.log"
  if [ -n "$rss" ] && [ "$rss" -gt "$limit_kb" ]; then kill -9 $pid; echo "stopped above the limit" >> "$out/rss.log"; fi
  sleep 5
done
tail -5 "$out/run.log"
sort -k2 -n "$out/rss.log" | tail -1
