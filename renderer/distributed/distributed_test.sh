#!/usr/bin/env bash
# End-to-end tests of distributed rendering: isotrace under mpirun with 2 ranks on this machine.
#   distributed_test.sh <isotrace binary> <source dir> <mpirun> <case>
# Renders are small (32x32 to 64x64) so that the cases stay in the default test run.
set -euo pipefail

(($# == 4)) || { echo "usage: $0 <isotrace binary> <source dir> <mpirun> <case>" >&2; exit 64; }
cli=$1 source_dir=$2 mpirun=$3 case_name=$4
cd "$source_dir"
# $work, $time_scale, fail, run, show_output
source "$source_dir/tests/cli/test_script_helpers.sh"
cornell=scenes/cornell_box.json
scene=$cornell  # what expect_identical_to_one_process renders
# Test machines and containers often run as root, which Open MPI refuses unless told.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Two ranks on however few cores: one thread each, no binding to cores.
mpi=("$mpirun" --oversubscribe --bind-to none)
# Under AddressSanitizer (tools/test --sanitize address,undefined) the ranks run without leak checking: Open MPI
# 4.1 leaks ~120 KB at exit in its own allocations (hwloc bitmaps, opal_argv, ompi_op_base_op_select, and its MCA
# components, which it unloads first, so their stacks show only "<unknown module>" and no suppression can name
# them). Memory errors and UBSan still stop the ranks; the single-process renders beside them keep leak checks.
if [[ -n ${ASAN_OPTIONS:-} ]]; then
  mpi=(env "ASAN_OPTIONS=$ASAN_OPTIONS:detect_leaks=0" "${mpi[@]}")
fi

expect_status() {  # expect_status <code> <what>
  ((status == $1)) || { show_output; fail "$2 exited with $status, expected $1"; }
}

expect_failure() {  # expect_failure <what>
  ((status != 0)) || { show_output; fail "$1 succeeded but should have failed"; }
}

expect_in_stderr() {
  grep -qF -- "$1" "$work/stderr" || { show_output; fail "stderr does not contain \"$1\""; }
}

expect_no_outputs() {  # nothing written: neither the image nor a temporary file of it
  local leftovers
  leftovers=$(find "$work" -name '*.exr' -o -name '*.partial*' | tr '\n' ' ')
  [[ -z "$leftovers" ]] || fail "files written: $leftovers"
}

identical() {  # identical <a.exr> <b.exr> <what>
  idiff -fail 0 -failpercent 0 -warn 0 "$1" "$2" >"$work/idiff" 2>&1 || { cat "$work/idiff" >&2; fail "$3"; }
}

json_value() {  # json_value <file> <python expression on j>
  python3 -c "import json,sys; j=json.load(open(sys.argv[1])); print($2)" "$1"
}

# The single-process render of $scene and the 2-rank render with the given arguments: the same pixels, the same rays, and
# statistics from both ranks.
expect_identical_to_one_process() {
  run "$work/stdout" "$work/stderr" "$cli" render "$scene" --quiet --threads 2 "$@" -o "$work/one.exr" --stats-json "$work/one.json"
  expect_status 0 "the single-process render"
  run "$work/stdout" "$work/stderr" "${mpi[@]}" -np 2 "$cli" render "$scene" --quiet --threads 1 "$@" -o "$work/two.exr" \
    --stats-json "$work/two.json"
  expect_status 0 "mpirun -np 2 isotrace render $*"
  identical "$work/one.exr" "$work/two.exr" "2 ranks ($*) give other pixels than one process"
  [[ $(json_value "$work/two.json" 'len(j["ranks"])') == 2 ]] || fail "the statistics do not list 2 ranks"
  [[ $(json_value "$work/two.json" 'min(r["items"] for r in j["ranks"]) > 0') == True ]] ||
    fail "a rank rendered nothing: $(json_value "$work/two.json" 'j["ranks"]')"
  [[ $(json_value "$work/one.json" 'j["rays_total"]') == $(json_value "$work/two.json" 'j["rays_total"]') ]] ||
    fail "the ranks' rays do not add up to the single process's"
}

# ---- cases -----------------------------------------------------------------------------------------------

# 80 spp: blocks of 32, 32 and 16 samples, so the last block is partial.
case_identical_samples() {
  expect_identical_to_one_process --res 32x32 --spp 80 --tile-size 8 --distribute samples
}

case_identical_tiles() {
  expect_identical_to_one_process --res 32x32 --spp 40 --tile-size 8 --distribute tiles
  # A single-process render stopped mid-pass by its time budget (pixels with different sample counts), finished by
  # 2 ranks: each region goes on from its pixels' counts.
  local arguments=("$cornell" --res 32x32 --spp 1024 --quiet)
  run "$work/stdout" "$work/stderr" "$cli" render "${arguments[@]}" --threads 1 --time 0.2 \
    --checkpoint "$work/ck.bin" -o "$work/stopped.exr"
  expect_status 0 "the render stopped by its time budget"
  [[ -f "$work/ck.bin" ]] || fail "the render stopped by its time budget left no checkpoint"
  # The samples split refuses it unless the budget happened to end with every pixel at a multiple of 32 samples.
  local counts
  counts=$(python3 -c 'import json, struct, sys
data = open(sys.argv[1], "rb").read()
film = json.loads(data[32:32 + struct.unpack_from("<Q", data, 16)[0]])["film"]
print(film["completed_spp"], film["max_spp"])' "$work/ck.bin")
  run "$work/stdout" "$work/stderr" "${mpi[@]}" -np 2 "$cli" render "$cornell" --quiet --distribute samples \
    --resume "$work/ck.bin" -o "$work/refused.exr"
  if [[ ${counts% *} == "${counts#* }" ]] && ((${counts% *} % 32 == 0)); then
    expect_status 0 "the samples split resuming a checkpoint at ${counts% *} spp"
  else
    expect_status 2 "the samples split resuming a checkpoint with $counts spp"
    expect_in_stderr "finish it with --distribute tiles"
  fi
  run "$work/stdout" "$work/stderr" "${mpi[@]}" -np 2 "$cli" render "$cornell" --quiet --threads 1 --tile-size 8 \
    --resume "$work/ck.bin" -o "$work/resumed.exr"
  expect_status 0 "2 ranks resuming a mid-pass checkpoint"
  run "$work/stdout" "$work/stderr" "$cli" render "${arguments[@]}" --threads 2 -o "$work/uninterrupted.exr"
  expect_status 0 "the uninterrupted render"
  identical "$work/uninterrupted.exr" "$work/resumed.exr" "2 ranks finishing a mid-pass checkpoint give other pixels"
}

# Every AOV (ids, depth, variance, sample counts) through both merges.
case_identical_aovs() {
  expect_identical_to_one_process --res 32x24 --spp 72 --tile-size 8 --aov all --distribute samples
  expect_identical_to_one_process --res 32x24 --spp 72 --tile-size 8 --aov all --distribute tiles
}

# Isosurfaces placed as instances, the round primitives, an infinite plane and a rectangle light, with every AOV.
case_identical_surfaces() {
  scene=tests/cli/data/surfaces/instanced.json
  expect_identical_to_one_process --res 32x24 --spp 40 --tile-size 8 --aov all --distribute samples
  expect_identical_to_one_process --res 32x24 --spp 16 --tile-size 8 --aov all --distribute tiles
}

# A rank killed mid-render: the job fails naming the rank, writes no image, and its checkpoint resumes (under
# MPI again) to the pixels of an uninterrupted render.
case_killed_rank() {
  local arguments=("$cornell" --res 48x48 --spp 320 --tile-size 16 --distribute samples)
  "${mpi[@]}" -np 2 "$cli" render "${arguments[@]}" --threads 1 -o "$work/killed.exr" \
    --checkpoint "$work/ck.bin" --checkpoint-every 0.1 >"$work/stdout" 2>"$work/stderr" &
  local launcher=$! rank1="" waited
  for waited in $(seq $((100 * time_scale))); do  # until rank 1 runs and a checkpoint exists (10 s at most, scaled)
    rank1=$(grep -lz '^OMPI_COMM_WORLD_RANK=1$' /proc/[0-9]*/environ 2>/dev/null |
      while read -r environ; do
        pid=${environ#/proc/}
        pid=${pid%/environ}
        tr '\0' ' ' <"/proc/$pid/cmdline" 2>/dev/null | grep -qF "$work/killed.exr" && echo "$pid"
      done | head -n 1 || true)
    [[ -n "$rank1" && -f "$work/ck.bin" ]] && break
    sleep 0.1
  done
  [[ -n "$rank1" && -f "$work/ck.bin" ]] || { kill "$launcher"; wait "$launcher" || true; fail "no rank 1 or no checkpoint after $((10 * time_scale)) s"; }
  kill -KILL "$rank1"
  status=0
  wait "$launcher" || status=$?
  expect_failure "mpirun with a killed rank"
  expect_in_stderr "rank 1"
  [[ ! -e "$work/killed.exr" ]] || fail "an image was written by a render that lost a rank"
  [[ -z $(find "$work" -name '*.exr.partial*' -o -name '.killed*') ]] || fail "temporary output files were left"
  cat "$work/stderr" >&2

  run "$work/stdout" "$work/stderr" "$cli" render "${arguments[@]}" --threads 2 --quiet -o "$work/one.exr"
  expect_status 0 "the uninterrupted single-process render"
  run "$work/stdout" "$work/stderr" "${mpi[@]}" -np 2 "$cli" render "${arguments[@]}" --threads 1 --quiet --resume "$work/ck.bin" -o "$work/resumed.exr"
  expect_status 0 "the resumed 2-rank render"
  identical "$work/one.exr" "$work/resumed.exr" "the resumed render differs from the uninterrupted one"
}

case_bad_input() {
  # More ranks than work: 16 spp is one block of samples.
  run "$work/stdout" "$work/stderr" "${mpi[@]}" -np 2 "$cli" render "$cornell" --res 16x16 --spp 16 --quiet --distribute samples -o "$work/a.exr"
  expect_status 2 "2 ranks for one block"
  expect_in_stderr "2 ranks but the work divides into only 1 block of samples"
  # A rank that cannot load its scene (MPMD: rank 1 is given a broken file).
  printf '{"camera": ' >"$work/broken.json"
  run "$work/stdout" "$work/stderr" "${mpi[@]}" -np 1 "$cli" render "$cornell" --res 16x16 --spp 4 --quiet -o "$work/a.exr" : \
    -np 1 "$cli" render "$work/broken.json" --res 16x16 --spp 4 --quiet -o "$work/a.exr"
  expect_status 2 "a rank that cannot read its scene"
  expect_in_stderr "rank 1 (on $(hostname)) could not load the scene"
  # Another scene, or another option that changes pixels, on one rank.
  run "$work/stdout" "$work/stderr" "${mpi[@]}" -np 1 "$cli" render "$cornell" --res 16x16 --spp 4 --quiet -o "$work/a.exr" : \
    -np 1 "$cli" render "$cornell" --res 16x16 --spp 4 --seed 7 --quiet -o "$work/a.exr"
  expect_status 2 "ranks with different seeds"
  expect_in_stderr "rank 1 (on $(hostname)) loaded another scene than rank 0"
  # Another isotrace build on one rank: the same executable with one byte more.
  cp "$cli" "$work/other-isotrace"
  printf 'x' >>"$work/other-isotrace"
  run "$work/stdout" "$work/stderr" "${mpi[@]}" -np 1 "$cli" render "$cornell" --res 16x16 --spp 4 --quiet -o "$work/a.exr" : \
    -np 1 "$work/other-isotrace" render "$cornell" --res 16x16 --spp 4 --quiet -o "$work/a.exr"
  expect_status 2 "ranks running different builds"
  expect_in_stderr "rank 1 (on $(hostname)) runs another isotrace build than rank 0"
  rm "$work/other-isotrace"
  # Another command on one rank: each waited for the other's messages forever.
  run "$work/stdout" "$work/stderr" timeout $((60 * time_scale)) "${mpi[@]}" -np 1 "$cli" render "$cornell" --res 16x16 \
    --spp 4 --quiet -o "$work/a.exr" : -np 1 "$cli" bench --quick --filter cornell_box/primary --threads 1
  expect_status 2 "ranks running different commands"
  expect_in_stderr "rank 1 runs \"isotrace bench\""
  # A time budget cannot be shared by the ranks.
  run "$work/stdout" "$work/stderr" "${mpi[@]}" -np 2 "$cli" render "$cornell" --res 16x16 --time 5 --quiet -o "$work/a.exr"
  expect_status 2 "--time under MPI"
  expect_in_stderr "--time"
  expect_no_outputs
  # Nor interim outputs: the last checkpoint of a stopped job must be the checkpoint.
  run "$work/stdout" "$work/stderr" "${mpi[@]}" -np 2 "$cli" render "$cornell" --res 16x16 --write-every 1 --quiet \
    -o "$work/a.exr"
  expect_status 2 "--write-every under MPI"
  expect_in_stderr "--write-every: is not available in a distributed render"
  expect_no_outputs
}

case_bench() {
  run "$work/stdout" "$work/stderr" "${mpi[@]}" -np 2 "$cli" bench --quick --filter cornell_box/primary --threads 1 --json "$work/bench.json"
  expect_status 0 "mpirun -np 2 isotrace bench"
  [[ $(json_value "$work/bench.json" 'j["mpi"]["ranks"]') == 2 ]] || fail "the report does not say 2 ranks"
  [[ $(json_value "$work/bench.json" 'len(j["mpi"]["workloads"][0]["runs"][0]["per_rank"])') == 2 ]] ||
    fail "the report does not have both ranks' throughput"
  grep -qF "Aggregate of 2 ranks" "$work/stdout" || { show_output; fail "the table does not show the aggregate of 2 ranks"; }
}

"case_$case_name"
