#!/bin/sh
# The reduced models' stage on the demo's disc at mesh size 3 with the check against the
# full FE compliance (12 frequencies, 8 random probe columns), for
# docs/studies/model_check_cost.md: each model's time, the check's, the peak memory.
# About 4 minutes on 2 cores. Usage, from the repository after ./scripts/run-tests:
#   sh docs/studies/model_check_cost.sh [output directory]
set -e
cyclone=${CYCLONE:-build/drivers/cyclone}
out=${1:-model_check_cost}
mkdir -p "$out"
"$cyclone" print-demo-scene > "$out/demo.yaml"
python3 - "$out/demo.yaml" "$out/mesh_3.yaml" "$out/mesh_3" <<'PY'
import sys, yaml
scene = yaml.safe_load(open(sys.argv[1]))
c = scene["cyclone"]
c["analysis"] = ["static", "disc_response"]
c["output_directory"] = sys.argv[3]
c["mesh"]["shrouded_sector"]["mesh_size"] = 3.0
for key in ("studies", "peak_studies", "peak_stress"):
    c["disc_response"].pop(key, None)
yaml.safe_dump(scene, open(sys.argv[2], "w"), sort_keys=False)
PY
OPENBLAS_NUM_THREADS=1 /usr/bin/time -v "$cyclone" run "$out/mesh_3.yaml" > "$out/mesh_3.log" 2>&1
grep -h "reduced model ND\|reduced model check\|Maximum resident" "$out/mesh_3.log"
