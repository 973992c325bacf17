#!/usr/bin/env bash
# End-to-end tests of the isotrace command line. CTest runs one case per test:
#   cli_test.sh <isotrace binary> <source dir> <case>
# Each case works in its own temporary directory, removed afterwards. Renders are tiny (64x64 or smaller).
set -euo pipefail

if (($# != 3)); then
  echo "usage: $0 <isotrace binary> <source dir> <case>" >&2
  exit 64
fi
cli=$1
source_dir=$2
case_name=$3
cd "$source_dir"

# $work, $time_scale, fail, run, show_output
source "$(dirname "${BASH_SOURCE[0]}")/test_script_helpers.sh"
cornell=scenes/cornell_box.json
closed_mesh=tests/cli/closed_mesh.py  # closed_mesh.py MESH.obj [GENUS]: a closed, consistently oriented surface

# ---- helpers ---------------------------------------------------------------------------------------------

# cli_expect <exit code> <isotrace arguments...>: runs isotrace, captures $work/stdout and $work/stderr.
cli_expect() {
  local expected=$1
  shift
  run "$work/stdout" "$work/stderr" "$cli" "$@"
  if ((status != expected)); then
    show_output
    fail "isotrace $* exited with $status, expected $expected"
  fi
}

# expect_in <file> <fixed string> [what]: the file contains the string.
expect_in() {
  if ! grep -qF -- "$2" "$1"; then
    echo "--- $1:" >&2
    cat "$1" >&2
    fail "${3:-$(basename "$1")} does not contain \"$2\""
  fi
}

expect_no_file() {
  [[ ! -e "$1" ]] || fail "$1 exists but should not"
}

# Fails if a directory holds a leftover temporary output (".<name>.partial-<pid>.<ext>").
expect_no_partial_files() {
  local leftovers
  leftovers=$(find "$1" -name '*.partial*' -print)
  [[ -z "$leftovers" ]] || fail "leftover temporary files: $leftovers"
}

render_small() {  # render_small <extra arguments...>: the Cornell box at 64x64, 8 spp.
  cli_expect 0 render "$cornell" --res 64x64 --spp 8 --quiet "$@"
}

exr_info() {  # exr_info <exr> <output file>: every attribute and channel name of the image.
  iinfo -v "$1" >"$2" || fail "iinfo -v $1 failed"
}

# A small valid scene; the malformed-scene cases change one line of it. Line numbers matter: keep the layout.
write_base_scene() {  # write_base_scene <path>
  cat >"$1" <<'JSON'
{
  "isotrace": 1,
  "film": { "resolution": [16, 16], "spp": 1 },
  "camera": { "type": "perspective", "fov": 40, "look_at": { "eye": [0, 0, -5], "target": [0, 0, 0], "up": [0, 1, 0] } },
  "materials": { "grey": { "type": "diffuse", "reflectance": { "rgb": [0.5, 0.5, 0.5], "space": "lin_rec709" } } },
  "lights": [ { "type": "point", "position": [0, 3, -3], "intensity": { "rgb": [10, 10, 10], "space": "lin_rec709" } } ],
  "objects": [
    {
      "material": "grey",
      "shape": {
        "type": "sphere",
        "radius": 1
      }
    }
  ]
}
JSON
}

# bad_scene <line number> <replacement line or "" to keep> <expected line> <expected JSON path> [<expected text>]
# Writes the base scene with one line replaced, renders it, and checks exit code 2, "scene.json:LINE:" and the
# JSON path on stderr, and that neither the output nor a temporary file was left behind.
bad_scene() {
  local line=$1 replacement=$2 expected_line=$3 path=$4 text=${5:-}
  local dir="$work/scene"
  mkdir -p "$dir"
  write_base_scene "$dir/base.json"
  awk -v n="$line" -v r="$replacement" 'NR == n && r != "" { print r; next } { print }' "$dir/base.json" \
    >"$dir/scene.json"
  rm "$dir/base.json"
  check_bad_scene "$dir" "$expected_line" "$path" "$text"
}

check_bad_scene() {  # check_bad_scene <dir with scene.json> <expected line> <expected JSON path> [<expected text>]
  local dir=$1 expected_line=$2 path=$3 text=${4:-}
  cli_expect 2 render "$dir/scene.json" -o "$dir/out.exr" -o "$dir/out.png" --quiet
  sed 's/^/  stderr: /' "$work/stderr" >&2
  expect_in "$work/stderr" "$dir/scene.json:$expected_line:" stderr
  [[ -z "$path" ]] || expect_in "$work/stderr" "$path" stderr
  [[ -z "$text" ]] || expect_in "$work/stderr" "$text" stderr
  expect_no_file "$dir/out.exr"
  expect_no_file "$dir/out.png"
  expect_no_partial_files "$dir"
}

# ---- cases -----------------------------------------------------------------------------------------------

case_version() {
  cli_expect 0 --version
  expect_in "$work/stdout" "isotrace 0.1.0" stdout
}

case_help() {
  cli_expect 0 --help
  for text in --help --version render info depth bench polygonize; do expect_in "$work/stdout" "$text" "--help output"; done
}

case_render_help() {
  cli_expect 0 render --help
  for option in --output --spp --res --threads --seed --aov --stats-json --time --checkpoint --checkpoint-every --resume --tile-size --quiet --set --display --view; do
    expect_in "$work/stdout" "$option" "render --help output"
  done
}

case_info_help() {
  cli_expect 0 info --help
  expect_in "$work/stdout" "--plugins" "info --help output"
}

case_no_subcommand() {  # plain isotrace: a short usage, every command with what it does; exit 0
  cli_expect 0
  local command
  for command in "render    Render a scene to image files" "info      Validate a scene and print a summary" \
    "depth     Write a range image" "bench     Time fixed workloads" "benchmark Run the frozen benchmark suite" \
    "mesh      Polygonise" "(alias: polygonize)" "deform    Apply mesh deformers" \
    "diff      Compare an image with a reference" "isotrace COMMAND --help"; do
    expect_in "$work/stdout" "$command" "the usage"
  done
  (($(wc -l <"$work/stdout") <= 15)) || fail "the usage is not short: $(wc -l <"$work/stdout") lines"
}

# Every option that takes a number shows its type and range in --help, also those parsed as text on purpose.
case_help_shows_types() {
  cli_expect 0 render --help
  local entry
  for entry in "--spp INT:INT in [1 - 16777216]" "--threads INT:INT in [0 - 4096]" "--seed UINT64" \
    "--time SECONDS>0" "--checkpoint-every SECONDS>=0.05" "--target-error NUMBER>0" "--res WIDTHxHEIGHT" \
    "--tile-size INT:INT in [1 - 4096]" "--max-memory SIZE" "--max-scene-size SIZE" "--stats short|full|none"; do
    expect_in "$work/stdout" "$entry" "render --help"
  done
  grep -E -- '--(seed|time|checkpoint-every|target-error|res|max-scene-size) TEXT' "$work/stdout" &&
    fail "an option parsed as text shows TEXT"
  cli_expect 0 depth --help
  expect_in "$work/stdout" "--threads INT:INT in [0 - 4096]" "depth --help"
  expect_in "$work/stdout" "--res WIDTHxHEIGHT" "depth --help"
  cli_expect 0 mesh --help
  expect_in "$work/stdout" "--depth INT:INT in [1 - 10]" "mesh --help"
  expect_in "$work/stdout" "--simplify DISTANCE>=0" "mesh --help"
  cli_expect 0 bench --help
  expect_in "$work/stdout" "--resolution WIDTHxHEIGHT|scene" "bench --help"
  cli_expect 0 diff --help
  expect_in "$work/stdout" "--fail METRIC=VALUE" "diff --help"
  expect_in "$work/stdout" "--ppd FLOAT:FLOAT in [1 - 1000]" "diff --help"
  # Help texts describe, they do not point at work logs or equation numbers.
  for command in render info depth bench mesh deform diff; do
    cli_expect 0 "$command" --help
    grep -E -i 'eq\. ?[0-9]|seed [0-9]{3}|issue|session' "$work/stdout" && fail "$command --help cites a work log"
  done
  return 0
}

case_determinism_threads() {
  render_small --threads 1 -o "$work/a.exr"
  render_small --threads 2 -o "$work/b.exr"
  run "$work/stdout" "$work/stderr" idiff -fail 0 -warn 0 "$work/a.exr" "$work/b.exr"
  ((status == 0)) || { show_output; fail "images rendered with 1 and 2 threads differ"; }
}

case_determinism_tile_size() {
  render_small --threads 2 --tile-size 32 -o "$work/a.exr"
  render_small --threads 2 --tile-size 7 -o "$work/b.exr"
  run "$work/stdout" "$work/stderr" idiff -fail 0 -warn 0 "$work/a.exr" "$work/b.exr"
  ((status == 0)) || { show_output; fail "images rendered with tile sizes 32 and 7 differ"; }
}

case_stats_json() {
  render_small --threads 2 -o "$work/a.exr" --stats-json "$work/s.json"
  python3 - "$work/s.json" <<'PY' || fail "statistics JSON is incomplete"
import json, sys
with open(sys.argv[1]) as f:
    stats = json.load(f)
problems = []
for key in ["rays_total", "render_seconds", "build_seconds", "mrays_per_second", "threads", "spp",
            "nan_samples", "non_finite_pixels", "peak_memory_bytes", "geometry", "counters"]:
    if key not in stats:
        problems.append("missing key " + key)
if stats.get("threads") != 2: problems.append("threads is %r, expected 2" % stats.get("threads"))
if stats.get("spp") != 8: problems.append("spp is %r, expected 8" % stats.get("spp"))
if not stats.get("rays_total", 0) > 0: problems.append("rays_total is not positive")
geometry = stats.get("geometry")
if not isinstance(geometry, dict) or not geometry:
    problems.append("geometry is not a non-empty object")
else:
    for name, row in geometry.items():
        for key in ["intersection_tests", "closest_hits"]:
            if key not in row: problems.append("geometry.%s has no %s" % (name, key))
for p in problems: print("stats:", p, file=sys.stderr)
if problems:
    print(json.dumps(stats, indent=2), file=sys.stderr)
    sys.exit(1)
PY
}

case_exr_metadata() {
  render_small -o "$work/a.exr" --seed 7
  exr_info "$work/a.exr" "$work/info"
  for key in isotrace:spp isotrace:seed isotrace:integrator isotrace:version isotrace:render_seconds \
    isotrace:rays isotrace:scene isotrace:partial; do
    expect_in "$work/info" "$key" "EXR metadata"
  done
  grep -Eq 'isotrace:spp: *8$' "$work/info" || fail "isotrace:spp is not 8"
  grep -Eq 'isotrace:seed: *"?7"?$' "$work/info" || fail "isotrace:seed is not 7"
  grep -Eq 'isotrace:version: *"0\.1\.0"' "$work/info" || fail "isotrace:version is not 0.1.0"
  grep -Eq 'isotrace:partial: *0$' "$work/info" || fail "isotrace:partial is not 0"
}

case_exr_aovs() {
  render_small -o "$work/plain.exr"
  exr_info "$work/plain.exr" "$work/plain_info"
  if grep -q "albedo.R" "$work/plain_info"; then fail "AOV channels written without --aov"; fi
  render_small -o "$work/a.exr" --aov all
  exr_info "$work/a.exr" "$work/info"
  for channel in R G B A albedo.R albedo.G albedo.B N.X N.Y N.Z Z P.X P.Y P.Z objectId primitiveId sampleCount \
    variance.R variance.G variance.B; do
    grep -Eq "channel list:.*(^|[ ,])$channel([ ,(]|$)" "$work/info" ||
      { cat "$work/info" >&2; fail "channel $channel missing with --aov all"; }
  done
  render_small -o "$work/d.exr" --aov depth,normal
  exr_info "$work/d.exr" "$work/d_info"
  grep -Eq "channel list:.*N\.X.*Z" "$work/d_info" || fail "--aov depth,normal did not add N and Z"
  if grep -q "albedo.R" "$work/d_info"; then fail "--aov depth,normal added albedo"; fi
}

case_round_primitives() {  # the cylinders, cones and tori of scenes/includes render without NaN and mesh closed
  cat >"$work/round.json" <<JSON
{
  "isotrace": 1,
  "include": "$PWD/scenes/includes/round_primitives.json",
  "film": {"resolution": [48, 24], "spp": 2},
  "camera": {"type": "perspective", "fov": 60, "look_at": {"eye": [0, 1.8, 4.2], "target": [0, 0.45, -0.7]}},
  "lights": [{"type": "directional", "direction": [-1, -2, -1.5], "irradiance": 1.5}],
  "objects": [{"name": "floor", "material": "round_white", "shape": {"type": "box", "center": [0, -0.05, 0], "half_size": [8, 0.05, 8]}}]
}
JSON
  cli_expect 0 render "$work/round.json" --quiet -o "$work/round.exr" --stats-json "$work/s.json"
  python3 - "$work/s.json" <<'PY' || fail "the round primitives' render statistics are wrong"
import json, sys
stats = json.load(open(sys.argv[1]))
problems = [key for key in ["nan_samples", "non_finite_pixels"] if stats.get(key) != 0]
for shape in ["cylinder", "cone", "torus"]:
    if not stats["geometry"].get(shape, {}).get("intersection_tests", 0) > 0: problems.append("no tests of " + shape)
for problem in problems: print("stats:", problem, file=sys.stderr)
sys.exit(1 if problems else 0)
PY
  # Closed, consistently oriented meshes of genus 0 (the cylinder) and 1 (the torus, the bored frustum).
  local object
  for object in round_cylinder:0 round_torus:1 round_bored_frustum:1; do
    cli_expect 0 mesh "$work/round.json" --object "${object%:*}" --method dc --depth 5 -o "$work/m.obj"
    python3 "$closed_mesh" "$work/m.obj" "${object#*:}" || fail "the mesh of ${object%:*} is not closed of genus ${object#*:}"
  done
}

case_valid_minimal_scene() {  # the base of the malformed-scene cases renders
  mkdir -p "$work/scene"
  write_base_scene "$work/scene/scene.json"
  cli_expect 0 render "$work/scene/scene.json" -o "$work/scene/out.exr" -o "$work/scene/out.png" --quiet
  [[ -s "$work/scene/out.exr" && -s "$work/scene/out.png" ]] || fail "outputs missing"
  expect_no_partial_files "$work/scene"
}

case_bad_scene_truncated() {
  local dir="$work/scene"
  mkdir -p "$dir"
  write_base_scene "$dir/base.json"
  # Keep lines 1-11 and the start of line 12 ('        "radius"'): the document ends inside objects[0].shape.
  { head -n 11 "$dir/base.json"; printf '        "radius"'; } >"$dir/scene.json"
  rm "$dir/base.json"
  check_bad_scene "$dir" 12 ""
}

case_bad_scene_wrong_type() {
  bad_scene 12 '        "radius": "big"' 12 "objects[0].shape.radius"
}

case_bad_scene_negative_radius() {
  bad_scene 12 '        "radius": -1' 12 "objects[0].shape.radius"
}

case_bad_scene_zero_resolution() {
  bad_scene 3 '  "film": { "resolution": [0, 16], "spp": 1 },' 3 "film.resolution"
}

case_bad_scene_unknown_key() {
  bad_scene 12 '        "radius": 1, "raduis": 2' 12 "objects[0].shape.raduis"
}

# write_shape_scene <dir> <line 11> <line 12>: the base scene in <dir>/scene.json with the shape's two lines replaced.
write_shape_scene() {
  mkdir -p "$1"
  write_base_scene "$1/base.json"
  awk -v a="$2" -v b="$3" 'NR == 11 { print a; next } NR == 12 { print b; next } { print }' "$1/base.json" \
    >"$1/scene.json"
  rm "$1/base.json"
}

case_bad_scene_missing_mesh() {
  write_shape_scene "$work/scene" '        "type": "mesh",' '        "file": "no_such_mesh.obj"'
  check_bad_scene "$work/scene" 12 "objects[0].shape.file" "no_such_mesh.obj"
}

case_bad_scene_unknown_shape() {
  bad_scene 11 '        "type": "sphear",' 11 "objects[0].shape.type" "sphear"
}

# A blob element's material is resolved like an object's: an unknown name is reported where it is written.
case_bad_scene_blob_element_material() {
  local ball='{"center": [0, 0, 0], "radius": 1}'
  write_shape_scene "$work/scene" '        "type": "blobs",' \
    '        "elements": ['"$ball"', {"center": [1, 0, 0], "radius": 1, "material": "gray"}]'
  check_bad_scene "$work/scene" 12 "objects[0].shape.elements[1].material" 'unknown material "gray" (did you mean "grey"?)'
  expect_in "$work/stderr" "scene.json:12:105:" stderr  # the column of "gray"
  write_shape_scene "$work/gen" '        "type": "blobs",' \
    '        "generate": {"count": 10, "min": [0, 0, 0], "max": [1, 1, 1], "materials": ["grey", "blu"]}'
  check_bad_scene "$work/gen" 12 "objects[0].shape.generate.materials[1]" 'unknown material "blu"'
}

case_info_scene() {
  cli_expect 0 info "$cornell"
  grep -Eq '^objects +[0-9]+' "$work/stdout" || { show_output; fail "info does not print the object count"; }
}

# An infinite plane is left out of the scene's extent: info prints the sphere's bounds, not the world's, and the
# scene renders without NaN.
case_plane_scene_extent() {
  cat >"$work/plane.json" <<'JSON'
{"isotrace": 1, "film": {"resolution": [16, 16], "spp": 2},
 "camera": {"type": "perspective", "look_at": {"eye": [0, 1, 4], "target": [0, 0.5, 0]}},
 "materials": {"grey": {"type": "diffuse"}, "lamp": {"type": "emissive", "radiance": 5}},
 "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": 1}],
 "objects": [{"material": "grey", "shape": {"type": "plane"}},
             {"material": "grey", "shape": {"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5}},
             {"material": "lamp", "shape": {"type": "rectangle", "size": [1, 1]}, "transform": {"rotate": {"axis": [1, 0, 0], "angle": 180}, "translate": [0, 2, 0]}}]}
JSON
  cli_expect 0 info "$work/plane.json"
  expect_in "$work/stdout" "bounds       [-0.5 0 -0.5] .. [0.5 2 0.5]" "info output"
  cli_expect 0 render "$work/plane.json" -o "$work/plane.exr"
  expect_in "$work/stderr" "NaN/Inf   0 samples discarded" "render statistics"
}

# Image I/O lives in a module loaded on first use: commands that read and write no image never load it (nor
# OpenImageIO's ~260 libraries); without the module, writing an image is a clear failure and leaves no file.
case_image_module_on_demand() {
  for arguments in "--version" "info $cornell"; do
    LD_DEBUG=files "$cli" $arguments >/dev/null 2>"$work/loader"
    if grep -Eq 'libisotrace_oiio|libOpenImageIO' "$work/loader"; then
      fail "isotrace $arguments loaded the image module or OpenImageIO"
    fi
  done
  LD_DEBUG=files "$cli" render "$cornell" --res 8x8 --spp 1 --quiet -o "$work/a.png" >/dev/null 2>"$work/loader"
  expect_in "$work/loader" "libisotrace_oiio.so" "the loader's log of a render"
  [[ -s "$work/a.png" ]] || fail "render wrote no PNG"
  # EXR is written by a module of its own that links OpenEXR alone: no OpenImageIO for an EXR render.
  LD_DEBUG=files "$cli" render "$cornell" --res 8x8 --spp 1 --quiet -o "$work/a.exr" >/dev/null 2>"$work/loader"
  expect_in "$work/loader" "libisotrace_exr.so" "the loader's log of an EXR render"
  if grep -Eq 'libisotrace_oiio|libOpenImageIO' "$work/loader"; then
    fail "a render to EXR loaded the image module or OpenImageIO"
  fi
  [[ -s "$work/a.exr" ]] || fail "render wrote no EXR"

  # The library alone, without the module beside it (LD_LIBRARY_PATH comes before the binary's RUNPATH).
  mkdir "$work/lib"
  cp "$(dirname "$cli")/../lib/libisotrace.so.0" "$work/lib/"
  LD_LIBRARY_PATH="$work/lib" cli_expect 0 info "$cornell"
  LD_LIBRARY_PATH="$work/lib" cli_expect 1 render "$cornell" --res 8x8 --spp 1 --quiet -o "$work/b.png"
  expect_in "$work/stderr" "cannot load the image module $work/lib/libisotrace_oiio.so" stderr
  expect_no_file "$work/b.png"
  LD_LIBRARY_PATH="$work/lib" cli_expect 1 render "$cornell" --res 8x8 --spp 1 --quiet -o "$work/b.exr"
  expect_in "$work/stderr" "cannot load the EXR writer module $work/lib/libisotrace_exr.so" stderr
  expect_no_file "$work/b.exr"
  # A longer render loads the module while it runs: the failed load stops it, and it fails the same way.
  LD_LIBRARY_PATH="$work/lib" cli_expect 1 render "$cornell" --res 96x96 --spp 256 --quiet -o "$work/c.png"
  expect_in "$work/stderr" "cannot load the image module $work/lib/libisotrace_oiio.so" stderr
  expect_no_file "$work/c.png"
  expect_no_partial_files "$work"
}

case_info_plugins() {
  cli_expect 0 info --plugins
  grep -Eq '^ +sphere ' "$work/stdout" || { show_output; fail "info --plugins does not list sphere"; }
  grep -Eq '^ +mesh ' "$work/stdout" || { show_output; fail "info --plugins does not list mesh"; }
}

case_bad_resolution() {
  cli_expect 2 render "$cornell" --res 0x5 -o "$work/a.exr" --quiet
  expect_in "$work/stderr" "--res" stderr
  expect_no_file "$work/a.exr"
  cli_expect 2 render "$cornell" --res 64 -o "$work/a.exr" --quiet
  expect_in "$work/stderr" "WIDTHxHEIGHT" stderr
  expect_no_file "$work/a.exr"
}

case_bad_aov() {
  cli_expect 2 render "$cornell" --res 16x16 --aov bogus -o "$work/a.exr" --quiet
  expect_in "$work/stderr" 'unknown AOV "bogus"' stderr
  expect_no_file "$work/a.exr"
}

case_bad_output_format() {
  cli_expect 2 render "$cornell" --res 16x16 --spp 1 -o "$work/out.exr" -o "$work/out.bmp" --quiet
  expect_in "$work/stderr" "out.bmp" stderr
  expect_no_file "$work/out.bmp"
  expect_no_file "$work/out.exr"
  expect_no_partial_files "$work"
}

case_missing_output_directory() {  # rejected before rendering, as bad input
  cli_expect 2 render "$cornell" --res 16x16 --spp 1 -o "$work/no_such_dir/a.exr" --quiet
  expect_in "$work/stderr" "no_such_dir" stderr
  cli_expect 2 render "$cornell" --res 16x16 --spp 1 -o "$work/a.exr" --stats-json "$work/no_such_dir/s.json" --quiet
  expect_in "$work/stderr" "--stats-json" stderr
  expect_no_file "$work/a.exr"
}

case_interrupt() {
  local pid waited=0
  # Without --quiet isotrace prints "... loaded in ..." just before it starts rendering (and handles SIGINT).
  "$cli" render "$cornell" --res 64x64 --spp 100000 --threads 2 -o "$work/a.exr" >"$work/stdout" 2>"$work/stderr" &
  pid=$!
  until grep -q "loaded in" "$work/stderr"; do
    kill -0 "$pid" 2>/dev/null || { show_output; fail "isotrace ended before rendering"; }
    ((waited++ < 300)) || { kill -KILL "$pid"; fail "scene did not load within 30 s"; }
    sleep 0.1
  done
  sleep 1
  kill -INT "$pid"
  # A render stops at the next tile; give it 20 s before calling it hung.
  waited=0
  while kill -0 "$pid" 2>/dev/null; do
    ((waited++ < 200)) || { kill -KILL "$pid"; show_output; fail "isotrace did not stop within 20 s of SIGINT"; }
    sleep 0.1
  done
  status=0
  wait "$pid" || status=$?
  ((status == 130)) || { show_output; fail "exit code $status after SIGINT, expected 130"; }
  expect_in "$work/stderr" "interrupted" stderr
  [[ -s "$work/a.exr" ]] || fail "no image written after SIGINT"
  expect_no_partial_files "$work"
  exr_info "$work/a.exr" "$work/info"
  local spp partial
  spp=$(sed -n 's/.*isotrace:spp: *\([0-9]*\).*/\1/p' "$work/info")
  partial=$(sed -n 's/.*isotrace:partial: *\([0-9]*\).*/\1/p' "$work/info")
  [[ -n "$spp" && -n "$partial" ]] || { cat "$work/info" >&2; fail "isotrace:spp or isotrace:partial missing"; }
  echo "interrupted render: isotrace:spp $spp, isotrace:partial $partial" >&2
  ((spp < 100000)) || fail "isotrace:spp is $spp after an interrupted render"
  ((partial == 1 || spp > 0)) || fail "neither a partial image nor a completed pass (spp $spp, partial $partial)"
}

# ---- long renders: hard budgets, signals, checkpoints ----------------------------------------------------

# The renders below wait for events (a line printed, a checkpoint written), never for fixed delays, so that the
# slower instrumented builds pass too. Their bounds only catch hangs and are multiplied by $time_scale.

# start_render <stderr file> <isotrace render arguments...>: starts a render in the background, sets $pid, and
# returns once it has loaded the scene (isotrace prints "... loaded in ..." just before it starts rendering).
start_render() {
  local err=$1 waited=0
  shift
  "$cli" render "$@" >"$work/stdout" 2>"$err" &
  pid=$!
  until grep -q "loaded in" "$err"; do
    kill -0 "$pid" 2>/dev/null || { cat "$err" >&2; fail "isotrace ended before rendering"; }
    ((waited++ < 300 * time_scale)) || { kill -KILL "$pid"; fail "scene did not load within $((30 * time_scale)) s"; }
    sleep 0.1
  done
}

# wait_exit <seconds>: waits for $pid (killing it after that long, scaled), sets $status.
wait_exit() {
  local waited=0 limit=$(($1 * time_scale))
  while kill -0 "$pid" 2>/dev/null; do
    ((waited++ < limit * 10)) || { kill -KILL "$pid"; show_output; fail "isotrace did not stop within $limit s"; }
    sleep 0.1
  done
  status=0
  wait "$pid" || status=$?
}

# wait_for_file <path>: waits until $pid has created <path>. Returns 1 if the render ended first.
wait_for_file() {
  until [[ -e "$1" ]]; do
    kill -0 "$pid" 2>/dev/null || return 1
    sleep 0.01
  done
}

# --write-every writes the outputs between passes (whole files, marked "in progress") while the render goes on;
# the final write replaces them.
case_write_every() {
  start_render "$work/stderr" "$cornell" --res 64x64 --spp 16777216 --threads 2 --write-every 0.1 \
    -o "$work/a.exr" -o "$work/a.png"
  wait_for_file "$work/a.png" || { show_output; fail "no interim output while rendering"; }
  [[ "$(exr_attribute "$work/a.exr" stopped)" == "in progress" ]] ||
    fail "the interim EXR is marked \"$(exr_attribute "$work/a.exr" stopped)\", not \"in progress\""
  kill -INT "$pid"
  wait_exit 20
  ((status == 130)) || { show_output; fail "exit code $status after SIGINT, expected 130"; }
  [[ "$(exr_attribute "$work/a.exr" stopped)" == "interrupted" ]] || fail "the final write did not replace the interim one"
  expect_no_partial_files "$work"
  cli_expect 2 render "$cornell" --res 16x16 --spp 1 --write-every 0.01 -o "$work/b.exr"
  expect_in "$work/stderr" "--write-every: must be at least 0.05 s"
  cli_expect 2 render "$cornell" --res 16x16 --spp 1 --write-every nan -o "$work/b.exr"
  expect_no_file "$work/b.exr"
}

# checkpoint_number <checkpoint> <field>: a count from the checkpoint's metadata (JSON at the start of the file:
# completed_spp, samples), 0 while there is no checkpoint. Every checkpoint is renamed over the previous one
# complete, so the file read is always a whole one.
checkpoint_number() {
  local found
  found=$(grep -a -o -m 1 "\"$2\": [0-9]*" "$1" 2>/dev/null | head -n 1) || true
  echo "${found##* }" | sed 's/^$/0/'
}

# wait_for_checkpoint_past <checkpoint> <field> <value>: waits until $pid has written a checkpoint whose <field>
# is above <value>. Returns 1 if the render ended first (a render that never gets there hits CTest's limit).
wait_for_checkpoint_past() {
  until (($(checkpoint_number "$1" "$2") > $3)); do
    kill -0 "$pid" 2>/dev/null || return 1
    sleep 0.01
  done
}

exr_attribute() {  # exr_attribute <exr> <name>: the value of an isotrace: attribute
  iinfo -v "$1" | sed -n "s/.*isotrace:$2: *\"\{0,1\}\([^\"]*\)\"\{0,1\}.*/\1/p" | head -n 1
}

# A first pass at 1920x1080 with 4 light bounces takes many seconds on this scene; a 0.3 s budget must stop it
# inside the pass: fewer than one sample per pixel on average, the image marked partial.
case_time_budget_is_hard() {
  cli_expect 0 render "$cornell" --res 1920x1080 --spp 64 --time 0.3 --threads 2 --quiet --aov sample_count \
    -o "$work/a.exr" --stats-json "$work/stats.json"
  [[ "$(exr_attribute "$work/a.exr" stopped)" == "time budget" ]] || fail "isotrace:stopped is not \"time budget\""
  local spp spp_max
  spp=$(exr_attribute "$work/a.exr" spp)
  spp_max=$(exr_attribute "$work/a.exr" spp_max)
  echo "--time 0.3: isotrace:spp $spp, isotrace:spp_max $spp_max, $(grep '"render_seconds"' "$work/stats.json")" >&2
  ((spp < 64 && spp_max < 64)) || fail "the time budget did not stop the render (spp $spp, spp_max $spp_max)"
  if ((spp < spp_max)); then
    [[ "$(exr_attribute "$work/a.exr" partial)" == 1 ]] || fail "pixels differ in sample count but partial is not 1"
  fi
}

# SIGTERM: like the first Ctrl-C (partial image, checkpoint, exit 143); the checkpoint resumes.
case_sigterm() {
  start_render "$work/stderr" "$cornell" --res 64x64 --spp 100000 --threads 2 -o "$work/a.exr" \
    --checkpoint "$work/ck.bin"
  sleep 1
  kill -TERM "$pid"
  wait_exit 20
  ((status == 143)) || { show_output; fail "exit code $status after SIGTERM, expected 143"; }
  expect_in "$work/stderr" "interrupted by SIGTERM" stderr
  [[ "$(exr_attribute "$work/a.exr" stopped)" == interrupted ]] || fail "isotrace:stopped is not \"interrupted\""
  [[ -s "$work/ck.bin" ]] || fail "no checkpoint written after SIGTERM"
  expect_no_partial_files "$work"
  local before after
  before="$(exr_attribute "$work/a.exr" spp) $(exr_attribute "$work/a.exr" spp_max)"
  cli_expect 0 render "$cornell" --resume "$work/ck.bin" --time 0.5 --threads 2 -o "$work/b.exr"
  expect_in "$work/stderr" "resuming at $(exr_attribute "$work/a.exr" spp) spp" stderr
  after="$(exr_attribute "$work/b.exr" spp) $(exr_attribute "$work/b.exr" spp_max)"
  echo "interrupted: spp, spp_max = $before; resumed for 0.5 s: $after" >&2
  ((${after% *} >= ${before% *} && ${after#* } >= ${before#* })) ||
    fail "the resumed render (spp, spp_max = $after) has fewer samples than the one it resumed from ($before)"
  expect_no_partial_files "$work"
}

# A second signal ends at once, whatever is happening — here writing the large checkpoint and outputs: exit 128 +
# the signal, no temporary file left in the output directory, and the last output never written. The second
# signal is sent once isotrace has said that the first one stopped the render (sent sooner, ThreadSanitizer's
# runtime, which delivers signals at its next safe point, merges the two).
case_second_signal() {
  # 1024x1024 with every AOV takes seconds to write (a 360 MB checkpoint, then the images). Instrumented builds
  # get 1/time_scale of the pixels: they take as long to write them, and ThreadSanitizer needs 16 GB for 2048².
  local signal size
  size=$(awk -v scale="$time_scale" 'BEGIN { printf "%d", 1024 / sqrt(scale) }')
  for signal in TERM INT; do
    start_render "$work/stderr" "$cornell" --res "${size}x$size" --spp 100000 --threads 2 --aov all \
      -o "$work/a.exr" -o "$work/a.tif" --checkpoint "$work/ck.bin"
    sleep 0.5  # rendering (the handler is installed right after "loaded in" is printed)
    kill -"$signal" "$pid"
    until grep -q "SIG$signal: stopped; writing" "$work/stderr"; do
      kill -0 "$pid" 2>/dev/null || { show_output; fail "isotrace ended without saying it stopped for SIG$signal"; }
      sleep 0.01
    done
    kill -"$signal" "$pid"
    wait_exit 20
    local expected=143
    [[ $signal == INT ]] && expected=130
    ((status == expected)) || { show_output; fail "exit code $status after two SIG$signal, expected $expected"; }
    expect_no_partial_files "$work"
    expect_no_file "$work/a.tif"
  done
}

# kill_during_checkpoint_write: SIGKILLs $pid while it has a checkpoint open for writing: the unnamed file
# (O_TMPFILE) shows in /proc/<pid>/fd as "<directory>/#<inode> (deleted)". Returns 1 if the render ended first.
kill_during_checkpoint_write() {
  while kill -0 "$pid" 2>/dev/null; do
    if ls -l "/proc/$pid/fd" 2>/dev/null | grep -qF -- "-> $work/#"; then
      kill -KILL "$pid"
      wait "$pid" 2>/dev/null || true
      return 0
    fi
  done
  return 1
}

# SIGKILL at several moments, then resume, killed again, and resume to the end: the final image is bit-identical
# to the uninterrupted render. Three kills come right after the first checkpoint (one every 50 ms) past 0, 31
# and 127 completed samples per pixel: early, in the pass from 32 to 64 and in the last pass from 128 to 256,
# however fast the build renders; two come exactly while a checkpoint is being written. A kill leaves no
# temporary file behind unless it lands between the link and the rename, two consecutive system calls (docs/cli.md,
# "Output files"; about 1 run in 20 under load): that file must be the complete new checkpoint, and resume to the
# same image.
case_checkpoint_resume_identical() {
  cli_expect 0 render "$cornell" --res 48x48 --spp 256 --threads 2 --quiet -o "$work/reference.exr"
  local kill_at resumed=0 during_write=0 samples left
  for kill_at in 0 31 127 write write; do
    rm -f "$work/ck.bin"
    start_render "$work/stderr" "$cornell" --res 48x48 --spp 256 --threads 2 -o "$work/a.exr" \
      --checkpoint "$work/ck.bin" --checkpoint-every 0.05
    if [[ $kill_at == write ]]; then
      # The first checkpoint complete, then kill during the next write: the checkpoint must be the previous one.
      wait_for_file "$work/ck.bin" || true
      kill_during_checkpoint_write && during_write=$((during_write + 1))
    else
      wait_for_checkpoint_past "$work/ck.bin" completed_spp "$kill_at" ||
        echo "the render ended before a checkpoint past $kill_at spp" >&2
      kill -KILL "$pid" 2>/dev/null || true
      wait "$pid" 2>/dev/null || true
    fi
    left=$(find "$work" -name '.*partial-*')
    if [[ -n $left ]]; then
      # Only a SIGKILL between the link and the rename can leave one, and then it is the complete new checkpoint
      # under its hidden name: it must resume to the same image.
      [[ $(wc -l <<<"$left") == 1 && $left == "$work/.ck.partial-"????????????????.bin ]] ||
        fail "a SIGKILL ($kill_at) left temporary files behind: $(ls -l $left)"
      cli_expect 0 render "$cornell" --resume "$left" --checkpoint "$work/verify.bin" --threads 2 --quiet \
        -o "$work/left.exr"
      idiff -fail 0 -failpercent 0 -warn 0 "$work/reference.exr" "$work/left.exr" >"$work/idiff" 2>&1 ||
        { cat "$work/idiff" >&2; fail "a SIGKILL ($kill_at) left an incomplete checkpoint behind: $(ls -l $left)"; }
      echo "killed ($kill_at) between the link and the rename: the complete checkpoint was left as $left" >&2
      rm -f "$left" "$work/verify.bin"
    fi
    [[ -f "$work/ck.bin" ]] || { echo "killed ($kill_at): no checkpoint yet" >&2; continue; }
    # Resume and kill once more after the resumed render checkpointed samples of its own, then resume to the end.
    samples=$(checkpoint_number "$work/ck.bin" samples)
    start_render "$work/stderr" "$cornell" --resume "$work/ck.bin" --threads 1 -o "$work/b.exr" --checkpoint-every 0.05
    wait_for_checkpoint_past "$work/ck.bin" samples "$samples" ||
      echo "the resumed render ($kill_at) ended before its first checkpoint" >&2
    kill -KILL "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
    cli_expect 0 render "$cornell" --resume "$work/ck.bin" --threads 2 --tile-size 7 --quiet -o "$work/b.exr"
    idiff -fail 0 -failpercent 0 -warn 0 "$work/reference.exr" "$work/b.exr" >"$work/idiff" 2>&1 ||
      { cat "$work/idiff" >&2; fail "killed ($kill_at): the resumed image differs from the uninterrupted one"; }
    [[ "$(exr_attribute "$work/b.exr" spp)" == 256 ]] || fail "the resumed image does not have 256 spp"
    resumed=$((resumed + 1))
  done
  echo "resumed and identical after $resumed of 5 kills ($during_write of them during a checkpoint write)" >&2
  ((resumed == 5)) || fail "only $resumed of 5 kills left a checkpoint to resume"
  ((during_write >= 1)) || fail "no kill landed during a checkpoint write"
}

# The progress bar on a terminal (script(1) provides one, 60 columns): it fits the width, ends at 100 %, and with
# --time shows the clock against the budget.
case_progress_bar() {
  command -v script >/dev/null || fail "script (util-linux) is needed for a terminal"
  local arguments
  for arguments in "--spp 16" "--time 0.5"; do
    script -qec "stty cols 60; '$cli' render '$cornell' --res 32x32 $arguments --threads 2 -o '$work/a.exr'" \
      /dev/null >"$work/tty" || { cat "$work/tty" >&2; fail "render $arguments on a terminal failed"; }
    tr '\r' '\n' <"$work/tty" | sed 's/\x1b\[K//g' | grep -a '%' >"$work/bar" || fail "no progress bar drawn"
    cat "$work/bar" >&2
    awk 'length($0) > 59 { exit 1 }' "$work/bar" || fail "a progress line is wider than the 60-column terminal"
    tail -n 1 "$work/bar" | grep -q '100.0%' || fail "the progress bar did not end at 100 %"
    if [[ $arguments == --time* ]]; then
      grep -q 'budget' "$work/bar" || fail "with --time the bar does not show the budget"
    fi
  done
}

# A bad checkpoint or a changed scene or pixel option: exit 2, a clear message, the checkpoint untouched.
case_resume_bad_input() {
  cp "$cornell" "$work/scene.json"
  cli_expect 0 render "$work/scene.json" --res 16x16 --spp 100000 --time 0.2 --quiet -o "$work/a.exr" \
    --checkpoint "$work/ck.bin"
  [[ -s "$work/ck.bin" ]] || fail "no checkpoint after a time budget ended the render"
  local sum
  sum=$(md5sum <"$work/ck.bin")
  resume_fails() {  # resume_fails <checkpoint> <expected text> [more arguments]
    local checkpoint=$1 text=$2
    shift 2
    cli_expect 2 render "$work/scene.json" --resume "$checkpoint" --quiet -o "$work/b.exr" "$@"
    sed 's/^/  stderr: /' "$work/stderr" >&2
    expect_in "$work/stderr" "$text" stderr
    expect_no_file "$work/b.exr"
    expect_no_partial_files "$work"
  }
  head -c 100 "$work/ck.bin" >"$work/truncated.bin"
  resume_fails "$work/truncated.bin" "truncated"
  cp "$work/ck.bin" "$work/corrupted.bin"
  printf 'X' | dd of="$work/corrupted.bin" bs=1 seek=200 conv=notrunc status=none
  resume_fails "$work/corrupted.bin" "corrupted"
  cp "$work/scene.json" "$work/not_a_checkpoint.bin"
  resume_fails "$work/not_a_checkpoint.bin" "not an isotrace checkpoint"
  resume_fails "$work/scene.json" "an output may not replace an input"  # it would go on checkpointing to the scene
  resume_fails "$work/ck.bin" "--spp 32 differs from the checkpoint's 100000" --spp 32
  resume_fails "$work/ck.bin" "--res 8x8 differs" --res 8x8
  resume_fails "$work/ck.bin" "--seed 5 differs" --seed 5
  resume_fails "$work/ck.bin" "--aov depth differs" --aov depth
  echo >>"$work/scene.json"  # the same scene to the parser, but not the same file
  resume_fails "$work/ck.bin" "the scene file $work/scene.json changed since the checkpoint was written"
  [[ "$(md5sum <"$work/ck.bin")" == "$sum" ]] || fail "a refused resume changed the checkpoint"
  cli_expect 2 render "$work/scene.json" --resume "$work/missing.bin" --quiet -o "$work/b.exr"
  cli_expect 2 render "$work/scene.json" --checkpoint-every 5 --quiet -o "$work/b.exr"
  expect_in "$work/stderr" "needs --checkpoint" stderr
}

# ---- hostile input and safe output -----------------------------------------------------------------------

case_output_symlink_not_followed() {  # a planted symlink at the output or at old-style temporary names: refused, both kept
  echo precious >"$work/victim"
  ln -s "$work/victim" "$work/out.png"
  for n in 0 1 2 3; do ln -s "$work/victim" "$work/.out.partial-$$-$n.png"; done
  cli_expect 2 render "$cornell" --res 16x16 --spp 1 --quiet -o "$work/out.png"
  expect_in "$work/stderr" "symbolic link" stderr
  [[ "$(cat "$work/victim")" == precious ]] || fail "the symlink's target was overwritten"
  [[ -L "$work/out.png" ]] || fail "the symlink was replaced"
  rm "$work/out.png"
  cli_expect 0 render "$cornell" --res 16x16 --spp 1 --quiet -o "$work/out.png"
  [[ -f "$work/out.png" && ! -L "$work/out.png" ]] || fail "the output is not a regular file"
  [[ $(find "$work" -name '.out.partial-*' -type f | wc -l) == 0 ]] || fail "a temporary file was left behind"
}

# Disk full, simulated by a file-size limit (ulimit -f, in KiB): every output fails cleanly, none is truncated,
# no temporary is left, and each failing output is named (libjpeg used to exit() at the first one).
case_disk_full() {
  local format
  for format in png jpg tif exr; do
    run "$work/stdout" "$work/stderr" bash -c 'ulimit -f 1; exec "$@"' _ "$cli" render "$cornell" --res 64x64 \
      --spp 2 --quiet -o "$work/a.$format" -o "$work/b.png"
    ((status == 1)) || { show_output; fail "$format: exit code $status with a full disk, expected 1"; }
    expect_in "$work/stderr" "cannot write $work/a.$format" stderr
    expect_in "$work/stderr" "cannot write $work/b.png" stderr
    expect_no_file "$work/a.$format"
    expect_no_file "$work/b.png"
    expect_no_partial_files "$work"
  done
}

case_output_not_writable() {  # found before rendering, as bad input
  mkdir "$work/taken.png"
  cli_expect 2 render "$cornell" --res 16x16 --spp 1 -o "$work/taken.png"
  expect_in "$work/stderr" "is a directory" stderr
  if grep -q "loaded in" "$work/stderr"; then fail "the scene was loaded before the output was checked"; fi
  cli_expect 2 render "$cornell" --res 16x16 --spp 1 -o /proc/isotrace-test.png  # no one may create files there
  expect_in "$work/stderr" "/proc/isotrace-test.png" stderr
  expect_in "$work/stderr" "--output" stderr
}

case_display_metadata() {  # PNG text chunks, and ImageDescription in JPEG and TIFF
  local format
  for format in png jpg tif; do
    cli_expect 0 render "$cornell" --res 16x16 --spp 3 --quiet -o "$work/a.$format"
    oiiotool --info -v "$work/a.$format" >"$work/info" || fail "oiiotool cannot read a.$format"
    expect_in "$work/info" "isotrace:partial=0" "$format metadata"
    expect_in "$work/info" "isotrace:spp=3" "$format metadata"
    expect_in "$work/info" "isotrace:render_seconds=" "$format metadata"
  done
  oiiotool --info -v "$work/a.png" >"$work/info"
  grep -Eq '^ *isotrace:partial: "0"' "$work/info" || { cat "$work/info" >&2; fail "PNG has no isotrace:partial text chunk"; }
}

# Each: the replaced line of the base scene, and what the message must name.
case_bad_scene_ill_conditioned_transform() {  # Embree asserted (exit 134)
  bad_scene 9 '      "material": "grey", "transform": {"scale": [1, 1e-20, 1]},' 9 "objects[0].transform.scale" \
    "ill-conditioned"
}

case_bad_scene_huge_light_power() {
  bad_scene 6 '  "lights": [ { "type": "point", "position": [0, 3, -3], "intensity": 1e30 } ],' 6 "lights[0]" "power"
}

case_bad_scene_negative_intensity() {
  bad_scene 6 '  "lights": [ { "type": "point", "position": [0, 3, -3], "intensity": -1 } ],' 6 \
    "lights[0].intensity" "must not be negative"
  bad_scene 6 '  "lights": [ { "type": "directional", "direction": [0, -1, 0], "irradiance": [1, -1, 1] } ],' 6 \
    "lights[0].irradiance" "must not be negative"
}

case_bad_scene_non_linear_working_space() {
  bad_scene 2 '  "isotrace": 1, "colour": { "working_space": "srgb_texture" },' 2 "colour.working_space" "scene-linear"
}

case_bad_scene_display_view() {  # used to fail only when writing the PNG, after the render, without a position
  bad_scene 3 '  "film": { "resolution": [16, 16], "spp": 1, "display": "sRBG" },' 3 "film.display" 'did you mean "sRGB"'
  bad_scene 3 '  "film": { "resolution": [16, 16], "spp": 1, "view": "Raww" },' 3 "film.view" "view"
}

case_bad_ocio_variable() {
  mkdir -p "$work/scene"
  write_base_scene "$work/scene/scene.json"
  OCIO="$work/no_such.ocio" cli_expect 2 render "$work/scene/scene.json" -o "$work/scene/out.png" --quiet
  expect_in "$work/stderr" '$OCIO' stderr
  expect_in "$work/stderr" "no_such.ocio" stderr
  expect_no_file "$work/scene/out.png"
}

case_bad_scene_huge_twist() {  # hung and ignored Ctrl-C
  write_shape_scene "$work/scene" '        "type": "superquadric",' '        "deform": [{ "twist": 1e9 }]'
  check_bad_scene "$work/scene" 12 "objects[0].shape.deform[0].twist" "[-3600, 3600]"
}

case_bad_scene_unknown_key_lists_all_keys() {  # "crop" was never listed: it is only asked about
  bad_scene 3 '  "film": { "resolution": [16, 16], "spp": 1, "crpo": [0, 1, 0, 1] },' 3 "film.crpo" "crop"
}

case_bad_scene_nul_in_key() {  # the message used to end at the NUL
  bad_scene 3 '  "film": { "resolution": [16, 16], "spp": 1, "a\u0000b": 1 },' 3 'film.a\x00b' 'unknown key "a\x00b"'
}

case_bad_mesh_file() {  # the message names the scene line that refers to the mesh, then the mesh's own line
  local dir="$work/scene"
  write_shape_scene "$dir" '        "type": "mesh",' '        "file": "wrapped.obj"'
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 4294967299\n' >"$dir/wrapped.obj"
  check_bad_scene "$dir" 12 "objects[0].shape.file" "wrapped.obj:5: f line"
  printf 'v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n' >"$dir/wrapped.obj"
  check_bad_scene "$dir" 12 "objects[0].shape.file" 'wrapped.obj:3: v line: "nan"'
}

case_memory_estimate() {  # std::bad_alloc (exit 1) or the OOM killer before
  cli_expect 2 render "$cornell" --res 65536x65536 -o "$work/a.exr" --quiet
  expect_in "$work/stderr" "--res" stderr
  expect_in "$work/stderr" "needs about" stderr
  cli_expect 2 render "$cornell" --res 1024x1024 --max-memory 4M -o "$work/a.exr" --quiet
  expect_in "$work/stderr" "limit of 4.19 MB" stderr
  cli_expect 2 render "$cornell" --res 16x16 --max-memory lots -o "$work/a.exr" --quiet
  expect_in "$work/stderr" "--max-memory" stderr
  expect_no_file "$work/a.exr"
}

case_scene_size_limit() {  # /dev/zero was read without end; now it is refused as a device before reading
  cli_expect 2 render /dev/zero -o "$work/a.exr" --quiet --max-scene-size 1M
  expect_in "$work/stderr" "character device" stderr
  truncate -s 2M "$work/big.json"
  cli_expect 2 render "$work/big.json" -o "$work/a.exr" --quiet --max-scene-size 1M
  expect_in "$work/stderr" "larger than the limit" stderr
  mkdir -p "$work/scene"
  write_base_scene "$work/scene/scene.json"
  cli_expect 2 render "$work/scene/scene.json" -o "$work/a.exr" --quiet --max-scene-size 1
  expect_in "$work/stderr" "--max-scene-size" stderr
  expect_no_file "$work/a.exr"
}

case_million_keys() {  # the duplicate-key check was quadratic (5·10¹¹ comparisons here); no clock in the test:
  # CTest's 120 s timeout is the backstop against a return of it
  python3 - "$work/keys.json" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write('{"isotrace": 1, "materials": {')
    f.write(",".join('"m%d": {"type": "diffuse"}' % i for i in range(1000000)))
    f.write('}, "camera": {"type": "perspective", "fov": 40, "look_at": {"eye": [0, 0, -5], "target": [0, 0, 0], "up": [0, 1, 0]}}}')
PY
  cli_expect 0 info "$work/keys.json"
}

case_bad_numeric_options() {
  cli_expect 2 render "$cornell" --seed -1 -o "$work/a.exr" --quiet
  expect_in "$work/stderr" "isotrace: error: --seed" stderr
  cli_expect 2 render "$cornell" --seed 18446744073709551616 -o "$work/a.exr" --quiet
  expect_in "$work/stderr" "--seed" stderr
  cli_expect 2 render "$cornell" --time nan -o "$work/a.exr" --quiet
  expect_in "$work/stderr" "--time" stderr
  cli_expect 2 render "$cornell" --time 0 -o "$work/a.exr" --quiet
  expect_in "$work/stderr" "--time" stderr
  (($(wc -c <"$work/stderr") < 200)) || { cat "$work/stderr" >&2; fail "the --time 0 message is too long"; }
  expect_no_file "$work/a.exr"
}

case_cli_error_messages() {
  cli_expect 2 rendr "$cornell"
  expect_in "$work/stderr" 'isotrace: error: unknown command "rendr" (did you mean "render"?)' stderr
  cli_expect 2 render "$cornell" --spp 0
  expect_in "$work/stderr" "isotrace: error: --spp" stderr
  cli_expect 2 render "$cornell" --no-such-option
  expect_in "$work/stderr" "isotrace: error:" stderr
}

# Two blended balls and a lone one seen from 6 m, 24x16 pixels: the smallest scene with a blob group.
write_blob_scene() {  # write_blob_scene <path>
  cat >"$1" <<'JSON'
{
  "isotrace": 1,
  "film": { "resolution": [24, 16], "spp": 1 },
  "camera": { "type": "perspective", "fov": 40, "look_at": { "eye": [0, 0, -6], "target": [0, 0, 0], "up": [0, 1, 0] } },
  "materials": { "grey": { "type": "diffuse" } },
  "objects": [ { "material": "grey", "shape": { "type": "blobs", "elements": [
    { "center": [-0.4, 0, 0], "radius": 1 }, { "center": [0.4, 0, 0], "radius": 1 }, { "center": [0, 1.4, 0], "radius": 0.8 } ] } } ]
}
JSON
}

case_depth_help() {
  cli_expect 0 depth --help
  for option in --output --near --far --near-dark --exr --res --threads --quiet; do
    expect_in "$work/stdout" "$option" "depth --help output"
  done
}

# pixel_values <image>: one grey value (0..255) per line, row by row.
pixel_values() {
  oiiotool --dumpdata "$1" | sed -n 's/^ *Pixel ([0-9]*, *[0-9]*): *\([0-9]*\) .*/\1/p'
}

case_depth_range_image() {  # the base scene: a unit sphere 5 m in front of the camera, background around it
  mkdir -p "$work/scene"
  write_base_scene "$work/scene/scene.json"
  cli_expect 0 depth "$work/scene/scene.json" -o "$work/range.png" --exr "$work/z.exr" --res 32x32
  [[ -s "$work/range.png" && -s "$work/z.exr" ]] || fail "outputs missing"
  expect_no_partial_files "$work"
  iinfo -v "$work/range.png" >"$work/info" || fail "iinfo failed"
  expect_in "$work/info" "32 x   32, 1 channel, uint8 png" "range image info"
  pixel_values "$work/range.png" >"$work/values"
  (($(wc -l <"$work/values") == 1024)) || { head "$work/values" >&2; fail "expected 1024 pixel values"; }
  (($(sort -n "$work/values" | tail -1) == 255)) || fail "the nearest hit is not 255"
  (($(sort -n "$work/values" | head -1) == 0)) || fail "the farthest hit or background is not 0"
  (($(grep -cx 0 "$work/values") > 100)) || fail "no background (0) around the sphere"
  (($(awk '$1 > 0 && $1 < 255' "$work/values" | wc -l) > 50)) || fail "no grey levels between near and far"
  # The sphere's nearest point is 4 m away: with --near 2 --far 6.5 it is floor((6.5 - 4) * 256 / 4.5) = 142.
  cli_expect 0 depth "$work/scene/scene.json" -o "$work/fixed.png" --res 31x31 --near 2 --far 6.5 --quiet
  pixel_values "$work/fixed.png" >"$work/fixed_values"
  (($(sort -n "$work/fixed_values" | tail -1) == 142)) || fail "the nearest point (depth 4) is not 142 for 2..6.5"
  # --near-dark: the same point is floor((4 - 2) * 256 / 4.5) = 113, the lowest level; the background is 255.
  cli_expect 0 depth "$work/scene/scene.json" -o "$work/dark.png" --res 31x31 --near 2 --far 6.5 --near-dark --quiet
  pixel_values "$work/dark.png" >"$work/dark_values"
  (($(sort -n "$work/dark_values" | head -1) == 113)) || fail "the nearest point (depth 4) is not 113 with --near-dark"
  (($(grep -cx 255 "$work/dark_values") > 100)) || fail "no white background with --near-dark"
  exr_info "$work/z.exr" "$work/z_info"
  grep -Eq "channel list: *Z" "$work/z_info" || fail "the EXR has no Z channel"
}

case_depth_bad_input() {
  mkdir -p "$work/scene"
  write_base_scene "$work/scene/scene.json"
  cli_expect 2 depth "$work/scene/scene.json" -o "$work/range.png" --near 5 --far 2
  expect_in "$work/stderr" "--far" stderr
  cli_expect 2 depth "$work/scene/scene.json" -o "$work/range.jpg"
  expect_in "$work/stderr" ".png" stderr
  cli_expect 2 depth "$work/scene/scene.json" -o "$work/no_such_dir/range.png"
  expect_in "$work/stderr" "no_such_dir" stderr
  expect_no_file "$work/range.png"
}

case_bench_help() {
  cli_expect 0 bench --help
  for option in --threads --repeats --resolution --cell-size --cells-per-radius --json --quiet --filter --quick \
    --report --scaling --scaling-max --list; do
    expect_in "$work/stdout" "$option" "bench --help output"
  done
  # The spacing is applied in each shape's own space, before its object's transform.
  expect_in "$work/stdout" "own units" "bench --help output (--cell-size)"
}

case_bench_small_scene() {  # the whole pipeline in seconds
  write_blob_scene "$work/blobs.json"
  cli_expect 0 bench "$work/blobs.json" --filter direct_vs_tessellated --threads 1 2 --repeats 1 --resolution scene \
    --json "$work/bench.json"
  for text in "Direct" "Tessellated" "direct/tess" "blobs" "primary" "shadow" "bounce"; do
    expect_in "$work/stdout" "$text" "bench table"
  done
  python3 - "$work/bench.json" <<'PY' || fail "bench JSON is incomplete or wrong"
import json, sys
report = json.load(open(sys.argv[1]))["blob_comparison"]
scene = report["scenes"][0]
problems = []
# Timed runs come after a warm-up, as in the suite (the first run builds what rays find lazily).
if report["warm_up_runs"] != 1 or report["repeats"] != 1: problems.append("warm-up %r" % report["warm_up_runs"])
if scene["elements"] != 3: problems.append("elements %r" % scene["elements"])
if scene["rays"] != 24 * 16: problems.append("rays %r" % scene["rays"])
if [r["threads"] for r in scene["direct"]["runs"]] != [1, 2]: problems.append("direct thread counts")
t = scene["tessellated"]
if not t["triangles"] > 100: problems.append("triangles %r" % t["triangles"])
if not t["closed"]: problems.append("tessellation not closed")
if not all(r["direct_over_tessellated"] > 0 for r in t["runs"]): problems.append("ratio")
if not scene["pixel_agreement"] > 0.95: problems.append("pixel agreement %r" % scene["pixel_agreement"])
# The light sits above the bounds (top y 1.4 + 0.8), raised by their height.
if not (len(scene["light"]) == 3 and scene["light"][1] > 2.2): problems.append("light %r" % scene["light"])
for kind in ("shadow", "bounce"):
    k = scene[kind]
    if not 0 < k["rays"] <= scene["rays"]: problems.append("%s rays %r" % (kind, k["rays"]))
    if not k["agreement"] > 0.9: problems.append("%s agreement %r" % (kind, k["agreement"]))
    if not 0 <= k["direct_hit_fraction"] <= 1: problems.append("%s hit fraction" % kind)
    for side in ("direct", "tessellated"):
        runs = k[side]["runs"]
        if [r["threads"] for r in runs] != [1, 2]: problems.append("%s %s thread counts" % (kind, side))
        if not all(r["mrays_per_second"] > 0 and r["ns_per_ray"] > 0 and len(r["seconds"]) == 1 for r in runs):
            problems.append("%s %s timings" % (kind, side))
    if not all(r["direct_over_tessellated"] > 0 for r in k["tessellated"]["runs"]): problems.append("%s ratio" % kind)
# Shadow rays go only towards a light the surface faces: the camera sees the blobs from the side, so some
# primary hits face away from the light above.
if not scene["shadow"]["rays"] < scene["bounce"]["rays"]: problems.append("shadow rays not fewer than bounces")
for p in problems: print("bench:", p, file=sys.stderr)
sys.exit(1 if problems else 0)
PY
  cli_expect 2 bench "$work/blobs.json" --filter direct_vs_tessellated --cell-size 1e-9 --repeats 1 --resolution scene
  expect_in "$work/stderr" "cell" stderr
  cli_expect 2 bench "$work/no_such_scene.json" --filter direct_vs_tessellated
  expect_in "$work/stderr" "no_such_scene.json" stderr
}

# The round primitives are compared with their tessellation too, and the secondary rays' clearance is half the
# coarsest cell in the world: an isosurface scaled 4× by its transform has cells 4× as long as in its own space.
case_bench_round_primitives_and_scaled_cells() {
  cat >"$work/scaled.json" <<'JSON'
{
  "isotrace": 1,
  "film": {"resolution": [32, 18], "spp": 1},
  "camera": {"type": "perspective", "fov": 40, "look_at": {"eye": [0, 2, 8], "target": [0, 0.5, 0]}},
  "materials": {"grey": {"type": "diffuse", "reflectance": 0.5}},
  "lights": [{"type": "directional", "direction": [-1, -2, -1], "irradiance": 2}],
  "objects": [
    {"name": "ball", "material": "grey", "transform": {"scale": 4, "translate": [-1, 0.5, 0]},
     "shape": {"type": "isosurface", "function": "length(p) - 0.25",
               "contained_by": {"box": {"min": [-0.5, -0.5, -0.5], "max": [0.5, 0.5, 0.5]}}}},
    {"name": "ring", "material": "grey", "transform": {"translate": [1.5, 0.3, 0]},
     "shape": {"type": "torus", "major_radius": 0.5, "minor_radius": 0.2}}
  ]
}
JSON
  cli_expect 0 bench "$work/scaled.json" --filter direct_vs_tessellated --threads 1 --repeats 1 --json "$work/bench.json"
  python3 - "$work/bench.json" <<'PY' || fail "the round primitives or the scaled cells are compared wrongly"
import json, sys
scene = json.load(open(sys.argv[1]))["blob_comparison"]["scenes"][0]
t = scene["tessellated"]
print("elements", scene["elements"], "finest cell", t["cell_size"], "clearance", scene["secondary_clearance"])
problems = []
if scene["elements"] < 2: problems.append("elements %r (an isosurface and a torus)" % scene["elements"])
if not t["closed"]: problems.append("tessellation not closed")
# The torus's bounds are about 1.4 m across: cells of about 1.4/128 m; the ball's box is 4 m in the world: 4/128 m.
if not 1.3 / 128 < t["cell_size"] < 2 / 128: problems.append("finest cell %r" % t["cell_size"])
if abs(scene["secondary_clearance"] - 0.5 * 4 / 128) > 1e-9: problems.append("clearance %r" % scene["secondary_clearance"])
for p in problems: print("bench:", p, file=sys.stderr)
sys.exit(1 if problems else 0)
PY
}

# Superquadrics and CSG solids are compared with their dual-contouring tessellation like blob groups: both kinds are
# replaced (a closed mesh), counted and traced; a scene without implicit surfaces is refused.
case_bench_superquadrics_and_csg() {
  cli_expect 0 bench tests/cli/data/surfaces/superquadric_and_csg.json --filter direct_vs_tessellated --threads 1 \
    --repeats 1 --resolution 48x27 --json "$work/bench.json"
  python3 - "$work/bench.json" <<'PY' || fail "the superquadric and CSG comparison is wrong"
import json, sys
scene = json.load(open(sys.argv[1]))["blob_comparison"]["scenes"][0]
t = scene["tessellated"]
problems = []
if scene["elements"] != 2: problems.append("elements %r (a superquadric and a CSG solid)" % scene["elements"])
if not (t["triangles"] > 1000 and t["closed"]): problems.append("tessellation %r" % t)
if not scene["pixel_agreement"] > 0.98: problems.append("pixel agreement %r" % scene["pixel_agreement"])
for p in problems: print("bench:", p, file=sys.stderr)
sys.exit(1 if problems else 0)
PY
  write_base_scene "$work/sphere.json"
  cli_expect 2 bench "$work/sphere.json" --filter direct_vs_tessellated --repeats 1
  expect_in "$work/stderr" "no blob group, isosurface, superquadric, CSG solid, torus, cylinder or cone" stderr
  # A superquadric inside a CSG solid counts its work in the statistics like one on its own.
  grep -v '"name": "tapered"\|"shape": {"type": "superquadric", "radii": \[0.4' tests/cli/data/surfaces/superquadric_and_csg.json \
    >"$work/csg_only.json"
  cli_expect 0 render "$work/csg_only.json" --quiet -o "$work/csg.exr" --stats-json "$work/stats.json"
  python3 -c 'import json, sys; c = json.load(open(sys.argv[1]))["counters"]; sys.exit(0 if c.get("superquadric.evaluations", 0) > 0 else 1)' \
    "$work/stats.json" || fail "the CSG operand's superquadric work is not counted"
}

# The secondary rays of the direct-vs-tessellated comparison start half a tessellation cell off the exact surface:
# from on it they would start inside the dual-contouring mesh of a sphere (its vertices lie outside a convex
# surface) and hit it at once, and a third of them would disagree.
case_bench_isosurface_agreement() {
  write_shape_scene "$work/scene" '        "type": "isosurface", "function": "length(p) - 1",' \
    '        "contained_by": {"box": {"min": [-1.2, -1.2, -1.2], "max": [1.2, 1.2, 1.2]}}'
  cli_expect 0 bench "$work/scene/scene.json" --filter direct_vs_tessellated --threads 1 --repeats 1 \
    --resolution 48x48 --json "$work/bench.json"
  python3 - "$work/bench.json" <<'PY' || fail "the isosurface's secondary rays disagree with its tessellation"
import json, sys
scene = json.load(open(sys.argv[1]))["blob_comparison"]["scenes"][0]
cell = scene["tessellated"]["cell_size"]
assert abs(cell - 2.4 / 128) < 1e-9, cell
assert abs(scene["secondary_clearance"] - cell / 2) < 1e-9, scene["secondary_clearance"]
for kind in ("shadow", "bounce"):
    assert scene[kind]["rays"] > 100, (kind, scene[kind]["rays"])
    assert scene[kind]["agreement"] > 0.99, (kind, scene[kind]["agreement"])
PY
}

case_bench_suite() {  # two workloads of the suite on two thread counts, with JSON and the HTML report
  cli_expect 0 bench --quick --resolution 32x18 --threads 1,2 --filter '^cornell_box/(primary|path)$' \
    --json "$work/suite.json" --report "$work/suite.html"
  for text in "cornell_box/primary" "cornell_box/path" "Mrays/s" "Msamples/s" "Thread scaling" "speed-up"; do
    expect_in "$work/stdout" "$text" "bench table"
  done
  ! grep -qF cornell_box/shadow "$work/stdout" || fail "--filter did not leave out cornell_box/shadow"
  python3 - "$work/suite.json" <<'PY' || fail "bench suite JSON is incomplete or wrong"
import json, sys
report = json.load(open(sys.argv[1]))
problems = []
machine = report["machine"]
for key in ("cpu", "cores", "embree_isa", "blob_march_isa", "embree_version", "compiler", "flags", "isotrace_version", "commit"):
    if not machine.get(key): problems.append("machine lacks " + key)
# The commit of the build, not of the last configure (regression: it was recorded when CMake configured).
import subprocess
head = subprocess.run(["git", "rev-parse", "HEAD"], capture_output=True, text=True)
if head.returncode == 0 and machine.get("commit", "").split("-")[0] != head.stdout.strip():
    problems.append("commit %r is not HEAD %s" % (machine.get("commit"), head.stdout.strip()))
if report["isotrace_bench"] != 2: problems.append("format version")
if report["settings"]["threads"] != [1, 2]: problems.append("threads %r" % report["settings"]["threads"])
names = [w["name"] for w in report["workloads"]]
if names != ["cornell_box/primary", "cornell_box/path"]: problems.append("workloads %r" % names)
for w in report["workloads"]:
    if not w["build_seconds"] > 0 or not w["peak_memory_bytes"] > 1 << 20: problems.append(w["name"] + " build/memory")
    if [r["threads"] for r in w["runs"]] != [1, 2]: problems.append(w["name"] + " thread counts")
    for r in w["runs"]:
        t = r["throughput"]
        if len(r["seconds"]) != 1: problems.append(w["name"] + ": --quick is one timed run")
        if not 0 < t["min"] <= t["median"] <= t["max"]: problems.append(w["name"] + " throughput %r" % t)
        if abs(r["efficiency"] - r["speedup"] / r["threads"]) > 1e-9: problems.append(w["name"] + " efficiency")
    if w["runs"][0]["speedup"] != 1: problems.append(w["name"] + " base speed-up")
primary, path = report["workloads"]
if primary["work_per_run"] != 32 * 18: problems.append("primary rays %r" % primary["work_per_run"])
if path["work_per_run"] != 32 * 18 * 1: problems.append("path samples %r" % path["work_per_run"])
if report["scaling"] is not None or report["blob_comparison"] is not None: problems.append("unasked parts")
for p in problems: print("bench:", p, file=sys.stderr)
sys.exit(1 if problems else 0)
PY
  for text in "<!DOCTYPE html>" "<svg" "Thread scaling" "cornell_box/path" "</html>"; do
    expect_in "$work/suite.html" "$text" "bench HTML report"
  done
  cli_expect 0 bench --list
  expect_in "$work/stdout" "blobs/direct_vs_tessellated" "bench --list"
  for name in metacube_dog/mesh_mc metacube_dog/mesh_dc metacube_dog/mesh_sdc blobs_10k/mesh_mc blobs_10k/mesh_dc blobs_10k/mesh_sdc; do
    expect_in "$work/stdout" "$name" "bench --list"
  done
}

case_bench_scaling() {  # the element-count scaling alone (a filter that matches no workload)
  cli_expect 0 bench --scaling --scaling-max 10000 --filter '^$' --repeats 1 --resolution 16x9 --json "$work/scaling.json"
  expect_in "$work/stdout" "Element-count scaling" "bench table"
  python3 - "$work/scaling.json" <<'PY' || fail "bench scaling JSON is incomplete or wrong"
import json, sys
report = json.load(open(sys.argv[1]))
points = report["scaling"]["points"]
problems = []
if [p["elements"] for p in points] != [1000, 10000]: problems.append("counts %r" % [p["elements"] for p in points])
if points[0]["cost_growth"] != 1: problems.append("growth is relative to the smallest count")
for p in points:
    if not (p["rays"] == 16 * 9 and p["ns_per_ray"] > 0 and 10 < p["bytes_per_element"] < 100000):
        problems.append("point %r" % p)
if report["workloads"]: problems.append("workloads ran")
for p in problems: print("bench:", p, file=sys.stderr)
sys.exit(1 if problems else 0)
PY
}

case_bench_bad_input() {  # each with --quick and one workload, so that a wrongly accepted one stays cheap
  cli_expect 2 bench --threads 0 --quick --filter '^cornell_box/primary$'
  expect_in "$work/stderr" "--threads" stderr
  cli_expect 2 bench --threads abc --quick --filter '^cornell_box/primary$'
  expect_in "$work/stderr" "--threads" stderr
  cli_expect 2 bench --filter '(unclosed' --quick
  expect_in "$work/stderr" "not a valid regular expression" stderr
  cli_expect 2 bench --filter 'no_such_workload' --quick
  expect_in "$work/stderr" "matches no workload" stderr
  expect_in "$work/stderr" "cornell_box/primary" stderr
  cli_expect 2 bench --quick --filter '^cornell_box/primary$' --json "$work/missing/b.json"
  expect_in "$work/stderr" "--json" stderr
  cli_expect 2 bench --quick --filter '^cornell_box/primary$' --report "$work/missing/r.html"
  expect_in "$work/stderr" "--report" stderr
  cli_expect 2 bench --quick --filter '^cornell_box/primary$' --report "$work"
  expect_in "$work/stderr" "--report" stderr
  [[ ! -e "$work/missing" ]] || fail "an output directory was created"
  cli_expect 2 bench --repeats 0 --quick --filter '^cornell_box/primary$'
  cli_expect 2 bench --scaling --scaling-max 10 --quick --filter '^cornell_box/primary$'
  expect_in "$work/stderr" "--scaling-max" stderr
  cli_expect 2 bench --resolution 0x5 --quick --filter '^cornell_box/primary$'
  expect_in "$work/stderr" "--resolution" stderr
}

# isotrace benchmark: from a directory without scenes, the suite found beside the program.
benchmark_in_empty_directory() {  # benchmark_in_empty_directory <exit code> <benchmark arguments...>
  local expected=$1
  shift
  mkdir -p "$work/empty"
  (cd "$work/empty" && cli_expect "$expected" benchmark "$@")
}

# Checks a result file against docs/benchmark-result.schema.json; more checks as Python after it, on `result`.
expect_benchmark_json() {  # expect_benchmark_json <result.json> <python statements>
  python3 - "$1" docs/benchmark-result.schema.json "$2" <<'PY' || fail "the benchmark result $1 is wrong"
import json, sys
import jsonschema
result = json.load(open(sys.argv[1]))
jsonschema.validate(result, json.load(open(sys.argv[2])))
exec(sys.argv[3])
PY
}

case_benchmark_short() {  # the short mode from another directory: every workload's output matches the reference
  benchmark_in_empty_directory 0 --short --json "$work/short.json" --report "$work/short.html"
  expect_in "$work/stdout" "short run" stdout
  local name
  for name in blobs_1k blobs_10k blobs_100k metacube_dog superquadric_deform csg_cup showcase dog_mesh; do
    grep -qE "^$name .* ok\$" "$work/stdout" || fail "$name is not validated: $(cat "$work/stdout")"
  done
  ! grep -q "WRONG\|VOID" "$work/stdout" || fail "the short run is not valid"
  expect_benchmark_json "$work/short.json" '
assert result["valid"] and result["mode"] == "short" and not result["problems"], result["problems"]
assert len(result["workloads"]) == 8
for w in result["workloads"]:
    assert w["hash"] == w["reference_hash"], w
    assert all(r["units"] == 1 for r in w["runs"]), w
assert result["system"]["hardware_threads"] >= 1 and result["system"]["caches"], result["system"]
'
  expect_in "$work/short.html" "<svg" "the HTML report"
  expect_in "$work/short.html" "Units per second on 1 thread" "the HTML report"
}

case_benchmark_tampered() {  # a reference hash or a scene changed: the score is void, exit 3, the outputs written
  cp -r "$(dirname "$cli")/../share/isotrace/benchmark/isotrace-bench-1" "$work/suite"
  python3 - "$work/suite/references.json" <<'PY'
import json, sys
references = json.load(open(sys.argv[1]))
references["workloads"]["blobs_1k"]["hash"] = "0123456789abcdef"
json.dump(references, open(sys.argv[1], "w"))
PY
  benchmark_in_empty_directory 3 --short --suite "$work/suite" --workloads blobs_1k --json "$work/void.json"
  expect_in "$work/stdout" "SCORE VOID" stdout
  expect_in "$work/stdout" "0123456789abcdef" stdout
  expect_benchmark_json "$work/void.json" '
assert not result["valid"] and len(result["problems"]) == 1
assert result["scores"][0]["score"] is None
'
  # The reference restored but the scene changed: another image, so another hash.
  cp "$(dirname "$cli")/../share/isotrace/benchmark/isotrace-bench-1/references.json" "$work/suite/"
  sed -i 's/"seed": \([0-9]*\)/"seed": 1\1/' "$work/suite/blobs_1k.json"
  ! cmp -s "$work/suite/blobs_1k.json" "$(dirname "$cli")/../share/isotrace/benchmark/isotrace-bench-1/blobs_1k.json" ||
    fail "the scene was not changed"
  benchmark_in_empty_directory 3 --short --suite "$work/suite" --workloads blobs_1k
  expect_in "$work/stdout" "is not the reference output" stdout
}

case_benchmark_installed() {  # cmake --install puts the suite where the installed program finds it
  cmake --install "$(dirname "$cli")/.." --prefix "$work/prefix" >"$work/install.log" 2>&1 ||
    fail "cmake --install failed: $(tail -5 "$work/install.log")"
  [[ -f "$work/prefix/share/isotrace/benchmark/isotrace-bench-1/references.json" ]] || fail "the suite is not installed"
  mkdir -p "$work/empty"
  (
    cd "$work/empty"
    run "$work/stdout" "$work/stderr" "$work/prefix/bin/isotrace" benchmark --short --workloads blobs_1k
    ((status == 0)) || { show_output; fail "the installed benchmark exited with $status"; }
  )
  grep -qE "^blobs_1k .* ok\$" "$work/stdout" || fail "the installed suite's output is not validated"
}

case_benchmark_bad_input() {  # exit 2 before any work: unknown workloads, bad outputs, a missing or other suite
  cli_expect 2 benchmark --workloads blobs_1k,blob_10k
  expect_in "$work/stderr" 'no workload "blob_10k"' stderr
  expect_in "$work/stderr" "blobs_10k" stderr
  cli_expect 2 benchmark --short --workloads blobs_1k --json "$work/missing/b.json"
  expect_in "$work/stderr" "--json" stderr
  cli_expect 2 benchmark --short --workloads blobs_1k --report "$work"
  expect_in "$work/stderr" "--report" stderr
  local suite
  suite=$(dirname "$cli")/../share/isotrace/benchmark/isotrace-bench-1
  cli_expect 2 benchmark --short --workloads blobs_1k --json "$suite/references.json"
  expect_in "$work/stderr" "--json" stderr
  cli_expect 2 benchmark --short --suite "$work/no_such_folder"
  expect_in "$work/stderr" "--suite" stderr
  cp -r "$suite" "$work/suite"
  sed -i 's/isotrace-bench 1/isotrace-bench 0/' "$work/suite/references.json"
  cli_expect 2 benchmark --short --suite "$work/suite"
  expect_in "$work/stderr" 'references of "isotrace-bench 0"' stderr
  rm "$work/suite/csg_cup.json"
  sed -i 's/isotrace-bench 0/isotrace-bench 1/' "$work/suite/references.json"
  cli_expect 2 benchmark --short --suite "$work/suite" --workloads csg_cup
  expect_in "$work/stderr" "suite folder is incomplete" stderr
  cli_expect 2 benchmark --threads 0
  expect_in "$work/stderr" "--threads" stderr
}

case_benchmark_compare() {  # two results compared; another suite's result or a file of isotrace bench: exit 2
  cli_expect 0 benchmark --short --workloads blobs_1k,dog_mesh --json "$work/a.json" --quiet
  cli_expect 0 benchmark --short --workloads blobs_1k --json "$work/b.json" --quiet
  cli_expect 0 benchmark compare "$work/a.json" "$work/b.json"
  grep -qE '^blobs_1k +threads 1 .*\[' "$work/stdout" || fail "no ratio for blobs_1k: $(cat "$work/stdout")"
  ! grep -q dog_mesh "$work/stdout" || fail "a workload of one result only was compared"
  expect_in "$work/stdout" "overall" stdout
  sed 's/isotrace-bench 1/isotrace-bench 2/' "$work/a.json" >"$work/other.json"
  cli_expect 2 benchmark compare "$work/a.json" "$work/other.json"
  expect_in "$work/stderr" 'a result of "isotrace-bench 2"' stderr
  cli_expect 0 bench --quick --resolution 32x18 --filter '^cornell_box/primary$' --json "$work/bench.json"
  cli_expect 2 benchmark compare "$work/bench.json" "$work/b.json"
  expect_in "$work/stderr" "not a result of isotrace benchmark" stderr
  cli_expect 2 benchmark compare "$work/a.json"
  cli_expect 2 benchmark compare "$work/a.json" "$work/missing.json"
}

case_benchmark_progress_bar() {  # on a terminal: one bar over the whole run, with its ETA and the workload running
  command -v script >/dev/null || fail "script (util-linux) is needed for a terminal"
  script -qec "stty cols 70; '$cli' benchmark --short --workloads blobs_1k,dog_mesh" /dev/null >"$work/tty" ||
    { cat "$work/tty" >&2; fail "benchmark on a terminal failed"; }
  tr '\r' '\n' <"$work/tty" | sed 's/\x1b\[K//g' | grep -a '%.*ETA' >"$work/bar" || fail "no progress bar drawn"
  cat "$work/bar" >&2
  awk 'length($0) > 69 { exit 1 }' "$work/bar" || fail "a progress line is wider than the 70-column terminal"
  grep -q 'blobs_1k on 1 thread' "$work/bar" || fail "the bar does not name the workload running"
  tail -n 1 "$work/bar" | grep -q '100.0%' || fail "the progress bar did not end at 100 %"
  # Drawn after every unit: 2 workloads, 2 thread counts (on a machine with more than one hardware thread).
  (($(wc -l <"$work/bar") >= 2)) || fail "the bar was drawn once only"
}

case_benchmark_report_in_browser() {  # the HTML page as a browser (headless Chromium) parses it: its plots are there
  command -v chromium >/dev/null || fail "chromium (Debian package) is needed to open the HTML report"
  cli_expect 0 benchmark --short --workloads blobs_1k,csg_cup --report "$work/page.html" --quiet
  # No sandbox: tests may run as root, where Chromium's sandbox refuses to start.
  timeout 120 chromium --headless --no-sandbox --disable-gpu --dump-dom "file://$work/page.html" >"$work/dom.html" \
    2>"$work/chromium.log" || { tail -5 "$work/chromium.log" >&2; fail "headless Chromium could not open the report"; }
  python3 - "$work/dom.html" <<'PY' || fail "the report, as the browser parsed it, lacks its plots"
import sys
from html.parser import HTMLParser
class Plots(HTMLParser):
    def __init__(self):
        super().__init__()
        self.svg = self.rect = 0
        self.titles = []
    def handle_starttag(self, tag, attrs):
        if tag == "svg": self.svg += 1
        if tag == "rect": self.rect += 1
    def handle_data(self, data):
        self.titles.append(data)
p = Plots()
p.feed(open(sys.argv[1]).read())
text = " ".join(p.titles)
# One chart per thread count (units per second: a short run has no scores), and the speed-up chart on 2 threads.
assert p.svg >= 2, p.svg
assert p.rect >= 2 * 2, p.rect  # a bar per workload in every chart
assert "Units per second on 1 thread" in text and "blobs_1k" in text and "csg_cup" in text, text[:500]
PY
}

case_benchmark_full() {  # the whole suite as people run it: valid, one score per thread count
  benchmark_in_empty_directory 0 --json "$work/full.json" --report "$work/full.html"
  expect_in "$work/stdout" "Score (1 thread):" stdout
  expect_benchmark_json "$work/full.json" '
assert result["valid"] and result["mode"] == "full"
for w in result["workloads"]:
    for r in w["runs"]:
        assert r["units"] == w["units_per_run"] and r["seconds"] > 0, w
assert all(s["score"] is not None for s in result["scores"]), result["scores"]
'
  expect_in "$work/full.html" "Score on 1 thread" "the HTML report"
}

case_polygonize_obj() {  # "polygonize" is an alias of "mesh": the scene's one implicit object by default
  write_blob_scene "$work/blobs.json"
  cli_expect 0 polygonize "$work/blobs.json" -o "$work/blobs.obj" --depth 5 --threads 1
  expect_in "$work/stdout" "triangles" stdout
  local vertices faces
  vertices=$(grep -c '^v ' "$work/blobs.obj")
  faces=$(grep -c '^f ' "$work/blobs.obj")
  ((vertices > 100 && faces > vertices)) || fail "unexpected OBJ counts: $vertices v, $faces f"
  # The same mesh bytes on two threads.
  cli_expect 0 mesh "$work/blobs.json" -o "$work/blobs2.obj" --depth 5 --threads 2 --quiet
  cmp -s "$work/blobs.obj" "$work/blobs2.obj" || fail "mesh differs between 1 and 2 threads"
  # The mesh loads back as a scene mesh with every triangle.
  python3 - "$work/blobs.json" "$work/mesh.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["objects"][0]["shape"] = {"type": "mesh", "file": "blobs.obj"}
json.dump(scene, open(sys.argv[2], "w"))
PY
  cli_expect 0 info "$work/mesh.json"
  grep -Eq "triangle_mesh +$faces primitive" "$work/stdout" || { show_output; fail "info does not list $faces triangles"; }
  cli_expect 2 polygonize "$work/blobs.json" -o "$work/blobs.stl"
  expect_in "$work/stderr" ".ply" stderr
  # An open mesh has no inside: nothing to polygonise without --object.
  python3 - "$work/blobs.json" "$work/floor.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["objects"][0]["shape"] = {"type": "mesh", "positions": [[-1, 0, -1], [1, 0, -1], [0, 0, 1]], "triangles": [[0, 1, 2]]}
json.dump(scene, open(sys.argv[2], "w"))
PY
  cli_expect 2 polygonize "$work/floor.json" -o "$work/floor.obj"
  expect_in "$work/stderr" "no object with an implicit surface" stderr
  expect_no_partial_files "$work"
}

case_mesh_threads_every_method() {  # a generated blob cloud: each method writes the same PLY bytes on 1 and 2 threads
  cat >"$work/cloud.json" <<'JSON'
{
  "isotrace": 1,
  "film": { "resolution": [24, 16], "spp": 1 },
  "camera": { "type": "perspective", "fov": 40, "look_at": { "eye": [0, 0, -6], "target": [0, 0, 0], "up": [0, 1, 0] } },
  "materials": { "grey": { "type": "diffuse" } },
  "objects": [ { "name": "cloud", "material": "grey", "shape": { "type": "blobs", "field": "kim", "threshold": 0.5,
    "generate": { "count": 300, "seed": 4, "min": [-1, -1, -1], "max": [1, 1, 1], "radius": [0.15, 0.3], "weight": [0.8, 1.2] } } } ]
}
JSON
  local method
  for method in mc dc sdc; do
    cli_expect 0 mesh "$work/cloud.json" --method "$method" --depth 6 --threads 1 -q -o "$work/one_$method.ply"
    cli_expect 0 mesh "$work/cloud.json" --method "$method" --depth 6 --threads 2 -q -o "$work/two_$method.ply"
    cmp -s "$work/one_$method.ply" "$work/two_$method.ply" || fail "$method: the mesh differs between 1 and 2 threads"
  done
}

case_mesh_simplify() {  # octree simplification by QEF error: fewer vertices; bad tolerances and methods exit 2
  write_blob_scene "$work/blobs.json"
  cli_expect 0 mesh "$work/blobs.json" -o "$work/full.obj" --depth 5
  cli_expect 0 mesh "$work/blobs.json" -o "$work/simple.obj" --depth 5 --simplify 0.05
  expect_in "$work/stdout" "simplified to tolerance 0.05" stdout
  local full simple
  full=$(grep -c '^v ' "$work/full.obj")
  simple=$(grep -c '^v ' "$work/simple.obj")
  ((simple < full)) || fail "--simplify 0.05 kept $simple of $full vertices"
  for bad in -1 nan inf abc; do
    cli_expect 2 mesh "$work/blobs.json" -o "$work/bad.obj" --depth 5 --simplify "$bad"
    expect_in "$work/stderr" "--simplify" stderr
  done
  cli_expect 2 mesh "$work/blobs.json" -o "$work/bad.obj" --depth 5 --method sdc --simplify 0.01
  expect_in "$work/stderr" "only dual contouring" stderr
  expect_no_file "$work/bad.obj"
}

# Two equal Kim metaballs whose surfaces touch at the centre of their bounds, a saddle of the field where the
# gradient is 0: the default origin of the spherical octree.
write_touching_blobs_scene() {  # write_touching_blobs_scene <path>
  cat >"$1" <<'JSON'
{
  "isotrace": 1,
  "film": { "resolution": [24, 16], "spp": 1 },
  "camera": { "type": "perspective", "fov": 40, "look_at": { "eye": [0, 0, -6], "target": [0, 0, 0], "up": [0, 1, 0] } },
  "materials": { "grey": { "type": "diffuse" } },
  "objects": [ { "material": "grey", "shape": { "type": "blobs", "field": "kim", "threshold": 0.5, "elements": [
    { "center": [-1.2166174009154453, 0, 0], "radius": 2 }, { "center": [1.2166174009154453, 0, 0], "radius": 2 } ] } } ]
}
JSON
}

case_mesh_touching_blobs() {  # the origin leaves the saddle: closed meshes, or exit 2 with the reason and no file
  write_touching_blobs_scene "$work/touch.json"
  for depth in 4 5 6; do
    cli_expect 0 mesh "$work/touch.json" --method sdc --depth "$depth" -q -o "$work/touch$depth.obj"
    python3 "$closed_mesh" "$work/touch$depth.obj" 0 || fail "sdc depth $depth: the mesh is not closed"
  done
  # An origin on a sheet of no thickness has nowhere to go: exit 2, no file.
  python3 - "$work/touch.json" "$work/sheet.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["objects"][0]["shape"] = {"type": "isosurface", "function": "max(abs(z), abs(x) - 1, abs(y) - 1)",
                                "contained_by": {"box": {"min": [-1.5, -1.5, -0.5], "max": [1.5, 1.5, 0.5]}}}
json.dump(scene, open(sys.argv[2], "w"))
PY
  cli_expect 2 mesh "$work/sheet.json" --method sdc --depth 4 -q -o "$work/bad.obj"
  expect_in "$work/stderr" "--origin: (0, 0, 0) could not be moved clear of the surface" stderr
  expect_no_file "$work/bad.obj"
  # Uncorrected, the holes are written with a warning, even when quiet.
  cli_expect 0 mesh "$work/touch.json" --method sdc --depth 5 --no-origin-correction -q -o "$work/holes.obj"
  expect_in "$work/stderr" "warning: the mesh has 104 boundary" stderr
}

case_mesh_method_options() {  # spherical settings for mc/dc and NaN origins exit 2, naming the option
  write_blob_scene "$work/blobs.json"
  for method in mc dc; do
    cli_expect 2 mesh "$work/blobs.json" --method "$method" --origin 0,0,0 -o "$work/bad.obj"
    expect_in "$work/stderr" "--origin: an origin applies only to spherical-octree dual contouring (sdc)" stderr
    cli_expect 2 mesh "$work/blobs.json" --method "$method" --pole-cap normal -o "$work/bad.obj"
    expect_in "$work/stderr" "--pole-cap: the pole cap applies only to spherical-octree dual contouring" stderr
    cli_expect 2 mesh "$work/blobs.json" --method "$method" --no-origin-correction -o "$work/bad.obj"
    expect_in "$work/stderr" "--no-origin-correction: origin correction applies only" stderr
  done
  cli_expect 2 mesh "$work/blobs.json" --method sdc --origin nan,0,0 -o "$work/bad.obj"
  expect_in "$work/stderr" "--origin: (nan, 0, 0) has a coordinate that is NaN (not a number)" stderr
  expect_no_file "$work/bad.obj"
}

case_deform_help() {
  cli_expect 0 deform --help
  for option in --output --quiet mesh deformers; do
    expect_in "$work/stdout" "$option" "deform --help output"
  done
}

case_deform_mesh() {  # the bunny's ear bent by its sweep, as PLY and OBJ; statistics on stderr
  cli_expect 0 deform scenes/data/bunny.obj scenes/sweeps/bunny_ear_bend.json -o "$work/bent.ply"
  expect_in "$work/stderr" "13934 vertices" stderr
  expect_in "$work/stderr" "unbound" stderr
  expect_in "$work/stderr" "wrote $work/bent.ply" stderr
  head -c 200 "$work/bent.ply" | grep -q "element vertex 13934" || fail "PLY header lacks the vertex count"
  # A sweep too thin for the ear: deform says so and suggests a radius scale.
  sed -e 's/"measured_radius_scale": 2/"measured_radius_scale": 1.3/' -e 's/"weight_curve": \[1, 1, 1, 1, 0\]/"weight_curve": [1, 1, 1, 0.5, 0]/' \
    -e 's/"radius": 0.025/"radius": 0.012/' scenes/sweeps/bunny_ear_bend.json >"$work/thin.json"
  cli_expect 0 deform scenes/data/bunny.obj "$work/thin.json" -o "$work/thin.ply"
  expect_in "$work/stderr" "10 edges leave the sweep through its surface from moved vertices (out to 1.01 × its radius: measured_radius_scale 1.45 would enclose them)" stderr
  cli_expect 0 deform scenes/data/teapot.bpt scenes/sweeps/teapot_pull.json -o "$work/teapot.obj" --quiet
  [[ ! -s "$work/stderr" ]] || { show_output; fail "--quiet printed something"; }
  (($(grep -c '^v ' "$work/teapot.obj") > 1000)) || fail "too few vertices in the OBJ"
  # The deformed mesh loads back as a scene mesh.
  cat >"$work/scene.json" <<JSON
{"isotrace": 1, "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 1], "target": [0, 0, 0]}},
 "materials": {"m": {"type": "diffuse"}}, "objects": [{"material": "m", "shape": {"type": "mesh", "file": "bent.ply"}}]}
JSON
  cli_expect 0 info "$work/scene.json"
}

case_deform_bad_input() {
  cli_expect 2 deform scenes/data/bunny.obj scenes/sweeps/bunny_ear_bend.json -o "$work/bent.stl"
  expect_in "$work/stderr" "must end in .ply or .obj" stderr
  expect_no_file "$work/bent.stl"
  cat >"$work/bad_radius.json" <<'JSON'
{"deformers": [{"type": "sweep", "key_sections": [{"center": [0, 0, 0], "radius": 0.1}, {"center": [0, 0, 1], "radius": -1}]}]}
JSON
  cli_expect 2 deform scenes/data/bunny.obj "$work/bad_radius.json" -o "$work/out.ply"
  expect_in "$work/stderr" "bad_radius.json:1:121: deformers[0].key_sections[1].radius: value -1 out of range: must be > 0" stderr
  expect_no_file "$work/out.ply"
  cat >"$work/bad_quaternion.json" <<'JSON'
{"deformers": [{"type": "sweep", "key_sections": [{"center": [0, 0, 0], "radius": 0.1, "orientation": [2, 0, 0, 0]},
                                                {"center": [0, 0, 1], "radius": 0.1}]}]}
JSON
  cli_expect 2 deform scenes/data/bunny.obj "$work/bad_quaternion.json" -o "$work/out.ply"
  expect_in "$work/stderr" "key_sections[0].orientation: not a unit quaternion (|q| = 2)" stderr
  cat >"$work/one_key.json" <<'JSON'
{"deformers": [{"type": "sweep", "key_sections": [{"center": [0, 0, 0], "radius": 0.1}]}]}
JSON
  cli_expect 2 deform scenes/data/bunny.obj "$work/one_key.json" -o "$work/out.ply"
  expect_in "$work/stderr" "a sweep needs at least 2 key_sections, got 1" stderr
  cat >"$work/reversed.json" <<'JSON'
{"deformers": [{"type": "sweep", "key_sections": [{"center": [0, 0, 0], "radius": 0.1}, {"center": [0, 0, 1], "radius": 0.1, "normal": [0, 0.2, -1]}]}]}
JSON
  cli_expect 2 deform scenes/data/bunny.obj "$work/reversed.json" -o "$work/out.ply"
  expect_in "$work/stderr" "key_sections[1].normal: points against key section 0's normal" stderr
  expect_no_file "$work/out.ply"
  cat >"$work/bad_weight.json" <<'JSON'
{"deformers": [{"type": "sweep", "weight_curve": [1, 1.5, 0],
  "key_sections": [{"center": [0, 0, 0], "radius": 0.1}, {"center": [0, 0, 1], "radius": 0.1}]}]}
JSON
  cli_expect 2 deform scenes/data/bunny.obj "$work/bad_weight.json" -o "$work/out.ply"
  expect_in "$work/stderr" "weight_curve: weight_curve[1]: control value 1.5 is outside [0, 1]" stderr
  cat >"$work/huge.json" <<'JSON'
{"deformers": [{"type": "sweep", "mode": "global",
  "key_sections": [{"center": [-0.03, 0.1, -0.07], "radius": 0.1}, {"center": [-0.03, 0.1, 0.07], "radius": 0.1}],
  "edits": [{"key": 1, "scale_radii": 1e300}]}]}
JSON
  cli_expect 2 deform scenes/data/bunny.obj "$work/huge.json" -o "$work/out.ply"
  expect_in "$work/stderr" "deformers[0]: the deformation moved a vertex to a non-finite position" stderr
  # A pull whose target cannot be reached within the iteration cap reports its residual.
  python3 - scenes/sweeps/teapot_pull.json "$work/stuck.json" <<'PY'
import json, sys
spec = json.load(open(sys.argv[1]))
spec["deformers"][0]["max_iterations"] = 1
spec["deformers"][0]["edits"] = [{"sweep": "handle", "key": 2, "pull": [0, 0, 3]}]
json.dump(spec, open(sys.argv[2], "w"))
PY
  cli_expect 2 deform scenes/data/teapot.bpt "$work/stuck.json" -o "$work/out.ply"
  expect_in "$work/stderr" "edits[0]: pull: backward deformation did not converge: residual" stderr
  expect_in "$work/stderr" "(max_iterations 1)" stderr
  expect_no_file "$work/out.ply"
}

# Every shipped sweep figure deforms its mesh without turning a face over or stretching an edge past 2.5x, and
# deform prints the check.
case_deform_sweep_figures_quality() {
  local spec mesh
  for spec in scenes/sweeps/*.json; do
    case $spec in *teapot*) mesh=scenes/data/teapot.bpt ;; *) mesh=scenes/data/bunny.obj ;; esac
    cli_expect 0 deform "$mesh" "$spec" -o "$work/out.ply"
    expect_in "$work/stderr" "mesh quality: 0 flipped faces, max edge stretch" "stderr of $spec"
    # Where the teapot's parts meet, no edge between two sweeps (nor any other) grows beyond 2x.
    [[ $spec != *teapot* ]] || expect_in "$work/stderr" "(0 edges > 2×)" "stderr of $spec"
    awk -v spec="$spec" '/mesh quality:/ { for (i = 1; i <= NF; ++i) if ($i == "stretch") { s = $(i + 1); sub("×", "", s); found = 1
        if (s + 0 > 2.5) { print spec ": edge stretch " s "x > 2.5x"; exit 1 } } } END { if (!found) exit 1 }' \
      "$work/stderr" || { show_output; fail "$spec stretches an edge too far"; }
  done
  expect_in "$work/stderr" "volume ratios to the parent, now over before: spout 1 handle 1" "teapot_volume's stderr"
  # Rule 3 from a child: widening the spout widens the body and, through it, the handle.
  python3 - scenes/sweeps/teapot_volume.json "$work/child.json" <<'PY'
import json, sys
spec = json.load(open(sys.argv[1]))
spec["deformers"][0]["edits"] = [{"sweep": "spout", "key": 0, "scale_radii": 1.4}]
json.dump(spec, open(sys.argv[2], "w"))
PY
  cli_expect 0 deform scenes/data/teapot.bpt "$work/child.json" -o "$work/out.ply"
  expect_in "$work/stderr" "volume ratios to the parent, now over before: spout 1 handle 1" stderr
  expect_in "$work/stderr" "mesh quality: 0 flipped faces" stderr
}

# Pulls the parent cannot follow without folding or stretching beyond its reach are refused with the residual and
# the reason, and nothing is written.
case_deform_pull_out_of_reach() {
  local pull
  for pull in "[0, 0, 1000]" "[0, 0, 3.2]"; do
    python3 - scenes/sweeps/teapot_pull.json "$work/far.json" "$pull" <<'PY'
import json, sys
spec = json.load(open(sys.argv[1]))
spec["deformers"][0]["edits"][0]["pull"] = json.loads(sys.argv[3])
json.dump(spec, open(sys.argv[2], "w"))
PY
    cli_expect 2 deform scenes/data/teapot.bpt "$work/far.json" -o "$work/out.ply"
    [[ $pull != "[0, 0, 1000]" ]] || expect_in "$work/stderr" "pull: the target is out of reach: residual 998" stderr
    expect_in "$work/stderr" "edits[0]: pull: " stderr
    expect_in "$work/stderr" "the body sweep would stretch or shrink more than 2×" stderr
    expect_no_file "$work/out.ply"
  done
  expect_in "$work/stderr" "did not converge: residual 2.0" stderr  # 3.2 units: creeping along the limit
}

# Explicit vertex groups of a hierarchy: a box or an index list puts vertices in a sweep; groups that name missing
# vertices, overlap or select nothing are errors at their field.
case_deform_vertex_groups() {
  group() {  # group <output> <python statements editing the sweeps list "s">
    python3 - scenes/sweeps/teapot_body_edit.json "$1" "$2" <<'PY'
import json, sys
spec = json.load(open(sys.argv[1]))
s = spec["deformers"][0]["sweeps"]
exec(sys.argv[3])
json.dump(spec, open(sys.argv[2], "w"), indent=1)
PY
  }
  cli_expect 0 deform scenes/data/teapot.bpt scenes/sweeps/teapot_body_edit.json -o "$work/out.ply"
  expect_in "$work/stderr" "5190 on body, 1056 on spout, 1050 on handle" stderr
  # Everything beyond x = 1.6 (the spout and a band of the body) named for the spout; what the spout does not bind
  # (behind its first section) stays.
  group "$work/box.json" 's[1]["select"] = {"min": [1.6, -5, -5], "max": [5, 5, 5]}'
  cli_expect 0 deform scenes/data/teapot.bpt "$work/box.json" -o "$work/out.ply"
  expect_in "$work/stderr" "4937 on body, 1287 on spout, 1050 on handle, 22 unbound" stderr
  rm "$work/out.ply"
  bad_group() {  # bad_group <python statements> <expected message>
    group "$work/bad.json" "$1"
    cli_expect 2 deform scenes/data/teapot.bpt "$work/bad.json" -o "$work/out.ply"
    expect_in "$work/stderr" "$2" stderr
    expect_no_file "$work/out.ply"
  }
  bad_group 's[2]["vertices"] = [0, 7296]' "sweeps[2].vertices[1]: vertex 7296 does not exist (the mesh has 7296 vertices)"
  bad_group 's[1]["vertices"] = [5]; s[2]["vertices"] = [4, 5]' "sweeps[2].vertices[1]: vertex 5 is also in the group of sweep \"spout\""
  bad_group 's[1]["select"] = {"min": [10, 10, 10], "max": [11, 11, 11]}' "sweeps[1].select: the box selects no vertex of the mesh"
  bad_group 's[1]["select"] = {"min": [1, 0, 0], "max": [0, 1, 1]}' "sweeps[1].select: \"min\" must not exceed \"max\" on any axis"
  bad_group 's[1]["vertices"] = [1.5]' "sweeps[1].vertices[0]: a vertex index must be a whole number"
  bad_group 's[1]["vertices"] = []' "sweeps[1].vertices: the list names no vertex"
}

# Attribute-based patches: the closed gem of scenes/abm_models.json exported by isotrace mesh is watertight (every
# edge, keyed by its end positions, is used once in each direction) and carries a normal per vertex.
case_abm_patch_mesh() {
  cli_expect 0 mesh scenes/abm_models.json --object gem --method traced -o "$work/gem.obj"
  expect_in "$work/stdout" "gem: traced as triangles" stdout
  python3 - "$work/gem.obj" <<'PY' || fail "the exported gem is not watertight"
import sys
from collections import Counter
positions, normals, edges = [], 0, Counter()
for line in open(sys.argv[1]):
    f = line.split()
    if not f: continue
    if f[0] == "v": positions.append(tuple(f[1:4]))
    elif f[0] == "vn": normals += 1
    elif f[0] == "f":
        corners = [positions[int(c.split("/")[0]) - 1] for c in f[1:]]
        if len(set(corners)) < 3: continue  # a zero-area sliver
        for k in range(3): edges[(corners[k], corners[(k + 1) % 3])] += 1
bad = [e for e, n in edges.items() if n != 1 or edges.get((e[1], e[0])) != 1]
print(len(positions), "vertices,", normals, "normals,", len(edges), "directed edges,", len(bad), "open or repeated")
sys.exit(0 if positions and normals == len(positions) and not bad else 1)
PY
  cli_expect 0 mesh scenes/abm_models.json --object rounded_corner --method traced -o "$work/corner.ply" --quiet
  [[ -s "$work/corner.ply" ]] || fail "no PLY written"
  cli_expect 2 mesh scenes/abm_models.json --object rounded_corner -o "$work/open.ply"  # open: no implicit field
  expect_in "$work/stderr" "it has no inside" stderr
  cli_expect 2 mesh scenes/abm_models.json --object floor --method traced -o "$work/floor.ply"
  expect_in "$work/stderr" "not traced as triangles" stderr
  expect_no_file "$work/floor.ply"
}

# The gem with every curve written out inline in each patch that uses it (no names): the copies are found by their
# geometry and welded, so the mesh stays watertight; one copy moved by 1e-4 is refused with its place.
case_abm_patch_inline_curves() {
  python3 - scenes/abm_models.json "$work/inline.json" "$work/near.json" <<'PY'
import copy, json, sys
scene = json.load(open(sys.argv[1]))
gem = next(o for o in scene["objects"] if o["name"] == "gem")
curves = gem["shape"].pop("curves")
def inline(item):
    if isinstance(item, str): return copy.deepcopy(curves[item])
    curve = copy.deepcopy(curves[item["curve"]])
    if item.get("reversed"): curve["points"] = curve["points"][::-1]
    return curve
for patch in gem["shape"]["patches"]: patch["boundary"] = [inline(c) for c in patch["boundary"]]
scene["objects"] = [gem]
scene["lights"] = [{"type": "directional", "direction": [0, -1, 0], "irradiance": 1}]
json.dump(scene, open(sys.argv[2], "w"), indent=1)
gem["shape"]["patches"][1]["boundary"][0]["points"][1][1] += 1e-4
json.dump(scene, open(sys.argv[3], "w"), indent=1)
PY
  cli_expect 0 mesh "$work/inline.json" --object gem --method traced -o "$work/inline.obj" --quiet
  python3 - "$work/inline.obj" <<'PY' || fail "the gem of inline curves has a crack"
import sys
from collections import Counter
positions, edges = [], Counter()
for line in open(sys.argv[1]):
    f = line.split()
    if f and f[0] == "v": positions.append(tuple(f[1:4]))
    elif f and f[0] == "f":
        corners = [positions[int(c.split("/")[0]) - 1] for c in f[1:]]
        if len(set(corners)) == 3:
            for k in range(3): edges[(corners[k], corners[(k + 1) % 3])] += 1
open_edges = [e for e, n in edges.items() if n != 1 or edges.get((e[1], e[0])) != 1]
print(len(open_edges), "open edges")
sys.exit(1 if open_edges else 0)
PY
  cli_expect 2 mesh "$work/near.json" --object gem --method traced -o "$work/near.obj" --quiet
  expect_in "$work/stderr" "objects[0].shape.patches[1].boundary[0]: curve 0 of patch 1 nearly coincides with curve 0 of patch 0: they differ by up to 5e-05" stderr
  expect_no_file "$work/near.obj"
}

# Smooth joins: the gem and the rounded corner of scenes/abm_smooth_joins.json, exported by isotrace mesh. At every
# position on a shared curve (carried by a vertex of each of the two patches) the creased versions' normals jump by
# tens of degrees, the smooth versions' by at most 1°. p = 1 with smooth joins is refused at the patch's p.
case_abm_patch_smooth_joins() {
  local object
  for object in gem_crease gem_smooth rounded_corner_crease rounded_corner_smooth; do
    cli_expect 0 mesh scenes/abm_smooth_joins.json --object "$object" --method traced -o "$work/$object.obj" --quiet
  done
  python3 - "$work" <<'PY' || fail "normals across shared curves"
import math, statistics, sys
from collections import defaultdict
def jumps(path):
    positions, normals = [], []
    for line in open(path):
        f = line.split()
        if f and f[0] == "v": positions.append(tuple(f[1:4]))
        elif f and f[0] == "vn": normals.append([float(x) for x in f[1:4]])
    copies = defaultdict(list)
    for i, p in enumerate(positions): copies[p].append(i)
    result = []
    for ids in copies.values():
        if len(ids) != 2: continue
        a, b = normals[ids[0]], normals[ids[1]]
        cosine = sum(x * y for x, y in zip(a, b)) / math.sqrt(sum(x * x for x in a) * sum(y * y for y in b))
        result.append(math.degrees(math.acos(max(-1.0, min(1.0, cosine)))))
    return result
ok = True
for model, creased_median in (("gem", 90), ("rounded_corner", 30)):
    creased, smooth = jumps(f"{sys.argv[1]}/{model}_crease.obj"), jumps(f"{sys.argv[1]}/{model}_smooth.obj")
    print(model, "creased: median %.1f max %.1f; smooth: median %.4f max %.4f degrees (%d vertices)"
          % (statistics.median(creased), max(creased), statistics.median(smooth), max(smooth), len(smooth)))
    ok = ok and len(smooth) > 100 and statistics.median(creased) > creased_median and max(smooth) <= 1
sys.exit(0 if ok else 1)
PY
  cli_expect 2 info scenes/abm_smooth_joins.json --set 'objects.gem_smooth.shape.patches.3.p=1'
  expect_in "$work/stderr" "objects[3].shape.patches[3].p: smooth joins need p > 1" stderr
}

# Bad patches: exit 2 with file:line:column, the JSON path and what is wrong; nothing written.
case_abm_patch_bad_input() {
  local dir="$work/scene" e0='{"points": [[0,0,0],[1,0,0]]}' e1='{"points": [[1,0,0],[0,1,0]]}' e2='{"points": [[0,1,0],[0,0,0]]}'
  write_shape_scene "$dir" '        "type": "abm_patch",' '        "boundary": ['"$e0, $e1"', {"points": [[0,1,0],[0,0,0.5]]}]'
  check_bad_scene "$dir" 12 "objects[0].shape.boundary" "curve 2 ends at (0, 0, 0.5) but curve 0 starts at (0, 0, 0), a gap of 0.5"
  write_shape_scene "$dir" '        "type": "abm_patch",' '        "boundary": ['"$e0"', {"points": [[1,0,0],[1,0,0]]}, '"$e1, $e2"']'
  check_bad_scene "$dir" 12 "objects[0].shape.boundary" "curve 1 is degenerate"
  write_shape_scene "$dir" '        "type": "abm_patch",' '        "boundary": ['"$e0, $e1"']'
  check_bad_scene "$dir" 12 "objects[0].shape.boundary" "a patch needs 3 to 8 boundary curves, got 2"
  write_shape_scene "$dir" '        "type": "abm_patch",' '        "boundary": ['"$e0, $e0, $e0, $e0, $e0, $e0, $e0, $e0, $e0"']'
  check_bad_scene "$dir" 12 "objects[0].shape.boundary" "a patch needs 3 to 8 boundary curves, got 9"
  write_shape_scene "$dir" '        "type": "abm_patch",' '        "boundary": ['"$e0, $e1"', {"points": [[0,1,0],[NaN,0,0]]}]'
  check_bad_scene "$dir" 12 "" ""
  write_shape_scene "$dir" '        "type": "abm_patch",' '        "boundary": ['"$e0, $e1"', {"points": [[0,1,0],[1e999,0,0]]}]'
  check_bad_scene "$dir" 12 "" "number out of range"
  for p in 0 -1 0.5; do
    write_shape_scene "$dir" '        "type": "abm_patch", "p": '"$p"',' '        "boundary": ['"$e0, $e1, $e2"']'
    check_bad_scene "$dir" 11 "objects[0].shape.p" "value $p out of range: must be in [1, 8]"
  done
  # A bow-tie: the loop runs (0,0) → (1,1) → (1,0) → (0,1) and crosses itself.
  write_shape_scene "$dir" '        "type": "abm_patch",' '        "boundary": [{"points": [[0,0,0],[1,1,0]]}, {"points": [[1,1,0],[1,0,0]]}, {"points": [[1,0,0],[0,1,0]]}, {"points": [[0,1,0],[0,0,0]]}]'
  check_bad_scene "$dir" 12 "objects[0].shape.boundary" "the boundary loop crosses itself: curve 0 crosses curve 2"
  write_shape_scene "$dir" '        "type": "abm_patch",' '        "boundary": ['"$e0, $e1"', {"curve": "nope"}]'
  check_bad_scene "$dir" 12 "objects[0].shape.boundary[2]" 'no curve named "nope"'
  # 3 × 2048 × 4095 triangles need about 4.5 GB: refused under a 1 GB limit before anything is built.
  write_shape_scene "$dir" '        "type": "abm_patch", "segments": 2048,' '        "boundary": ['"$e0, $e1, $e2"']'
  cli_expect 2 render "$dir/scene.json" --max-memory 1G -o "$dir/out.exr" --quiet
  expect_in "$work/stderr" "scene.json:10:" stderr
  expect_in "$work/stderr" "objects[0].shape: " stderr
  expect_in "$work/stderr" "a tessellation of 25159680 triangles" stderr
  expect_no_file "$dir/out.exr"
}

# ---- isotrace diff ----------------------------------------------------------------------------------------

case_instances() {  # placements of one definition give the pixels of the same objects written out one by one
  local head='"isotrace": 1, "film": {"resolution": [32, 24], "spp": 2},
  "camera": {"type": "perspective", "fov": 50, "look_at": {"eye": [0, 1, 9], "target": [0, 0, 0]}},
  "materials": {"grey": {"type": "diffuse"}, "red": {"type": "diffuse", "reflectance": [0.8, 0.1, 0.1]}},
  "lights": [{"type": "point", "position": [2, 5, 6], "intensity": 40}]'
  local ball='{"type": "sphere", "radius": 1}'
  local squash='{"translate": [-2, 0, 0], "scale": [1, 0.6, 1]}' stretch='{"translate": [2, 0, 0], "scale": [0.5, 1.4, 1]}'
  cat >"$work/instanced.json" <<JSON
{ $head,
  "definitions": {"ball": {"material": "grey", "shape": $ball}},
  "objects": [{"name": "balls", "instance": "ball",
               "placements": [{"transform": $squash}, {"transform": $stretch, "material": "red"}]}] }
JSON
  cat >"$work/separate.json" <<JSON
{ $head,
  "objects": [{"name": "balls[0]", "material": "grey", "transform": $squash, "shape": $ball},
              {"name": "balls[1]", "material": "red", "transform": $stretch, "shape": $ball}] }
JSON
  cli_expect 0 render "$work/instanced.json" -o "$work/instanced.exr" --aov object_id --quiet --stats-json "$work/stats.json"
  expect_in "$work/stats.json" '"placements": 2' stats.json
  expect_in "$work/stats.json" '"placed_shapes": 1' stats.json
  cli_expect 0 render "$work/separate.json" -o "$work/separate.exr" --aov object_id --quiet
  idiff -fail 0 -warn 0 "$work/instanced.exr" "$work/separate.exr" >"$work/idiff.txt" ||
    { cat "$work/idiff.txt" >&2; fail "the instanced render differs from the separate objects"; }
  cli_expect 0 info "$work/instanced.json"
  expect_in "$work/stdout" "2 placement(s) of 1 shape(s)" stdout
  # an unknown definition: exit 2 at its position, with a suggestion
  sed 's/"instance": "ball"/"instance": "bal"/' "$work/instanced.json" >"$work/bad.json"
  cli_expect 2 render "$work/bad.json" -o "$work/bad.exr" --quiet
  expect_in "$work/stderr" "bad.json:6:" stderr
  expect_in "$work/stderr" 'objects[0].instance: unknown definition "bal" (did you mean "ball"?)' stderr
  expect_no_file "$work/bad.exr"
}

case_diff_help() {
  cli_expect 0 diff --help
  for option in --json --error-map --error-map-metric --fail --ztest --test-spp --ppd; do
    expect_in "$work/stdout" "$option" "diff --help"
  done
}

case_diff_identical() {  # an image against itself: 0 for every error, inf dB, SSIM 1; EXR (HDR-FLIP) and PNG (LDR)
  render_small -o "$work/a.exr" -o "$work/a.png"
  for image in a.exr a.png; do
    cli_expect 0 diff "$work/$image" "$work/$image" --json "$work/same.json" \
      --fail rmse=0 --fail relmse=0 --fail flip=0 --fail ssim=1 --fail psnr=1e300
    expect_in "$work/stdout" "rmse    0" stdout
    expect_in "$work/stdout" "relmse  0" stdout
    expect_in "$work/stdout" "psnr    inf dB" stdout
    expect_in "$work/stdout" "ssim    1 " stdout
    expect_in "$work/stdout" "flip    0 " stdout
    expect_in "$work/same.json" '"psnr": "inf"' same.json
  done
  expect_in "$work/stdout" "LDR-FLIP" stdout
}

case_diff_renders() {  # two renders at different spp differ; thresholds gate with exit 3; an error map is written
  render_small -o "$work/a.exr" --seed 1
  cli_expect 0 render "$cornell" --res 64x64 --spp 32 --seed 2 --quiet -o "$work/b.exr"
  cli_expect 0 diff "$work/b.exr" "$work/a.exr" --json "$work/d.json" --error-map "$work/map.png"
  expect_in "$work/stdout" "HDR-FLIP" stdout
  for metric in rmse relmse flip; do
    value=$(sed -n "s/^$metric *\([0-9.e+-]*\).*/\1/p" "$work/stdout")
    awk -v v="$value" 'BEGIN { exit !(v > 0) }' || fail "$metric is $value, expected > 0"
  done
  [[ $(iinfo "$work/map.png") == *"64 x   64, 3 channel, uint8 png"* ]] || fail "error map: $(iinfo "$work/map.png")"
  expect_in "$work/d.json" '"mode": "hdr"' d.json
  cli_expect 3 diff "$work/b.exr" "$work/a.exr" --fail flip=0.001
  expect_in "$work/stderr" "threshold broken: flip" stderr
  cli_expect 3 diff "$work/b.exr" "$work/a.exr" --fail psnr=200
  expect_in "$work/stderr" "threshold broken: psnr" stderr
  cli_expect 0 diff "$work/b.exr" "$work/a.exr" --fail flip=0.99 --fail psnr=1 --error-map "$work/ssim.png" \
    --error-map-metric ssim
  expect_in "$work/stderr" "1 - per-pixel SSIM" stderr
}

case_diff_bad_input() {  # exit 2, a clear message, no output written
  render_small -o "$work/a.exr" -o "$work/a.png"
  cli_expect 0 render "$cornell" --res 32x32 --spp 4 --quiet -o "$work/small.exr"
  cli_expect 0 render "$cornell" --res 64x64 --spp 4 --quiet --aov depth -o "$work/depth.exr"
  echo "not an image" >"$work/text.png"
  cli_expect 2 diff "$work/a.exr" "$work/missing.exr" --json "$work/out.json"
  expect_in "$work/stderr" "missing.exr: file not found" stderr
  cli_expect 2 diff "$work/text.png" "$work/a.png"
  expect_in "$work/stderr" "text.png: cannot read image" stderr
  cli_expect 2 diff "$work/a.exr" "$work/small.exr"
  expect_in "$work/stderr" "different size" stderr
  cli_expect 2 diff "$work/a.exr" "$work/depth.exr"
  expect_in "$work/stderr" "only in $work/depth.exr: Z" stderr
  cli_expect 2 diff "$work/a.exr" "$work/a.png"
  expect_in "$work/stderr" "display-referred" stderr
  cli_expect 2 diff "$work/a.exr" "$work/a.exr" --fail flp=0.1
  expect_in "$work/stderr" 'unknown metric "flp" (did you mean "flip"?)' stderr
  cli_expect 2 diff "$work/a.exr" "$work/a.exr" --fail flip=abc
  expect_in "$work/stderr" "must be a finite number" stderr
  cli_expect 2 diff "$work/a.exr" "$work/a.exr" --fail flip
  expect_in "$work/stderr" "METRIC=VALUE" stderr
  cli_expect 2 diff "$work/a.exr" "$work/a.exr" --error-map-metric bogus --error-map "$work/map.png"
  cli_expect 2 diff "$work/a.exr" "$work/a.exr" --error-map "$work/map.jpg"
  cli_expect 2 diff --ztest "$work/a.exr" "$work/a.exr"
  expect_in "$work/stderr" "--aov variance,sample_count" stderr
  expect_no_file "$work/out.json"
  expect_no_file "$work/map.png"
}

write_two_balls_scene() {  # write_two_balls_scene <path> <left ball reflectance>
  cat >"$1" <<JSON
{"isotrace": 1, "colour": {"working_space": "lin_rec709"},
  "film": {"resolution": [32, 16], "filter": {"type": "box"}},
  "camera": {"type": "perspective", "fov": 40, "look_at": {"eye": [0, 0, 7], "target": [0, 0, 0]}},
  "sampler": {"type": "independent"},
  "integrator": {"type": "path", "max_depth": 4},
  "materials": {"ball": {"type": "diffuse", "reflectance": $2}, "other": {"type": "diffuse", "reflectance": 0.8}},
  "lights": [{"type": "point", "position": [0, 4, 6], "intensity": 250}],
  "objects": [{"material": "ball", "shape": {"type": "sphere", "radius": 1}, "transform": {"translate": [-1.1, 0, 0]}},
              {"material": "other", "shape": {"type": "sphere", "radius": 1}, "transform": {"translate": [1.1, 0, 0]}}]}
JSON
}

case_diff_ztest() {  # an unbiased 64-spp render passes against a 1024-spp reference; one material 2 % brighter fails
  write_two_balls_scene "$work/scene.json" 0.5
  write_two_balls_scene "$work/biased.json" 0.51
  cli_expect 0 render "$work/scene.json" --spp 1024 --seed 1 --aov variance,sample_count --quiet -o "$work/ref.exr"
  cli_expect 0 render "$work/scene.json" --spp 64 --seed 2 --quiet -o "$work/test.exr"
  cli_expect 0 render "$work/biased.json" --spp 64 --seed 2 --quiet -o "$work/biased.exr"
  cli_expect 0 diff --ztest "$work/ref.exr" "$work/test.exr" --json "$work/z.json"
  expect_in "$work/stdout" "): pass" stdout
  expect_in "$work/z.json" '"passed": true' z.json
  cli_expect 3 diff --ztest "$work/ref.exr" "$work/biased.exr" --error-map "$work/z.png"
  expect_in "$work/stdout" "): FAIL" stdout
  [[ -s "$work/z.png" ]] || fail "no z-test error map"
  # The test's sample count comes from its isotrace:spp metadata; a wrong --test-spp changes the verdict.
  cli_expect 3 diff --ztest "$work/ref.exr" "$work/test.exr" --test-spp 100000
  cli_expect 2 diff --ztest "$work/ref.exr" "$work/test.exr" --fail flip=0.1
}

# tools/convergence: a ladder per scene and build, its errors against a cached reference, the time to an error, the
# log-log plot; bad arguments are exit 2.
case_convergence_tool() {
  python3 tools/convergence "$cornell" scenes/embree_cornell_box.json --builds "one=$cli,two=$cli" --res 16x16 --spp-ladder 1,2,4 \
    --reference-spp 16 --threads 1 --cache "$work/cache" --plot "$work/plot.svg" --json "$work/c.json" \
    >"$work/stdout" 2>"$work/stderr" || { cat "$work/stderr" >&2; fail "tools/convergence failed"; }
  expect_in "$work/stdout" "scenes/cornell_box.json:" stdout
  expect_in "$work/stdout" "scenes/embree_cornell_box.json:" stdout
  expect_in "$work/stdout" "x one's" stdout
  grep -q "<polyline" "$work/plot.svg" || fail "no lines in the plot"
  (($(ls "$work/cache" | grep -c '\.exr$') == 2)) || fail "not one cached reference per scene"
  python3 - "$work/c.json" <<'PY' || fail "JSON: not three rungs per build with errors falling from 1 to 4 spp"
import json, sys
results = json.load(open(sys.argv[1]))["results"]
assert len(results) == 2
for result in results:
    for rows in result["builds"].values():
        assert [r["spp"] for r in rows] == [1, 2, 4]
        assert rows[0]["rms_error"] > rows[2]["rms_error"] > 0
PY
  local status=0
  python3 tools/convergence "$cornell" --builds "$cli" --spp-ladder 4 --cache "$work/cache" >/dev/null 2>&1 || status=$?
  ((status == 2)) || fail "a ladder of one rung is not refused with exit 2 (exit $status)"
}

# Reference mode: the stop at the target error is decided at pass boundaries, so the image is the same for any
# thread count and tile size, and --spp with the samples it stopped at renders the same pixels again.
case_reference_mode() {
  write_two_balls_scene "$work/scene.json" 0.5
  cli_expect 0 render "$work/scene.json" --reference --target-error 0.02 --seed 1 --threads 1 -o "$work/a.exr"
  sed 's/^/  stderr: /' "$work/stderr" >&2
  # The path tracer traces a pixel's samples eight at a time, so its first pass ends at 8 spp.
  expect_in "$work/stderr" "isotrace: 8 spp: estimated relative error "
  expect_in "$work/stderr" "(target 0.02, checked from 64 spp)"
  expect_in "$work/stderr" "(target 0.02): reached"
  cli_expect 0 render "$work/scene.json" --reference --target-error 0.02 --seed 1 --threads 2 --tile-size 5 \
    --quiet -o "$work/b.exr"
  [[ ! -s "$work/stderr" ]] || fail "--quiet printed the error estimate"
  idiff -fail 0 -failpercent 0 -warn 0 "$work/a.exr" "$work/b.exr" >"$work/idiff" 2>&1 ||
    { cat "$work/idiff" >&2; fail "reference renders with 1 and 2 threads differ"; }
  local spp
  spp=$(exr_attribute "$work/a.exr" spp)
  [[ "$(exr_attribute "$work/a.exr" stopped)" == "target error" ]] || fail "not stopped by the target error"
  ((spp >= 64 && (spp & (spp - 1)) == 0)) || fail "stopped at $spp spp, not a power of two from 64 on"
  exr_info "$work/a.exr" "$work/info"
  local entry
  for entry in variance.R variance.B sampleCount "isotrace:scene_hash" "isotrace:commit" "isotrace:target_error" \
    "isotrace:estimated_error" "isotrace:channels" "isotrace:reproduce" "isotrace:seed" "isotrace:sampler" \
    "isotrace:version"; do
    expect_in "$work/info" "$entry" "the reference's channels and metadata"
  done
  grep -q "half" "$work/info" && fail "a reference EXR must be full float"
  expect_in "$work/info" "--reference --res 32x16 --seed 1 --spp $spp"
  # The scene hash is the one isotrace info prints.
  cli_expect 0 info "$work/scene.json"
  expect_in "$work/stdout" "scene hash   $(exr_attribute "$work/a.exr" scene_hash)"
  # The printed command renders the same pixels.
  cli_expect 0 render "$work/scene.json" --reference --res 32x16 --seed 1 --spp "$spp" --quiet -o "$work/c.exr"
  idiff -fail 0 -failpercent 0 -warn 0 "$work/a.exr" "$work/c.exr" >"$work/idiff" 2>&1 ||
    { cat "$work/idiff" >&2; fail "--spp $spp does not reproduce the reference"; }
  # A low-budget reference-mode render with another seed passes the z-test (with its own variance), one with the
  # reference's seed is refused.
  cli_expect 0 render "$work/scene.json" --reference --spp 64 --seed 2 --quiet -o "$work/test.exr"
  cli_expect 0 diff --ztest "$work/a.exr" "$work/test.exr"
  expect_in "$work/stdout" "16x16 blocks"
  cli_expect 2 diff --ztest "$work/a.exr" "$work/c.exr"
  expect_in "$work/stderr" "same seed"
}

# A reference render cut short by its time budget leaves a checkpoint; resumed, it goes on to the same stop.
case_reference_resume() {
  write_two_balls_scene "$work/scene.json" 0.5
  cli_expect 0 render "$work/scene.json" --reference --target-error 0.01 --seed 3 --quiet -o "$work/a.exr"
  cli_expect 3 render "$work/scene.json" --reference --target-error 0.01 --seed 3 --time 0.05 --quiet \
    -o "$work/b.exr" --checkpoint "$work/ck.bin"
  [[ -s "$work/ck.bin" ]] || fail "no checkpoint after the time budget"
  cli_expect 2 render "$work/scene.json" --resume "$work/ck.bin" --target-error 0.5 --quiet -o "$work/b.exr"
  expect_in "$work/stderr" "--target-error 0.5 differs"
  cli_expect 0 render "$work/scene.json" --resume "$work/ck.bin" --quiet -o "$work/b.exr"
  idiff -fail 0 -failpercent 0 -warn 0 "$work/a.exr" "$work/b.exr" >"$work/idiff" 2>&1 ||
    { cat "$work/idiff" >&2; fail "the resumed reference differs from the uninterrupted one"; }
  [[ "$(exr_attribute "$work/b.exr" stopped)" == "target error" ]] || fail "the resumed render did not stop at the target"
}

case_reference_bad_input() {
  write_two_balls_scene "$work/scene.json" 0.5
  local value
  for value in 0 -0.1 nan inf abc ""; do
    cli_expect 2 render "$work/scene.json" --reference --target-error "$value" --quiet -o "$work/a.exr"
    expect_in "$work/stderr" "--target-error"
  done
  cli_expect 2 render "$work/scene.json" --target-error 0.01 --quiet -o "$work/a.exr"
  expect_in "$work/stderr" "needs --reference"
  cli_expect 2 render "$work/scene.json" --reference --quiet -o "$work/a.png"
  expect_in "$work/stderr" "give -o NAME.exr"
  cli_expect 0 render "$work/scene.json" --spp 100000 --time 0.1 --quiet -o "$work/plain.exr" --checkpoint "$work/ck.bin"
  cli_expect 2 render "$work/scene.json" --resume "$work/ck.bin" --reference --quiet -o "$work/a.exr"
  expect_in "$work/stderr" "not of a reference render"
  expect_no_file "$work/a.exr"
  expect_no_file "$work/a.png"
}

# A reference render whose sample limit or time budget ends it before its target error still writes its images,
# warns with the error reached and the target (also with --quiet), and exits 3.
case_reference_target_not_met() {
  write_two_balls_scene "$work/scene.json" 0.5
  cli_expect 3 render "$work/scene.json" --reference --target-error 0.0001 --spp 64 --quiet -o "$work/a.exr"
  expect_in "$work/stderr" "isotrace: warning: the target error was not reached: estimated relative error "
  expect_in "$work/stderr" "at 64 spp, target 0.0001 (the sample limit --spp was reached)"
  [[ "$(exr_attribute "$work/a.exr" stopped)" == "complete" ]] || fail "the image was not written whole"
  cli_expect 3 render "$work/scene.json" --reference --target-error 0.0001 --spp 16 --quiet -o "$work/b.exr"
  expect_in "$work/stderr" "the sample limit came before 64 spp, where the target is first checked"
  cli_expect 3 render "$work/scene.json" --reference --target-error 0.0001 --time 0.2 --quiet -o "$work/c.exr"
  expect_in "$work/stderr" "(the time budget --time ran out)"
  [[ -s "$work/c.exr" ]] || fail "no image after the time budget"
  # A target the budget reaches: exit 0, no warning.
  cli_expect 0 render "$work/scene.json" --reference --target-error 0.5 --spp 64 --quiet -o "$work/d.exr"
  [[ ! -s "$work/stderr" ]] || fail "a reached target printed: $(cat "$work/stderr")"
}

# Without an integrator a scene renders with the path tracer. The preview integrator warns about the light it
# leaves out (an environment seen by rays leaving the scene, emitters it cannot sample), also with --quiet and in
# isotrace info.
case_default_integrator_and_preview_warning() {
  write_base_scene "$work/scene.json"
  cli_expect 0 render "$work/scene.json" --quiet -o "$work/a.exr"
  [[ "$(exr_attribute "$work/a.exr" integrator)" == "path" ]] ||
    fail "a scene without integrator rendered with $(exr_attribute "$work/a.exr" integrator)"
  cli_expect 0 info "$work/scene.json"
  expect_in "$work/stdout" "integrator   path"
  sed 's/^  "film": .*/  "film": { "resolution": [16, 16], "spp": 1 }, "integrator": { "type": "preview" },/' \
    "$work/scene.json" >"$work/preview.json"
  cli_expect 0 render "$work/preview.json" --quiet -o "$work/b.exr"
  [[ ! -s "$work/stderr" ]] || fail "the preview of a point light warned: $(cat "$work/stderr")"
  sed 's/"type": "point", "position": \[0, 3, -3\], "intensity"/"type": "environment", "radiance"/' \
    "$work/preview.json" >"$work/environment.json"
  cli_expect 0 render "$work/environment.json" --quiet -o "$work/c.exr"
  expect_in "$work/stderr" "isotrace: warning: the preview integrator leaves out the environment"
  expect_in "$work/stderr" 'use "integrator": {"type": "path"}'
  (($(grep -c warning "$work/stderr") == 1)) || fail "more than one warning: $(cat "$work/stderr")"
  cli_expect 0 info "$work/environment.json"
  expect_in "$work/stderr" "isotrace: warning: the preview integrator leaves out the environment"
}

# A black image is warned about; the statistics count the pixels that are not finite, and print a short summary
# unless --stats full asks for every counter.
case_image_warnings_and_statistics() {
  write_base_scene "$work/scene.json"
  sed 's/^  "lights": .*/  "lights": [],/' "$work/scene.json" >"$work/dark.json"
  cli_expect 0 render "$work/dark.json" --quiet -o "$work/a.exr" --stats-json "$work/s.json"
  expect_in "$work/stderr" "isotrace: warning: the image is black everywhere"
  expect_in "$work/s.json" '"non_finite_pixels": 0'
  expect_in "$work/s.json" '"peak_memory_bytes": '
  cli_expect 0 render "$work/scene.json" -o "$work/b.exr"
  grep -q warning "$work/stderr" && fail "a lit image was warned about: $(cat "$work/stderr")"
  local scene=scenes/superquadric_gallery.json
  cli_expect 0 render "$scene" --res 24x16 --spp 1 -o "$work/c.exr" --stats-json "$work/full.json"
  for entry in "statistics:" "  time      parse" "samples/s" "Mrays/s" "NaN/Inf   0 samples discarded, 0 pixels" \
    "MiB peak resident"; do
    expect_in "$work/stderr" "$entry" "the short statistics"
  done
  grep -q -e halvings -e "geometry  type" "$work/stderr" && fail "the short statistics list the work counters"
  expect_in "$work/full.json" '"superquadric.halvings"' "--stats-json"
  cli_expect 0 render "$scene" --res 24x16 --spp 1 -o "$work/c.exr" --stats full
  expect_in "$work/stderr" "halvings" "--stats full"
  expect_in "$work/stderr" "geometry  type" "--stats full"
  cli_expect 0 render "$scene" --res 24x16 --spp 1 -o "$work/c.exr" --stats none
  grep -q "statistics:" "$work/stderr" && fail "--stats none printed statistics"
  cli_expect 0 render "$scene" --res 24x16 --spp 1 -o "$work/c.exr" --stats full --quiet
  [[ ! -s "$work/stderr" ]] || fail "--quiet printed: $(cat "$work/stderr")"
  cli_expect 2 render "$scene" --res 24x16 --spp 1 -o "$work/c.exr" --stats most
}

# info --views: the OCIO config's displays and views, its defaults marked, and the pair a scene uses.
case_info_views() {
  cli_expect 0 info --views
  expect_in "$work/stdout" "display      sRGB  (default)"
  expect_in "$work/stdout" "  view       ACES 1.0 - SDR Video  (default)"
  expect_in "$work/stdout" "  view       Un-tone-mapped"
  write_base_scene "$work/scene.json"
  sed 's/^  "film": { "resolution": \[16, 16\], "spp": 1 },/  "film": { "resolution": [16, 16], "spp": 1, "view": "Un-tone-mapped" },/' \
    "$work/scene.json" >"$work/view.json"
  cli_expect 0 info "$work/view.json" --views
  expect_in "$work/stdout" "display      sRGB  (default, the scene's)"
  expect_in "$work/stdout" "  view       Un-tone-mapped  (the scene's)"
  expect_in "$work/stdout" "  view       ACES 1.0 - SDR Video  (default)"
}

# ---- outputs that replace only what is theirs; inputs that are regular files -----------------------------

# expect_char_device <path>: the node is still a character device (not replaced by a regular file).
expect_char_device() {
  [[ -c "$1" && ! -L "$1" ]] || fail "$1 is no longer a character device"
}

# Every kind of non-regular output is refused before any work, for every command that writes, and stays as it was.
case_output_not_regular() {
  write_base_scene "$work/scene.json"
  local device="$work/null" nodes=("$work/fifo" "$work/dir.png")
  mkfifo "$work/fifo"
  mkdir "$work/dir.png"
  echo precious >"$work/victim"
  ln -s "$work/victim" "$work/link.png"
  nodes+=("$work/link.png")
  if mknod "$device" c 1 3 2>/dev/null; then nodes+=("$device"); else echo "(no mknod here: device case skipped)" >&2; fi
  local node
  for node in "${nodes[@]}"; do
    cli_expect 2 render "$work/scene.json" --quiet -o "$work/a.exr" --stats-json "$node"
    expect_in "$work/stderr" "--stats-json" stderr
    if grep -q "loaded in" "$work/stderr"; then fail "the scene was loaded before the output was refused"; fi
    cli_expect 2 render "$work/scene.json" --quiet -o "$work/a.exr" --checkpoint "$node"
    cli_expect 2 render "$work/scene.json" --quiet -o "$node"
    cli_expect 2 diff "$cornell" "$cornell" --json "$node"
    cli_expect 2 mesh "$work/scene.json" -o "$node"
    cli_expect 2 depth "$work/scene.json" -o "$node"
    expect_no_file "$work/a.exr"
  done
  [[ -p "$work/fifo" ]] || fail "the FIFO was replaced"
  [[ -d "$work/dir.png" ]] || fail "the directory was replaced"
  [[ -L "$work/link.png" && "$(cat "$work/victim")" == precious ]] || fail "the link or its target was replaced"
  [[ ! -e "$device" ]] || expect_char_device "$device"
  expect_no_partial_files "$work"
}

# No output may be an input or another output, however it is spelled; nothing is written or replaced.
case_output_collisions() {
  mkdir "$work/sub"
  write_base_scene "$work/scene.json"
  cp "$work/scene.json" "$work/scene.orig"
  local refused=(
    "render $work/scene.json --quiet -o $work/a.exr --stats-json $work/sub/../scene.json"
    "render $work/scene.json --quiet -o $work/x.exr --stats-json $work/x.exr"
    "render $work/scene.json --quiet -o $work/a.exr --checkpoint $work/scene.json"
    "render $work/scene.json --quiet -o $work/x.exr --checkpoint $work/sub/../x.exr"
    "render $work/scene.json --quiet -o $work/scene.json.exr -o $work/scene.json.exr"
    "render $work/scene.json --quiet -o $work/a.exr --stats-json - --checkpoint -")
  local command
  for command in "${refused[@]}"; do
    # shellcheck disable=SC2086
    cli_expect 2 $command
    cmp -s "$work/scene.json" "$work/scene.orig" || fail "$command changed the scene"
  done
  expect_no_file "$work/a.exr"
  expect_no_file "$work/x.exr"
  render_small -o "$work/ref.png"
  render_small -o "$work/test.png" --seed 3
  cp "$work/ref.png" "$work/ref.orig"
  cli_expect 2 diff "$work/ref.png" "$work/test.png" --error-map "$work/ref.png"
  cli_expect 2 diff "$work/ref.png" "$work/test.png" --json "$work/test.png"
  cmp -s "$work/ref.png" "$work/ref.orig" || fail "diff replaced its reference"
  # A file the scene reads (here its mesh) is known only once the scene is loaded: refused before rendering.
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$work/tri.obj"
  sed 's/"type": "sphere",/"type": "mesh", "file": "tri.obj"/; /"radius": 1/d' "$work/scene.json" >"$work/mesh_scene.json"
  cp "$work/tri.obj" "$work/tri.orig"
  cli_expect 2 render "$work/mesh_scene.json" --quiet --stats-json "$work/tri.obj" -o "$work/m.exr"
  expect_in "$work/stderr" "a file the scene reads" stderr
  cmp -s "$work/tri.obj" "$work/tri.orig" || fail "the render replaced the scene's mesh"
  expect_no_file "$work/m.exr"
  # Resuming goes on checkpointing to the file it came from: that one is allowed.
  cli_expect 0 render "$work/scene.json" --spp 100000 --time 0.2 --quiet -o "$work/r.exr" --checkpoint "$work/ck.bin"
  cli_expect 0 render "$work/scene.json" --resume "$work/sub/../ck.bin" --time 0.2 --quiet -o "$work/r.exr"
  expect_no_partial_files "$work"
}

case_stats_to_standard_output() {
  cli_expect 0 render "$cornell" --res 16x16 --spp 1 --quiet -o "$work/a.exr" --stats-json -
  python3 -c 'import json, sys; json.load(open(sys.argv[1]))' "$work/stdout" || fail "stdout is not the statistics JSON"
  expect_in "$work/stdout" '"samples_per_second"' stdout
  expect_no_file "$work/-"
  cli_expect 2 render "$cornell" --res 16x16 --spp 1 --quiet -o "$work/a.exr" --checkpoint -
  expect_in "$work/stderr" "standard output" stderr
}

# A FIFO or device named as any input is refused at once (a FIFO used to block forever, /dev/zero to stream).
case_input_not_regular() {
  write_base_scene "$work/scene.json"
  mkfifo "$work/fifo"
  local limit=$((10 * time_scale))
  run "$work/stdout" "$work/stderr" timeout "$limit" "$cli" render "$work/fifo" --quiet -o "$work/a.exr"
  ((status == 2)) || { show_output; fail "a FIFO as the scene: exit $status, expected 2"; }
  expect_in "$work/stderr" "is a FIFO" stderr
  run "$work/stdout" "$work/stderr" timeout "$limit" "$cli" render "$work/scene.json" --resume "$work/fifo" --quiet \
    -o "$work/a.exr"
  ((status == 2)) || { show_output; fail "a FIFO as the checkpoint: exit $status, expected 2"; }
  run "$work/stdout" "$work/stderr" timeout "$limit" "$cli" render "$work/scene.json" --resume /dev/zero --quiet \
    -o "$work/a.exr"
  ((status == 2)) || { show_output; fail "/dev/zero as the checkpoint: exit $status, expected 2"; }
  expect_in "$work/stderr" "character device" stderr
  run "$work/stdout" "$work/stderr" timeout "$limit" "$cli" diff "$work/fifo" "$cornell"
  ((status == 2)) || { show_output; fail "a FIFO as a diff input: exit $status, expected 2"; }
  run "$work/stdout" "$work/stderr" timeout "$limit" "$cli" deform scenes/data/bunny.obj "$work/fifo" -o "$work/d.ply"
  ((status == 2)) || { show_output; fail "a FIFO as the deformer file: exit $status, expected 2"; }
  # Named by a scene: the message has the scene position and says what the path is, not "file not found".
  sed 's/"type": "sphere",/"type": "mesh", "file": "fifo"/; /"radius": 1/d' "$work/scene.json" >"$work/fifo_scene.json"
  run "$work/stdout" "$work/stderr" timeout "$limit" "$cli" render "$work/fifo_scene.json" --quiet -o "$work/a.exr"
  ((status == 2)) || { show_output; fail "a FIFO as a mesh: exit $status, expected 2"; }
  expect_in "$work/stderr" "fifo_scene.json:11:" stderr
  expect_in "$work/stderr" "is a FIFO" stderr
  expect_no_file "$work/a.exr"
}

case_nul_in_file_name() {  # the extension check saw ".obj" but the system opened /etc/passwd
  write_base_scene "$work/scene.json"
  sed 's|"type": "sphere",|"type": "mesh", "file": "/etc/passwd\\u0000.obj"|; /"radius": 1/d' "$work/scene.json" \
    >"$work/nul.json"
  cli_expect 2 render "$work/nul.json" --quiet -o "$work/a.exr"
  expect_in "$work/stderr" "NUL" stderr
  expect_in "$work/stderr" "nul.json:11:" stderr
}

case_long_output_name() {  # the temporary sibling's name used to exceed NAME_MAX
  local name
  name=$(printf 'a%.0s' $(seq 1 245)).png
  render_small -o "$work/$name"
  [[ -s "$work/$name" ]] || fail "no output of a 249-character name"
  expect_no_partial_files "$work"
}

case_checkpoint_interval_minimum() {  # 1e-6 s paused the render before every sample: 0 samples in a minute
  cli_expect 2 render "$cornell" --quiet -o "$work/a.exr" --checkpoint "$work/ck.bin" --checkpoint-every 0.000001
  expect_in "$work/stderr" "at least 0.05 s" stderr
  expect_no_file "$work/ck.bin"
}

case_checkpoint_lost_is_a_failure() {  # "wrote checkpoint" used to follow "no checkpoint written", with exit 0
  run "$work/stdout" "$work/stderr" bash -c 'ulimit -f 2; exec "$@"' _ "$cli" render "$cornell" --res 8x8 \
    --spp 100000 --time 0.3 -o "$work/a.png" --checkpoint "$work/ck.bin"
  ((status == 1)) || { show_output; fail "exit $status when the final checkpoint could not be written, expected 1"; }
  expect_in "$work/stderr" "no checkpoint written" stderr
  if grep -q "wrote checkpoint" "$work/stderr"; then fail "claims a checkpoint it could not write"; fi
  [[ -s "$work/a.png" ]] || fail "the image was not written"
  expect_no_file "$work/ck.bin"
  expect_no_partial_files "$work"
}

case_max_memory_every_command() {  # mesh, depth, deform and diff had no limit but 80 % of physical memory
  cli_expect 2 deform scenes/data/teapot.bpt scenes/sweeps/teapot_pull.json -o "$work/t.ply" --max-memory 2M
  expect_in "$work/stderr" "more than the memory limit of 2.1 MB" stderr
  # The quality check (not with --quiet) is charged too: the bunny's traced copy and edge list.
  cli_expect 0 deform scenes/data/bunny.obj scenes/sweeps/bunny_ear_bend.json -o "$work/q.ply" --max-memory 12M --quiet
  cli_expect 2 deform scenes/data/bunny.obj scenes/sweeps/bunny_ear_bend.json -o "$work/r.ply" --max-memory 12M
  expect_in "$work/stderr" "needs about 8.93 MB (on top of 6.95 MB already needed)" stderr
  cli_expect 2 mesh scenes/metacube_dog.json --max-memory 1M -o "$work/m.ply"
  expect_in "$work/stderr" "more than the memory limit of 1.05 MB" stderr
  cli_expect 2 depth "$cornell" --max-memory 1M --res 1024x1024 -o "$work/d.png"
  expect_in "$work/stderr" "more than the memory limit of 1.05 MB" stderr
  python3 -c 'import sys; sys.stdout.write("{\"deformers\": [], \"padding\": [" + ",".join(["0"] * 3000000) + "]}")' \
    >"$work/padded.json"
  cli_expect 2 deform scenes/data/bunny.obj "$work/padded.json" -o "$work/t.ply" --max-memory 20M
  expect_in "$work/stderr" "padded.json:1:" stderr
  expect_in "$work/stderr" "the parsed document" stderr
  cli_expect 0 render "$cornell" --res 512x512 --spp 1 --quiet -o "$work/a.exr"
  cli_expect 0 render "$cornell" --res 512x512 --spp 1 --seed 2 --quiet -o "$work/b.exr"
  cli_expect 2 diff "$work/a.exr" "$work/b.exr" --max-memory 150M --json "$work/diff.json"
  expect_in "$work/stderr" "comparing the 512x512 image" stderr
  cli_expect 0 diff "$work/a.exr" "$work/b.exr" --max-memory 250M
  expect_no_file "$work/t.ply"
  expect_no_file "$work/m.ply"
  expect_no_file "$work/d.png"
  expect_no_file "$work/diff.json"
}

case_control_characters_escaped() {  # a scene's description and object names reached the terminal raw
  sed 's/"name": "dog"/"name": "d\\u001b[2Jog"/; s/"description": "Kim/"description": "\\u001b]0;pwned\\u0007Kim/' \
    scenes/metacube_dog.json >"$work/dog.json"
  sed -i 's|"file": "|"file": "'"$PWD"'/scenes/|' "$work/dog.json"
  cli_expect 0 info "$work/dog.json"
  if grep -q $'\x1b' "$work/stdout"; then fail "info printed an escape character"; fi
  expect_in "$work/stdout" '\x1b]0;pwned\x07Kim' stdout
  cli_expect 0 mesh "$work/dog.json" --object $'d\x1b[2Jog' --depth 3 -o "$work/dog.ply"
  if grep -q $'\x1b' "$work/stdout"; then fail "mesh printed an escape character"; fi
  expect_in "$work/stdout" 'd\x1b[2Jog' stdout
}

case_bench_filter_bounded() {  # 40,000 nested parentheses overflowed the regex compiler's stack
  cli_expect 2 bench --quick --filter "$(printf '(%.0s' $(seq 1 40000))x$(printf ')%.0s' $(seq 1 40000))"
  expect_in "$work/stderr" "longer than 256 characters" stderr
  cli_expect 2 bench --quick --filter "((((((((((x))))))))))"
  expect_in "$work/stderr" "nests groups deeper" stderr
}

# ---- image, scene and checkpoint limits -------------------------------------------------------------------
# --max-memory bounds the real peak: every input-sized allocation (images with their decoders' buffers and
# set-up copies, the parsed scene document) is charged before it happens; checkpoint values are range-checked.

# run_with_peak <isotrace arguments...>: runs isotrace like cli_expect (stdout and stderr in $work), sets $status
# and $peak_mb, its peak resident memory in MiB.
run_with_peak() {
  echo "+ $cli $*" >&2
  read -r status peak_mb < <(python3 -c '
import resource, subprocess, sys
with open(sys.argv[1], "w") as out, open(sys.argv[2], "w") as err:
    code = subprocess.run(sys.argv[3:], stdout=out, stderr=err).returncode
print(code, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss // 1024)' "$work/stdout" "$work/stderr" "$cli" "$@")
  echo "  exit $status, peak $peak_mb MiB" >&2
}

# peak_within <MiB>: whether the last run's peak resident memory ($peak_mb) is below <MiB>; always so in an
# instrumented build.
peak_within() { ((instrumented || peak_mb < $1)); }

# expect_bounded <limit MiB> <isotrace arguments...>: under --max-memory <limit>M, isotrace either refuses the
# input (exit 2) before allocating it or runs (exit 0) within the limit.
expect_bounded() {
  local limit=$1
  shift
  run_with_peak "$@" --max-memory "${limit}M"
  if ((status != 0 && status != 2)); then
    show_output
    fail "exit $status under --max-memory ${limit}M"
  fi
  peak_within "$limit" || { show_output; fail "peak resident memory $peak_mb MiB over --max-memory ${limit}M"; }
}

# write_png <path> <width> <height> <channels> [header]: a mid-grey 8-bit PNG, deflated ~1000:1; with "header",
# only its first row is stored (enough for a reader to see the size).
write_png() {
  python3 - "$@" <<'PY' || fail "cannot write $1"
import struct, sys, zlib
out, w, h, c = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
rows = 1 if len(sys.argv) > 5 else h
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
z, row = zlib.compressobj(9), b"\0" + b"\x80" * (w * c)
with open(out, "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, {1: 0, 3: 2, 4: 6}[c], 0, 0, 0)))
    data = bytearray()
    for _ in range(rows):
        data += z.compress(row)
    f.write(chunk(b"IDAT", bytes(data + z.flush())) + chunk(b"IEND", b""))
PY
}

# write_image_scene <path> <material reflectance> <light>: a sphere under one light, 16x16 at 1 spp.
write_image_scene() {
  cat >"$1" <<JSON
{
  "isotrace": 1,
  "film": { "resolution": [16, 16], "spp": 1 },
  "camera": { "type": "perspective", "fov": 40, "look_at": { "eye": [0, 0, -5], "target": [0, 0, 0], "up": [0, 1, 0] } },
  "materials": { "m": { "type": "diffuse", "reflectance": $2 } },
  "lights": [ $3 ],
  "objects": [ { "material": "m", "shape": { "type": "sphere", "radius": 1 } } ]
}
JSON
}

point_light='{ "type": "point", "position": [0, 3, -3], "intensity": { "rgb": [10, 10, 10], "space": "lin_rec709" } }'

# A 186 kB PNG of 8000x8000 peaked at 4.6 GB under --max-memory 2G, and 20000x20000 (estimated at 9.6 GB)
# brought the machine to the OOM killer: decoding is charged with the decoder's buffers, and the copies are gone.
case_texture_memory_limit() {  # refused from the header, before any pixel is decoded
  write_png "$work/huge.png" 20000 20000 3 header
  write_image_scene "$work/huge.json" '{ "texture": "huge.png" }' "$point_light"
  run_with_peak render "$work/huge.json" --max-memory 4G --quiet -o "$work/a.exr"
  ((status == 2)) || { show_output; fail "a 20000x20000 texture was not refused under 4G (exit $status)"; }
  expect_in "$work/stderr" "$work/huge.png" stderr
  expect_in "$work/stderr" "the 20000x20000 image with its mip levels needs about" stderr
  peak_within 300 || fail "the refused texture was decoded (peak $peak_mb MiB)"
  expect_no_file "$work/a.exr"
  # Reading any image loads OpenImageIO's libraries (over 100 MB resident), charged before they are loaded.
  write_png "$work/tiny.png" 1 1 3
  write_image_scene "$work/tiny.json" '{ "texture": "tiny.png" }' "$point_light"
  expect_bounded 64 render "$work/tiny.json" --quiet -o "$work/a.exr"
  expect_in "$work/stderr" "the image module that reads it (OpenImageIO's libraries) needs about" stderr
  expect_bounded 256 render "$work/tiny.json" --quiet -o "$work/a.exr"
  ((status == 0)) || { show_output; fail "a 1x1 texture was refused under 256M"; }
}

case_texture_memory_peak() {  # admitted textures stay within the limit (long: 64 M pixels decoded twice)
  write_png "$work/big.png" 8000 8000 3
  write_image_scene "$work/big.json" '{ "texture": "big.png" }' "$point_light"
  expect_bounded 2048 render "$work/big.json" --quiet -o "$work/a.exr"
  ((status == 0)) || { show_output; fail "the 8000x8000 texture was refused under 2G"; }
  write_png "$work/grey.png" 8000 8000 1
  write_image_scene "$work/grey.json" '{ "texture": "grey.png" }' "$point_light"
  # Spread to RGB floats, with its mip levels (a third more).
  expect_bounded 1600 render "$work/grey.json" --quiet -o "$work/a.exr"
  ((status == 0)) || { show_output; fail "the 8000x8000 grey texture was refused under 1600M"; }
}

# An EXR environment map estimated at 432 MB peaked at 1.4 GB under --max-memory 500M: the light's sampling
# distribution is charged with the map (long: 18 M pixels).
case_environment_map_memory_limit() {
  oiiotool --pattern constant:color=0.5,0.5,0.5 6000x3000 3 -d half -o "$work/env.exr" >/dev/null ||
    fail "oiiotool cannot write env.exr"
  write_image_scene "$work/env.json" '{ "rgb": [0.5, 0.5, 0.5], "space": "lin_rec709" }' \
    '{ "type": "environment", "file": "env.exr" }'
  expect_bounded 500 render "$work/env.json" --quiet -o "$work/a.exr"
  ((status == 2)) || fail "the environment map was not refused under 500M"
  expect_in "$work/stderr" "the 6000x3000 image needs about" stderr
  expect_bounded 1200 render "$work/env.json" --quiet -o "$work/a.exr"
  ((status == 0)) || { show_output; fail "the environment map was refused under 1200M"; }
}

# A 54 MB scene of inline arrays reached 2.8 GB under --max-memory 1G: the parsed document is charged as it grows,
# and the parse stops at the file, line and column where the budget ran out.
case_inline_scene_memory_limit() {
  write_base_scene "$work/scene.json"
  python3 - "$work/scene.json" <<'PY'
import sys
text = open(sys.argv[1]).read()
pad = '  "pad": [' + ",\n".join(["[0.5, 0.25, 0.125]"] * 3000000) + "],\n"
open(sys.argv[1], "w").write(text.replace('  "isotrace": 1,\n', '  "isotrace": 1,\n' + pad, 1))
PY
  expect_bounded 1024 render "$work/scene.json" --quiet -o "$work/a.exr"
  ((status == 2)) || fail "the inline scene was not refused"
  expect_in "$work/stderr" "the parsed document (" stderr
  grep -qE "$work/scene.json:[0-9]+:[0-9]+: " "$work/stderr" || { show_output; fail "the refusal does not name line and column"; }
}

# A checkpoint's checksum says only that its bytes are the ones written (these tests recompute it): every value
# behind it is checked, and a bad one refused naming the checkpoint and the field.
case_checkpoint_values_checked() {
  cp "$cornell" "$work/scene.json"
  cli_expect 0 render "$work/scene.json" --res 16x16 --spp 100000 --time 0.2 --quiet -o "$work/a.exr" \
    --checkpoint "$work/ck.bin"
  [[ -s "$work/ck.bin" ]] || fail "no checkpoint after a time budget ended the render"
  # edit_checkpoint <out> <python statement on `meta` (dict) and `state` (bytearray)>
  edit_checkpoint() {
    python3 - "$work/ck.bin" "$1" "$2" <<'PY' || fail "cannot edit the checkpoint"
import json, struct, sys
data = open(sys.argv[1], "rb").read()
m, s = struct.unpack_from("<QQ", data, 16)
meta, state = json.loads(data[32:32 + m]), bytearray(data[32 + m:32 + m + s])
exec(sys.argv[3])
body = json.dumps(meta).encode() + bytes(state)
h = 0xcbf29ce484222325
for b in body:
    h = ((h ^ b) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
open(sys.argv[2], "wb").write(data[:16] + struct.pack("<QQ", len(body) - len(state), len(state)) + body +
                              struct.pack("<Q", h))
PY
  }
  edit_checkpoint "$work/same.bin" "pass"
  cli_expect 0 render "$work/scene.json" --resume "$work/same.bin" --time 0.1 --quiet -o "$work/a.exr"
  value_refused() {  # value_refused <python edit> <expected text>
    edit_checkpoint "$work/edited.bin" "$1"
    cli_expect 2 render "$work/scene.json" --resume "$work/edited.bin" --quiet -o "$work/b.exr"
    expect_in "$work/stderr" "$work/edited.bin" stderr
    expect_in "$work/stderr" "$2" stderr
    expect_no_file "$work/b.exr"
  }
  value_refused 'meta["options"]["seed"] = "-1"' "options.seed: expected a whole number"
  value_refused 'meta["options"]["seed"] = "18446744073709551616"' "options.seed: expected a whole number"
  value_refused 'meta["options"]["spp"] = 0' "options.spp: 0 is out of range"
  value_refused 'meta["options"]["spp"] = 1 << 40' "options.spp: 1099511627776 is out of range"
  value_refused 'meta["options"]["spp"] = 2.5' "options.spp: expected a whole number"
  value_refused 'meta["options"]["resolution"] = [0, 16]' "options.resolution"
  value_refused 'meta["options"]["resolution"] = [100000, 16]' "options.resolution"
  value_refused 'meta["options"]["target_error"] = -1' "options.target_error"
  value_refused 'struct.pack_into("<d", state, 0, float("nan"))' "pixel (0, 0) holds a sum that is not a finite number"
  value_refused 'struct.pack_into("<I", state, 112 * 17 + 108, 0xFFFFFFFF)' \
    "pixel (1, 1) has a sample count of 4294967295, above the render's target of 100000"
}

# 64 MB of zero bytes named z.exr took 20 s in OpenImageIO, which tries every reader it has on a file its
# extension's reader refuses (a few hundred MB spun for minutes): such a file is refused at once.
case_diff_zero_file() {
  render_small -o "$work/a.exr"
  truncate -s 256M "$work/z.exr"
  cli_expect 2 diff "$work/z.exr" "$work/a.exr"
  expect_in "$work/stderr" "$work/z.exr" stderr
  expect_in "$work/stderr" \
    "its extension names the OpenEXR format, but the file does not start with that format's signature" stderr
  truncate -s 64M "$work/z.png"
  cli_expect 2 diff "$work/a.exr" "$work/z.png"
  expect_in "$work/stderr" "its extension names the PNG format" stderr
}

# ---- geometry work and memory limits -----------------------------------------------------------------------

# run_peak <expected exit code> <isotrace arguments...>: like cli_expect, and sets $peak_mb to the run's peak
# resident memory (the kernel's high-water mark of the child, VmHWM).
run_peak() {
  local expected=$1
  shift
  run_with_peak "$@"
  if ((status != expected)); then
    show_output
    fail "isotrace $* exited with $status, expected $expected"
  fi
}

expect_peak_below() {  # expect_peak_below <MB>
  peak_within "$1" || fail "peak resident memory $peak_mb MB, not below the limit of $1 MB"
}

# write_geometry_scene <dir> <shape JSON>: a 16x16 scene of that one shape.
write_geometry_scene() {
  mkdir -p "$1"
  cat >"$1/scene.json" <<JSON
{"isotrace": 1, "film": {"resolution": [16, 16], "spp": 1},
 "camera": {"type": "perspective", "look_at": {"eye": [0, 0, -5], "target": [0, 0, 0]}},
 "materials": {"m": {"type": "diffuse"}},
 "objects": [{"material": "m", "shape": $2}]}
JSON
}

# An eight-sided patch of curved sides: "segments": N, or adaptive to "tolerance" within "max_segments".
octagon_patch() {  # octagon_patch <extra keys>
  python3 - "$1" <<'PY'
import json, math, sys
corners = [(math.cos(2 * math.pi * k / 8), math.sin(2 * math.pi * k / 8), 0.0) for k in range(8)]
curves = []
for k in range(8):
    a, b = corners[k], corners[(k + 1) % 8]
    inner = [[a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f, z] for f, z in ((1 / 3, 0.4), (2 / 3, -0.4))]
    curves.append({"points": [list(a)] + inner + [list(b)]})
print('{"type": "abm_patch", %s "boundary": %s}' % (sys.argv[1], json.dumps(curves)))
PY
}

case_geometry_abm_far_control_point() {  # control points at 1e100 made the tessellation run for minutes
  write_geometry_scene "$work/s" '{"type": "abm_patch", "boundary": [{"points": [[0, 0, 0], [1e100, 0, 0]]},
   {"points": [[1e100, 0, 0], [0, 1e100, 0]]}, {"points": [[0, 1e100, 0], [0, 0, 0]]}]}'
  cli_expect 2 info "$work/s/scene.json"
  expect_in "$work/stderr" "scene.json:4:99: objects[0].shape.boundary[0].points[1]: control point lies beyond 1e18 from the origin"
}

# The tessellation's peak memory per triangle is charged before each refinement round: a uniform 8-sided patch of
# 4.2 million triangles (once accepted under 512 MB, and peaking at 720 MB) is refused before any work; adaptive
# refinement stops at the round that would not fit, below the limit.
case_geometry_abm_tessellation_memory() {
  write_geometry_scene "$work/u" "$(octagon_patch '"segments": 512,')"
  run_peak 2 render "$work/u/scene.json" --max-memory 512M --quiet -o "$work/u.exr"
  expect_in "$work/stderr" "objects[0].shape: a tessellation of 4190208 triangles needs about 754 MB"
  expect_peak_below 100
  write_geometry_scene "$work/a" "$(octagon_patch '"tolerance": 1e-7, "max_segments": 4096,')"
  run_peak 2 render "$work/a/scene.json" --max-memory 128M --quiet -o "$work/a.exr"
  expect_in "$work/stderr" "more than the memory limit of 134 MB"
  expect_peak_below 128
  expect_no_file "$work/u.exr"
  expect_no_file "$work/a.exr"
}

# A 4 MB .bpt of 100,000 patches ran 2 minutes to 8.7 GB under a 1 GB limit: the tessellation is charged first.
case_geometry_bezier_patch_memory() {
  mkdir -p "$work/b"
  python3 - "$work/b/many.bpt" 100000 <<'PY'
import sys
count = int(sys.argv[2])
with open(sys.argv[1], "w") as f:
    f.write("%d\n" % count)
    for p in range(count):
        x, y = p % 1000, p // 1000
        f.write("1 1\n%d %d 0\n%d %d 0\n%d %d 0\n%d %d 1\n" % (x, y, x, y + 1, x + 1, y, x + 1, y + 1))
PY
  write_geometry_scene "$work/b" '{"type": "mesh", "file": "many.bpt"}'
  run_peak 2 render "$work/b/scene.json" --max-memory 1G --quiet -o "$work/b.exr"
  expect_in "$work/stderr" "objects[0].shape.file: $work/b/many.bpt: a tessellation of 100000 Bézier patches"
  expect_in "$work/stderr" "into 51200000 triangles needs about 11.8 GB"
  expect_peak_below 200
  expect_no_file "$work/b.exr"
  # Newell's teapot still loads and deforms.
  cli_expect 0 deform scenes/data/teapot.bpt scenes/sweeps/teapot.json -o "$work/teapot.ply" --quiet
}

# sweep_tubes of 4096 x 4096 reached 5.2 GB under a 2 GB limit: each tube is charged before it is made.
case_geometry_sweep_tubes_memory() {
  local sweep='{"type": "sweep", "key_sections": [{"center": [0, 0, 0], "radius": 0.5},
    {"center": [0, 0.3, 1], "radius": 0.4}, {"center": [0, 0, 2], "radius": 0.5}]}'
  write_geometry_scene "$work/t" '{"type": "sweep_tubes", "theta_steps": 4096, "t_steps": 4096, "deformers": ['"$sweep"']}'
  run_peak 2 render "$work/t/scene.json" --max-memory 2G --quiet -o "$work/t.exr"
  expect_in "$work/stderr" "objects[0].shape: a tube of 33562624 triangles (theta_steps 4096, t_steps 4096) needs about 6.71 GB"
  expect_peak_below 100
  # 4.2 million triangles were accepted under 512 MB and peaked at 680 MB.
  write_geometry_scene "$work/t" '{"type": "sweep_tubes", "theta_steps": 2048, "t_steps": 1024, "deformers": ['"$sweep"']}'
  run_peak 2 render "$work/t/scene.json" --max-memory 512M --quiet -o "$work/t.exr"
  expect_in "$work/stderr" "a tube of 4198400 triangles"
  expect_no_file "$work/t.exr"
  # A quarter of that fits, and stays below the limit.
  write_geometry_scene "$work/t" '{"type": "sweep_tubes", "theta_steps": 512, "t_steps": 1024, "deformers": ['"$sweep"']}'
  run_peak 0 render "$work/t/scene.json" --max-memory 512M --res 4x4 --quiet -o "$work/t.exr"
  expect_peak_below 512
}

# 50 deformers took 19 s and a file of them hours: a list beyond the work limit is refused before any work, by
# `isotrace deform` and in a scene alike; a deformer's memory is charged before it works.
case_geometry_deformer_limits() {
  python3 - "$work/many.json" <<'PY'
import json, sys
keys = [{"center": [-0.05 + 0.003 * k, 0.15, 0.0], "normal": [1, 0, 0], "radius": 0.02} for k in range(16)]
sweep = {"type": "sweep", "mode": "global", "levels": 6, "key_sections": keys}
json.dump({"deformers": [sweep] * 200}, open(sys.argv[1], "w"))
PY
  cli_expect 2 deform scenes/data/bunny.obj "$work/many.json" -o "$work/out.ply"
  expect_in "$work/stderr" "many.json:1:15: deformers: 200 deformers on 13934 vertices need about"
  expect_in "$work/stderr" "more than the limit of 2e+10"
  expect_no_file "$work/out.ply"
  cp scenes/data/bunny.obj "$work/bunny.obj"
  write_geometry_scene "$work" '{"type": "mesh", "file": "bunny.obj", "deformers": "many.json"}'
  cli_expect 2 info "$work/scene.json"
  expect_in "$work/stderr" "many.json:1:15: deformers: 200 deformers"
  write_geometry_scene "$work" '{"type": "sweep_tubes", "deformers": "many.json"}'  # their sweeps' solves alone
  cli_expect 2 info "$work/scene.json"
  expect_in "$work/stderr" "many.json:1:15: deformers: 200 deformers on 0 vertices need about"
  cp scenes/sweeps/bunny_ear_bend.json "$work/ear.json"
  write_geometry_scene "$work" '{"type": "mesh", "file": "bunny.obj", "deformers": "ear.json"}'
  cli_expect 2 render "$work/scene.json" --max-memory 4M --quiet -o "$work/a.exr"
  expect_in "$work/stderr" "ear.json:1:15: deformers: deforming 13934 vertices needs about"
  expect_no_file "$work/a.exr"
}

# The slow ones (label long): large tessellations within their limits stay below them.
case_geometry_memory_long() {
  write_geometry_scene "$work/a" "$(octagon_patch '"tolerance": 1e-7, "max_segments": 4096,')"
  run_peak 2 render "$work/a/scene.json" --max-memory 1G --quiet -o "$work/a.exr"
  expect_peak_below 1024
  mkdir -p "$work/b"
  python3 - "$work/b/patches.bpt" <<'PY'
import random, sys
random.seed(1)
with open(sys.argv[1], "w") as f:
    f.write("8000\n")
    for p in range(8000):
        x, y = p % 100, p // 100
        f.write("3 3\n" + "".join("%.4f %.4f %.4f\n" % (x + i / 3, y + j / 3, random.random() * 0.3)
                                  for i in range(4) for j in range(4)))
PY
  write_geometry_scene "$work/b" '{"type": "mesh", "file": "patches.bpt"}'
  run_peak 0 render "$work/b/scene.json" --max-memory 1G --res 4x4 --quiet -o "$work/b.exr"
  expect_peak_below 1024
}

# ---- finite world and numeric failures -------------------------------------------------------------------

case_world_camera_beyond_limit() {  # each aborted the process inside Embree (exit 134)
  local look='"look_at": { "eye": [0, 0, -5], "target": [0, 0, 0] }'
  bad_scene 4 '  "camera": { "type": "perspective", "look_at": { "eye": [1e19, 0, -5], "target": [0, 0, 0] } },' 4 \
    "camera.look_at.eye" "1e18"
  cli_expect 2 depth "$work/scene/scene.json" -o "$work/range.png"
  expect_in "$work/stderr" "camera.look_at.eye" stderr
  expect_no_file "$work/range.png"
  bad_scene 4 "  \"camera\": { \"type\": \"perspective\", \"aperture_radius\": 1e19, $look }," 4 \
    "camera.aperture_radius" "1e+18"
  bad_scene 4 '  "camera": { "type": "perspective", "transform": { "translate": [0, 0, 1e30] } },' 4 \
    "camera.transform" "1e18"
  bad_scene 4 '  "camera": { "type": "orthographic", "width": 1e30, "transform": { "translate": [0, 0, 5] } },' 4 \
    "camera.width" "1e+18"
}

case_world_light_and_object_beyond_limit() {
  bad_scene 6 '  "lights": [ { "type": "spot", "position": [1e39, 0, 0], "target": [0, 0, 0] } ],' 6 \
    "lights[0].position" "1e18"
  bad_scene 6 '  "lights": [ { "type": "directional", "direction": [0, 0, 0] } ],' 6 "lights[0].direction" "non-zero"
  bad_scene 9 '      "material": "grey", "transform": { "translate": [1e30, 0, 0] },' 9 "objects[0].transform" "1e18"
  # A mesh 1e30 across: its triangle's area overflowed float in the area distribution (exit 1, no position).
  awk 'NR == 11 { print "        \"type\": \"mesh\", \"positions\": [[0, 0, 0], [1e30, 0, 0], [0, 1e30, 0]],"; next }
       NR == 12 { print "        \"triangles\": [[0, 1, 2]]"; next }
       { print }' "$work/scene/scene.json" >"$work/scene/mesh.json"
  mv "$work/scene/mesh.json" "$work/scene/scene.json"
  check_bad_scene "$work/scene" 10 "objects[0].shape" "1e18"
}

case_emission_overflow() {  # each failed in Distribution1D with exit 1 and no position
  bad_scene 5 '  "materials": { "grey": { "type": "diffuse", "emission": 1e300 } },' 5 "materials.grey.emission" "1e30"
  bad_scene 5 '  "materials": { "grey": { "type": "emissive", "radiance": 1e30, "scale": 1e30 } },' 5 \
    "materials.grey.scale" "1e30"
  bad_scene 6 '  "lights": [ { "type": "environment", "radiance": 1e30, "scale": 1e30 } ],' 6 "lights[0].scale" "1e30"
  bad_scene 3 '  "film": { "resolution": [16, 16], "spp": 1 }, "integrator": { "type": "preview", "ambient": 1e300 },' 3 \
    "integrator.ambient" "1e30"  # rendered black (inf times 0)
}

case_light_power_of_a_large_scene() {  # pi R^2 L of lights at infinity overflowed float: exit 1, no position
  mkdir -p "$work/scene"
  write_base_scene "$work/scene/base.json"
  awk 'NR == 6 { print "  \"lights\": [ { \"type\": \"environment\", \"radiance\": 1e20 }, { \"type\": \"directional\", \"direction\": [0, -1, 0], \"irradiance\": 1e20 } ],"; next }
       NR == 12 { print "        \"radius\": 1, \"center\": [0, 0, 0] } }, { \"material\": \"grey\", \"shape\": { \"type\": \"sphere\", \"center\": [9e17, 0, 0], \"radius\": 1e17"; next }
       { print }' "$work/scene/base.json" >"$work/scene/scene.json"
  cli_expect 0 render "$work/scene/scene.json" -o "$work/out.exr" --quiet
}

case_environment_map_overflow() {  # failed in Distribution1D with exit 1 and no position
  mkdir -p "$work/scene"
  # Radiance RGBE, 4x2 texels of mantissa 128 and exponent 255: 1.7e38 each.
  python3 - "$work/scene/huge.hdr" <<'PY'
import sys
with open(sys.argv[1], "wb") as f:
    f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n" + bytes([128, 128, 128, 255]) * 8)
PY
  oiiotool --pattern constant:color=3e38,3e38,3e38 4x2 3 -d float -o "$work/scene/huge.exr" ||
    fail "oiiotool could not write the test map"
  for map in huge.hdr huge.exr; do
    bad_scene 6 "  \"lights\": [ { \"type\": \"environment\", \"file\": \"$map\" } ]," 6 "lights[0].file" "1e30"
  done
}

case_negative_texels() {  # an environment map with negative pixels gave negative beauty pixels
  mkdir -p "$work/scene"
  oiiotool --pattern constant:color=0.5,-0.25,0.5 4x2 3 -d float -o "$work/scene/negative.exr" ||
    fail "oiiotool could not write the test map"
  bad_scene 6 '  "lights": [ { "type": "environment", "file": "negative.exr" } ],' 6 "lights[0].file" "negative"
  expect_in "$work/stderr" "negative.exr" stderr
  bad_scene 5 '  "materials": { "grey": { "type": "diffuse", "reflectance": { "texture": "negative.exr" } } },' 5 \
    "materials.grey.reflectance" "negative"
}

case_texture_bad_input() {  # texture mistakes are refused where they are written, before anything is read
  bad_scene 5 '  "materials": { "grey": { "type": "diffuse", "reflectance": { "type": "chekcer" } } },' 5 \
    "materials.grey.reflectance.type" 'unknown texture type "chekcer" (did you mean "checker"?)'
  bad_scene 5 '  "materials": { "grey": { "type": "diffuse", "reflectance": { "type": "image", "file": "a.png", "channel": "r" } } },' \
    5 "materials.grey.reflectance.channel" "a colour takes the image's RGB"
  bad_scene 5 '  "materials": { "grey": { "type": "diffuse", "reflectance": { "type": "checker", "projection": { "type": "planar", "axis": "w" } } } },' \
    5 "materials.grey.reflectance.projection.axis" 'unknown value "w"'
}

case_principled_bad_input() {  # principled materials: refused at the value, before anything is rendered
  bad_scene 5 '  "materials": { "grey": { "type": "principled", "metalic": 1 } },' 5 "materials.grey" \
    '"metalic"'
  expect_in "$work/stderr" 'did you mean "metallic"' stderr
  bad_scene 5 '  "materials": { "grey": { "type": "principled", "roughness": 1.5 } },' 5 "materials.grey.roughness" \
    "out of range"
  bad_scene 5 '  "materials": { "grey": { "type": "principled", "base_colour": { "type": "mix", "a": 0, "b": 1, "t": { "type": "field" } } } },' \
    5 "materials.grey.base_colour.t" "this texture reads a field, but the shape of object \"objects[0]\" (sphere) has none"
  bad_scene 5 '  "materials": { "grey": { "type": "principled", "normal_map": { "type": "image", "file": "missing.png" } } },' \
    5 "materials.grey.normal_map.file" "missing.png"
  # A uv mapping on a surface without uv (a blob group) is refused at the projection.
  local dir="$work/blob"
  mkdir -p "$dir"
  write_base_scene "$dir/base.json"
  awk 'NR == 5 { print "  \"materials\": { \"grey\": { \"type\": \"principled\", \"base_colour\": { \"type\": \"checker\", \"projection\": \"uv\" } } },"; next }
       /"type": "sphere",/ { print "        \"type\": \"blobs\", \"elements\": [ { \"center\": [0, 0, 0], \"radius\": 1 } ]"; next }
       /"radius": 1$/ { next }
       { print }' "$dir/base.json" >"$dir/scene.json"
  check_bad_scene "$dir" 5 "materials.grey.base_colour.projection" "this texture is mapped by uv, but the shape of object \"objects[0]\" (blobs) has no uv"
}

case_texture_nesting_bounded() {  # a deeply nested texture is an error (JSON itself may nest 256 levels)
  local deep='0.5' i
  for ((i = 0; i < 200; ++i)); do deep="{\"type\":\"invert\",\"value\":$deep}"; done
  bad_scene 5 "  \"materials\": { \"grey\": { \"type\": \"diffuse\", \"reflectance\": $deep } }," 5 \
    "materials.grey.reflectance.value.value" "textures nest more than 32 levels deep"
}

# ---- isosurfaces ----

# An isosurface (a gyroid cut by a ball) renders without NaN, counts its work, gives a range image and a closed mesh.
case_isosurface_render() {
  write_shape_scene "$work/scene" '        "type": "isosurface", "parameters": {"k": 4},' \
    '        "function": "sin(k*x)*cos(k*y) + sin(k*y)*cos(k*z) + sin(k*z)*cos(k*x)", "contained_by": {"sphere": {"radius": 1.2}}'
  local scene="$work/scene/scene.json"
  cli_expect 0 render "$scene" --spp 2 -o "$work/out.exr" --stats-json "$work/stats.json"
  grep -qE "NaN/Inf +0 samples" "$work/stderr" || { show_output; fail "samples were NaN"; }
  python3 - "$work/stats.json" <<'PY' || fail "the isosurface's work is not in the statistics"
import json, sys
stats = json.load(open(sys.argv[1]))
counters = stats["counters"]
assert counters.get("isosurface.evaluations", 0) > 0, counters
assert counters.get("isosurface.budget_exhausted", -1) == 0, counters
assert stats["geometry"]["isosurface"]["closest_hits"] > 0, stats["geometry"]
assert stats["non_finite_pixels"] == 0
PY
  cli_expect 0 depth "$scene" -o "$work/depth.png"
  [[ -s "$work/depth.png" ]] || fail "no range image"
  cli_expect 0 mesh "$scene" -o "$work/gyroid.obj" --depth 5
  python3 "$closed_mesh" "$work/gyroid.obj" || fail "the isosurface's mesh is not a closed, consistently oriented surface"
}

# Each function of the isosurface gallery meshes, by every polygoniser, as a closed surface of its genus: the rock and
# the smooth union are spheres, the twisted torus a torus (the gyroid cut by a ball has many handles: only closed).
case_isosurface_gallery_meshes() {
  local object method
  for object in "gyroid:" "rock:0" "twisted torus:1" "smooth union:0"; do
    for method in mc dc sdc; do
      cli_expect 0 mesh scenes/isosurfaces.json --object "${object%:*}" --method $method --depth 5 --error-samples 500 \
        -o "$work/m.obj"
      python3 "$closed_mesh" "$work/m.obj" ${object#*:} || fail "the $method mesh of ${object%:*} is not closed"
    done
  done
}

# isotrace mesh --method traced writes a placed triangle mesh in the world, where its placement puts it: each
# placement at its own transform, a mirroring one with its winding turned so that the front stays the front.
case_mesh_traced_placements_in_world_space() {
  cat >"$work/placed.json" <<'JSON'
{
  "isotrace": 1,
  "film": {"resolution": [8, 8], "spp": 1},
  "camera": {"type": "perspective", "fov": 40, "look_at": {"eye": [0, 0, 10], "target": [0, 0, 0]}},
  "materials": {"grey": {"type": "diffuse", "reflectance": 0.5}},
  "lights": [{"type": "environment", "radiance": 1}],
  "definitions": {"tile": {"material": "grey", "shape": {"type": "mesh",
    "positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2]]}}},
  "objects": [{"name": "tiles", "instance": "tile", "placements": [
    {"transform": {"translate": [5, 0, 0]}},
    {"transform": {"scale": [-2, 1, 1], "translate": [0, 3, 0]}}]}]
}
JSON
  cli_expect 0 mesh "$work/placed.json" --object 'tiles[0]' --method traced -o "$work/t0.obj" --quiet
  cli_expect 0 mesh "$work/placed.json" --object 'tiles[1]' --method traced -o "$work/t1.obj" --quiet
  python3 - "$work/t0.obj" "$work/t1.obj" <<'PY' || fail "the placed meshes are not where their placements put them"
import sys
def triangle(path):
    v = [tuple(float(x) for x in l.split()[1:4]) for l in open(path) if l.startswith("v ")]
    f = [l.split()[1:4] for l in open(path) if l.startswith("f ")]
    return [v[int(c.split("/")[0]) - 1] for c in f[0]]
def normal_z(t):
    (a, b, c) = t
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
t0, t1 = triangle(sys.argv[1]), triangle(sys.argv[2])
print(t0, t1)
ok = sorted(t0) == sorted([(5, 0, 0), (6, 0, 0), (5, 1, 0)]) and normal_z(t0) > 0
ok = ok and sorted(t1) == sorted([(0, 3, 0), (-2, 3, 0), (0, 4, 0)]) and normal_z(t1) > 0
sys.exit(0 if ok else 1)
PY
}

# Isosurfaces and emissive ellipsoids placed from definitions render, in every AOV, exactly as the same objects
# written out separately, beside the round primitives, an infinite plane and a rectangle light; the emissive
# placements are area lights, as the separate objects are (the rectangle and two ellipsoids).
case_instanced_isosurfaces_match_separate_objects() {
  local scene
  for scene in instanced separate; do
    cli_expect 0 render tests/cli/data/surfaces/$scene.json --quiet --aov all -o "$work/$scene.exr"
    cli_expect 0 info tests/cli/data/surfaces/$scene.json
    expect_in "$work/stdout" "of which 3 area light(s)" stdout
  done
  idiff -fail 0 -failpercent 0 -warn 0 "$work/instanced.exr" "$work/separate.exr" >"$work/idiff" 2>&1 ||
    { cat "$work/idiff" >&2; fail "the placements render other pixels than the same objects written out separately"; }
}

# An isosurface without a container gets one where interval arithmetic proves the function positive outside a
# cube (a ball, a noisy ball); one whose surface is unbounded (a gyroid, a plane), or that has field terms, needs
# "contained_by" and exits 2 at its position.
case_isosurface_derived_container() {
  local function
  for function in 'length(p) - 0.5' 'length(p) - 0.5 + 0.05*fbm(8*p)'; do
    write_shape_scene "$work/scene" '        "type": "isosurface",' "        \"function\": \"$function\""
    cli_expect 0 render "$work/scene/scene.json" --quiet -o "$work/derived.exr"
    cli_expect 0 info "$work/scene/scene.json"
    expect_in "$work/stdout" "isosurface" stdout
  done
  for function in 'sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)' 'z'; do
    write_shape_scene "$work/scene" '        "type": "isosurface",' "        \"function\": \"$function\""
    check_bad_scene "$work/scene" 10 "objects[0].shape" "contained_by"
    expect_in "$work/stderr" "cannot prove" stderr
  done
  write_shape_scene "$work/scene" '        "type": "isosurface",' \
    '        "function": "ball(p)", "fields": {"ball": {"type": "sphere"}}'
  check_bad_scene "$work/scene" 10 "objects[0].shape" "with field terms needs \"contained_by\""
}

# Bad isosurfaces exit 2 at their position: an empty container, a container without surface, an
# unknown name in the function (with a suggestion), a field the function does not use, terms nested too deep.
case_isosurface_bad_input() {
  local function='"function": "length(p) - r", "parameters": {"r": 0.5}'
  write_shape_scene "$work/scene" '        "type": "isosurface",' \
    "        $function, \"contained_by\": {\"box\": {\"min\": [-1, -1, 0], \"max\": [1, 1, 0]}}"
  check_bad_scene "$work/scene" 12 "objects[0].shape.contained_by.box.max" "hold nothing"
  write_shape_scene "$work/scene" '        "type": "isosurface",' \
    "        $function, \"contained_by\": {\"box\": {\"min\": [2, 2, 2], \"max\": [3, 3, 3]}}"
  check_bad_scene "$work/scene" 12 "objects[0].shape.contained_by" "no surface"
  write_shape_scene "$work/scene" '        "type": "isosurface",' \
    '        "function": "lenght(p) - 0.5", "contained_by": {"sphere": {"radius": 1}}'
  check_bad_scene "$work/scene" 12 "objects[0].shape.function" "length"
  write_shape_scene "$work/scene" '        "type": "isosurface",' \
    '        "function": "length(p) - 0.5", "fields": {"ball": {"type": "sphere"}}, "contained_by": {"sphere": {"radius": 1}}'
  check_bad_scene "$work/scene" 12 "objects[0].shape.fields.ball" "does not use"
  local inner='{"type": "sphere"}' i
  for ((i = 0; i < 5; ++i)); do
    inner="{\"type\": \"isosurface\", \"function\": \"f(p)\", \"fields\": {\"f\": $inner}, \"contained_by\": {\"sphere\": {\"radius\": 2}}}"
  done
  write_shape_scene "$work/scene" '        "type": "isosurface",' \
    "        \"function\": \"f(p)\", \"fields\": {\"f\": $inner}, \"contained_by\": {\"sphere\": {\"radius\": 2}}"
  check_bad_scene "$work/scene" 12 "fields" "nest more than 4"
}

case_tiny_roughness_no_nan() {  # roughness 1e-5 under an environment made a third of the samples NaN
  mkdir -p "$work/scene"
  write_base_scene "$work/scene/base.json"
  awk -v sky="$PWD/scenes/data/sky.exr" '
    NR == 3 { print "  \"film\": { \"resolution\": [16, 16], \"spp\": 1 }, \"integrator\": { \"type\": \"path\" },"; next }
    NR == 5 { print "  \"materials\": { \"grey\": { \"type\": \"conductor\", \"metal\": \"Au\", \"roughness\": 1e-5 } },"; next }
    NR == 6 { print "  \"lights\": [ { \"type\": \"environment\", \"file\": \"" sky "\" } ],"; next }
    { print }' "$work/scene/base.json" >"$work/scene/scene.json"
  cli_expect 0 render "$work/scene/scene.json" --spp 4 -o "$work/out.exr"
  grep -qE "NaN/Inf +0 samples" "$work/stderr" || { show_output; fail "samples were NaN"; }
}

case_depth_non_finite_range() {  # wrote a black PNG with exit 0
  mkdir -p "$work/scene"
  write_base_scene "$work/scene/scene.json"
  cli_expect 2 depth "$work/scene/scene.json" -o "$work/range.png" --near -inf --far inf
  expect_in "$work/stderr" "--near: must be a finite depth" stderr
  cli_expect 2 depth "$work/scene/scene.json" -o "$work/range.png" --near 1 --far 1e39
  expect_in "$work/stderr" "--far: must be a finite depth" stderr
  cli_expect 2 depth "$work/scene/scene.json" -o "$work/range.png" --near nan
  expect_in "$work/stderr" "--near" stderr
  expect_no_file "$work/range.png"
}

# ---- scene authoring: comments, trailing commas, includes, --set -------------------------------------------

authoring=tests/cli/data/authoring
authoring_sets=(--set film.spp=4 --set values.fov=30 --set materials.gold.roughness=0.2 --set 'objects.dog.material="gold"')

# A scene with comments, trailing commas, includes (whose mesh path resolves beside the included file) and a named
# value, with --set values, renders exactly as its plain equivalent; the overrides are in the metadata and the hash.
case_authoring_equivalent() {
  cli_expect 0 render "$authoring/plain.json" --quiet -o "$work/plain.exr"
  cli_expect 0 render "$authoring/authored.json" "${authoring_sets[@]}" --quiet -o "$work/authored.exr"
  idiff -fail 0 -failpercent 0 -warn 0 "$work/plain.exr" "$work/authored.exr" >"$work/idiff" 2>&1 ||
    { cat "$work/idiff" >&2; fail "the authored scene renders differently from its plain equivalent"; }
  cli_expect 0 render "$authoring/authored.json" --spp 4 --quiet -o "$work/no_set.exr"
  ! idiff -fail 0 "$work/plain.exr" "$work/no_set.exr" >/dev/null 2>&1 || fail "the --set values changed nothing"
  exr_info "$work/authored.exr" "$work/info"
  expect_in "$work/info" 'isotrace:set: "[\"film.spp=4\",\"values.fov=30\",\"materials.gold.roughness=0.2\",\"objects.dog.material=\\\"gold\\\"\"]"'
  exr_info "$work/no_set.exr" "$work/info"
  ! grep -q "isotrace:set" "$work/info" || fail "isotrace:set written without --set"
  # The hash covers the included files and the --set values; --spp (recorded on its own) leaves it alone.
  cli_expect 0 info "$authoring/authored.json"
  expect_in "$work/stdout" "the scene file and 3 referenced file(s)"
  local plain_hash set_hash spp_hash changed_hash
  plain_hash=$(sed -n 's/^scene hash *\([0-9a-f]*\).*/\1/p' "$work/stdout")
  cli_expect 0 info "$authoring/authored.json" --set camera.fov=30
  set_hash=$(sed -n 's/^scene hash *\([0-9a-f]*\).*/\1/p' "$work/stdout")
  [[ $set_hash != "$plain_hash" ]] || fail "--set does not change the scene hash"
  cp -r "$authoring" "$work/copy"
  cli_expect 0 info "$work/copy/authored.json"
  [[ $(sed -n 's/^scene hash *\([0-9a-f]*\).*/\1/p' "$work/stdout") == "$plain_hash" ]] || fail "a copy has another hash"
  echo '// changed' >>"$work/copy/lib/materials.json"
  cli_expect 0 info "$work/copy/authored.json"
  changed_hash=$(sed -n 's/^scene hash *\([0-9a-f]*\).*/\1/p' "$work/stdout")
  [[ $changed_hash != "$plain_hash" ]] || fail "a changed included file does not change the scene hash"
  # An output may not replace an included file.
  cli_expect 2 render "$work/copy/authored.json" --spp 1 --quiet -o "$work/copy/out.exr" \
    --stats-json "$work/copy/lib/materials.json"
  expect_in "$work/stderr" "an output may not replace an input" stderr
  # Every command that loads a scene takes --set (and says so in its help); a reference can be made again with them.
  local command
  for command in render info depth mesh; do
    cli_expect 0 "$command" --help
    expect_in "$work/stdout" "--set" "$command --help output"
  done
  cli_expect 0 render "$authoring/authored.json" --reference --spp 4 --res 8x6 --set "description=it's" --quiet \
    -o "$work/reference.exr"
  exr_info "$work/reference.exr" "$work/info"
  expect_in "$work/info" "--reference --res 8x6 --seed 0 --set 'description=it'\\\\''s' --spp 4"
  cli_expect 0 depth "$authoring/authored.json" --set camera.fov=20 -o "$work/range.png" --quiet
  cli_expect 0 mesh "$authoring/authored.json" --set 'objects.ball.shape.radius=0.4' --object ball --depth 3 \
    -o "$work/ball.obj" --quiet
  cli_expect 2 mesh "$authoring/authored.json" --set 'objects.ball.shape.radius=-1' --object ball -o "$work/b.obj"
  expect_in "$work/stderr" "--set objects.ball.shape.radius=-1:1:33: objects[1].shape.radius" stderr
}

# Errors inside included files name the file, line and column; bad includes are reported at the include string.
case_authoring_include_errors() {
  mkdir -p "$work/s/lib"
  printf '{\n  "materials": {"grey": {"type": "diffuse",\n    "reflectanse": 0.5}},\n}\n' >"$work/s/lib/bad_key.json"
  printf '{\n  "include": [\n    "lib/%s"\n  ],\n  "isotrace": 1,\n  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},\n}\n' \
    bad_key.json >"$work/s/scene.json"
  cli_expect 2 render "$work/s/scene.json" --quiet -o "$work/s/out.exr"
  expect_in "$work/stderr" "$work/s/lib/bad_key.json:3:20: materials.grey.reflectanse: unknown key" stderr
  expect_in "$work/stderr" 'did you mean "reflectance"' stderr
  include_fails() {  # include_fails <included file's text or "" for none> <expected text>
    rm -f "$work/s/lib/included.json"
    [[ -z $1 ]] || printf '%s' "$1" >"$work/s/lib/included.json"
    printf '{\n  "include": [\n    "lib/%s"\n  ],\n  "isotrace": 1,\n  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},\n}\n' \
      included.json >"$work/s/scene.json"
    cli_expect 2 render "$work/s/scene.json" --quiet -o "$work/s/out.exr"
    sed 's/^/  stderr: /' "$work/stderr" >&2
    expect_in "$work/stderr" "$work/s/scene.json:3:5: include: cannot include \"lib/included.json\": " stderr
    expect_in "$work/stderr" "$2" stderr
    expect_no_file "$work/s/out.exr"
  }
  include_fails "" "lib/included.json: file not found"
  include_fails '{"a": tru}' "lib/included.json:1:7: expected a JSON value but found 't'"
  include_fails '[1, 2]' "expected an object of scene sections, found array"
  include_fails '/* never closed' "lib/included.json:1:1: unterminated comment"
  # A cycle is reported at the include that closes it.
  printf '{"include": "../scene.json"}' >"$work/s/lib/included.json"
  cli_expect 2 render "$work/s/scene.json" --quiet -o "$work/s/out.exr"
  expect_in "$work/stderr" "$work/s/lib/included.json:1:13: include: cannot include \"../scene.json\": include cycle: \
$work/s/scene.json -> $work/s/lib/included.json -> $work/s/lib/../scene.json" stderr
}

# --set paths and values are checked: did-you-mean for unknown keys, positions in the option, exit 2.
case_authoring_set_errors() {
  set_fails() {  # set_fails <expected text> <arguments...>
    local text=$1
    shift
    cli_expect 2 render "$authoring/authored.json" --quiet -o "$work/out.png" "$@"
    sed 's/^/  stderr: /' "$work/stderr" >&2
    expect_in "$work/stderr" "$text" stderr
    expect_no_file "$work/out.png"
  }
  set_fails '--set flim.spp=3:1:7: no key "flim" in the scene (did you mean "film"?)' --set flim.spp=3
  set_fails '--set film.sp=256:1:15: film.sp: unknown key "sp" (did you mean "spp"?)' --set film.sp=256
  set_fails '--set objects.dgo.material=1:1:15: no element of "objects" is named "dgo" (did you mean "dog"?)' \
    --set objects.dgo.material=1
  set_fails '--set objects.7.material=1:1:15: no element 7 in "objects"' --set objects.7.material=1
  set_fails '--set: expected PATH=VALUE' --set film.spp
  set_fails '--set film.spp=abc:1:16: film.spp: expected a number, found string' --set film.spp=abc
  set_fails '--set film.resolution=[0, 4]:1:24: film.resolution[0]: value 0 out of range' --set 'film.resolution=[0, 4]'
  set_fails "--set film.resolution=[1, 2:1:28: film.resolution: expected ',' or ']'" --set 'film.resolution=[1, 2'
  set_fails '--set objects.ball.material="nope":1:29: objects[1].material: unknown material "nope"' \
    --set 'objects.ball.material="nope"'
  set_fails '--set integrator.type=pth:1:23: integrator.type: unknown integrator type "pth" (did you mean "path"?)' \
    --set integrator.type=pth
  set_fails '--set camera.fov={"$value": "fv"}:1:29: camera.fov: unknown value "fv" (did you mean "fov"?)' \
    --set 'camera.fov={"$value": "fv"}'
  set_fails '--set values.fov=400:1:18: camera.fov: ' --set values.fov=400
  set_fails '--view ACES 1.0 SDR Video: film.view: unknown view "ACES 1.0 SDR Video" of display "sRGB" (did you mean "ACES 1.0 - SDR Video"?)' \
    --view 'ACES 1.0 SDR Video'
  set_fails '--display sRBG: film.display: unknown display "sRBG" (did you mean "sRGB"?)' --display sRBG
  set_fails '--spp: Value 0 not in range' --spp 0
  cli_expect 0 render "$authoring/authored.json" --quiet -o "$work/out.png" --spp 1 --res 8x6 \
    --display sRGB --view Un-tone-mapped
  cli_expect 2 info "$authoring/authored.json" --set film.spp=0
  expect_in "$work/stderr" "--set film.spp=0:1:16: film.spp: value 0 out of range" stderr
}

# A checkpoint remembers the --set values: a resume with other ones is refused, one without them takes them.
case_authoring_resume_set() {
  cp "$cornell" "$work/scene.json"
  cli_expect 0 render "$work/scene.json" --res 16x16 --spp 100000 --time 0.2 --quiet -o "$work/a.exr" \
    --checkpoint "$work/ck.bin" --set camera.fov=30
  [[ -s "$work/ck.bin" ]] || fail "no checkpoint after a time budget ended the render"
  cli_expect 2 render "$work/scene.json" --resume "$work/ck.bin" --quiet -o "$work/b.exr" --set camera.fov=31
  expect_in "$work/stderr" "--set camera.fov=31 differs from the checkpoint's --set camera.fov=30" stderr
  expect_no_file "$work/b.exr"
  cli_expect 0 render "$work/scene.json" --resume "$work/ck.bin" --quiet -o "$work/b.exr" --time 0.1
  exr_info "$work/b.exr" "$work/info"
  expect_in "$work/info" 'isotrace:set: "[\"camera.fov=30\"]"'
}

# ---- dispatch --------------------------------------------------------------------------------------------

if [[ $(type -t "case_$case_name") != function ]]; then
  echo "unknown case \"$case_name\"; cases:" >&2
  declare -F | sed -n 's/^declare -f case_/  /p' >&2
  exit 64
fi
"case_$case_name"
echo "PASS [$case_name]"
