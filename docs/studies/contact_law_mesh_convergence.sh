#!/bin/sh
# The demo's disc with its contact law per unit area at mesh sizes 6, 4 and 8/3: the
# friction-damped peak converged in the harmonics (1 %) at each, for
# docs/studies/contact_law_mesh_convergence.md. The demo's scene less what the peak does
# not need (the modal sweep, the reduced models' check, the studies, the stresses).
# About 12 minutes on 2 cores. Usage, from the repository after ./scripts/run-tests:
#   sh docs/studies/contact_law_mesh_convergence.sh [output directory]
set -e
cyclone=${CYCLONE:-build/drivers/cyclone}
out=${1:-contact_law_mesh_convergence}
mkdir -p "$out"
"$cyclone" print-demo-scene > "$out/demo.yaml"
for size in 6.0 4.0 2.6667; do
  python3 - "$out/demo.yaml" "$out/mesh_$size.yaml" "$size" "$out/mesh_$size" <<'PY'
import sys, yaml
scene = yaml.safe_load(open(sys.argv[1]))
c = scene["cyclone"]
c["analysis"] = ["static", "disc_response"]
c["output_directory"] = sys.argv[4]
c["mesh"]["shrouded_sector"]["mesh_size"] = float(sys.argv[3])
c["reduced_model"]["check_frequencies"] = 0
for key in ("studies", "peak_studies", "peak_stress"):
    c["disc_response"].pop(key, None)
yaml.safe_dump(scene, open(sys.argv[2], "w"), sort_keys=False)
PY
  OPENBLAS_NUM_THREADS=1 "$cyclone" run "$out/mesh_$size.yaml" > "$out/mesh_$size.log" 2>&1
  grep -h "harmonics check: peak\|harmonics by error target" "$out/mesh_$size/report.md" | head -2
done
