#!/bin/bash
# Every whole-scene example in the documentation loads and validates (`isotrace info`), so that an example a user
# copies works. A whole scene is a fenced block opened with ```json scene (GitHub highlights it as JSON); other
# JSON blocks are fragments and are not checked here. The examples are self-contained (they name no files).
# Usage: doc_scene_examples_test.sh ISOTRACE SOURCE_DIR
set -u
cli=$1
root=$2
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

cd "$root" || exit 2
files=$( { ls README.md docs/*.md; find renderer geometry integrators -name README.md; } | sort)
count=0
failed=0
for file in $files; do
  # Writes block N of the file to $scratch/N.json and prints "N LINE" for each (LINE: where the block starts).
  blocks=$(awk -v out="$scratch/" '
    /^```json scene[ \t]*$/ { n++; name = out n ".json"; printf "" > name; inside = 1; print n, NR; next }
    inside && /^```[ \t]*$/ { inside = 0; close(name); next }
    inside { print > name }' "$file")
  while read -r n line; do
    [ -n "$n" ] || continue
    count=$((count + 1))
    if ! "$cli" info "$scratch/$n.json" > "$scratch/out" 2>&1; then
      echo "FAIL: $file:$line: the scene example does not load:"
      sed 's/^/  /' "$scratch/out"
      failed=$((failed + 1))
    fi
    rm -f "$scratch/$n.json"
  done <<< "$blocks"
done
# The examples are marked by hand: a documentation with none has lost its markers.
if [ "$count" -lt 10 ]; then
  echo "FAIL: only $count whole-scene examples (\`\`\`json scene) found; expected at least 10"
  exit 1
fi
[ "$failed" -eq 0 ] || exit 1
echo "ok: $count scene examples load"
