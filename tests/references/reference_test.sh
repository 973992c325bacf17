#!/usr/bin/env bash
# reference_test.sh <isotrace binary> <source dir> <scene name>: the statistical regression test of one scene
# (docs/reference-images.md). Renders scenes/<name>.json at 64 spp with a seed other than its reference's, at the
# reference's resolution, and runs isotrace diff --ztest against out/references/<name>.exr (made here by
# tools/make-references --cached when missing): per-pixel and per-block tests, both images' variances,
# Sidak-corrected. Fails with the z-test's listing; first checks that the scene is the one
# references/scene-hashes.txt was made from.
set -euo pipefail
if (($# != 3)); then
  echo "usage: $0 <isotrace binary> <source dir> <scene name>" >&2
  exit 64
fi
cli=$1
cd "$2"
name=$3
test_spp=64

fail() {
  echo "FAIL [reference_$name]: $*" >&2
  exit 1
}

hashes=references/scene-hashes.txt
line=$(awk -v n="$name" '$1 == n' "$hashes" 2>/dev/null || true)
[[ -n $line ]] || fail "no line for $name in $hashes: run tools/make-references $name"
read -r _ hash resolution seed _ <<<"$line"
current=$("$cli" info "scenes/$name.json" | sed -n 's/^scene hash *\([0-9a-f]*\).*/\1/p')
[[ $current == "$hash" ]] ||
  fail "scenes/$name.json (or a file it references) changed since its reference was made: scene hash $current," \
       "$hash in $hashes; if the change is meant to change the image, run tools/make-references $name and commit $hashes"
reference=${ISOTRACE_REFERENCE_DIR:-out/references}/$name.exr
# A fresh clone has no reference images: make this scene's (or remake it if it is from another version).
ISOTRACE=$cli tools/make-references --cached "$name" || fail "could not make $reference (tools/make-references --cached $name)"

out=${TMPDIR:-/tmp}/isotrace-reference-tests
mkdir -p "$out"
"$cli" render "scenes/$name.json" --reference --res "$resolution" --seed $((seed + 1)) --spp "$test_spp" --quiet \
  -o "$out/$name.exr"
status=0
"$cli" diff --ztest "$reference" "$out/$name.exr" --error-map "$out/$name-failures.png" --quiet || status=$?
if ((status == 3)); then
  fail "the $test_spp-spp render is not consistent with $reference (the z-test fails); the render and a map of" \
       "its failing pixels are in $out/"
elif ((status != 0)); then
  fail "isotrace diff --ztest failed with exit code $status"
fi
rm -f "$out/$name.exr" "$out/$name-failures.png"
echo "PASS [reference_$name]"
