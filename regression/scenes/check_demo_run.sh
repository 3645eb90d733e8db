#!/usr/bin/env bash
# The README's first command as a user runs it: `cyclone demo`, then what the user
# looks at: the run manifest says complete, every file it lists is there and not
# empty, and the report opens with the friction-damped peak and its harmonics check.
set -euo pipefail
cyclone=$1; out=$2
rm -rf "$out"
"$cyclone" demo --output "$out"
manifest="$out/run_manifest.txt"
grep -q "^status: complete" "$manifest" || { echo "demo: the manifest does not say complete"; exit 1; }
files=$(sed -n 's/^  - //p' "$manifest")
[ -n "$files" ] || { echo "demo: the manifest lists no files"; exit 1; }
for f in $files; do
  [ -s "$out/$f" ] || { echo "demo: $f is listed but missing or empty"; exit 1; }
done
grep -q "friction-damped peak: max|x(t)| .* Hz with harmonics 0\.\." "$out/report.md" ||
  { echo "demo: report.md has no friction-damped peak"; exit 1; }
grep -q "harmonics check" "$out/report.md" || { echo "demo: report.md has no harmonics check"; exit 1; }
echo "demo: complete, $(echo "$files" | wc -w) files, report with the headline peak"
