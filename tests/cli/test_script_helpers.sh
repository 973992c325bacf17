# Helpers of the end-to-end test scripts (tests/cli/cli_test.sh, renderer/distributed/distributed_test.sh), sourced
# once they have set $case_name: $work, a temporary directory removed on exit, and the reporting helpers.

# Instrumented builds run 3-15 times slower: the scripts' bounds on waiting for an event are multiplied by this
# (CTest sets it from cmake/Sanitizers.cmake, like its own time limits; 1 when a script is run by hand).
time_scale=${ISOTRACE_TEST_TIMEOUT_SCALE:-1}
# 1 in instrumented builds (cmake/Sanitizers.cmake): their shadow memory and quarantine are not isotrace's, so a
# run's peak resident memory is not held to isotrace's bounds there.
instrumented=${ISOTRACE_TEST_INSTRUMENTED:-0}

work=$(mktemp -d "${TMPDIR:-/tmp}/isotrace-test.XXXXXX")
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL [$case_name]: $*" >&2
  exit 1
}

# run <stdout file> <stderr file> <command...>: runs the command, sets $status, never fails the script.
run() {
  local out=$1 err=$2
  shift 2
  echo "+ $*" >&2
  status=0
  "$@" >"$out" 2>"$err" || status=$?
}

show_output() {
  echo "--- stdout:" >&2
  cat "$work/stdout" >&2 || true
  echo "--- stderr:" >&2
  cat "$work/stderr" >&2 || true
}
