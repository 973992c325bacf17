#!/bin/bash
# Runs check_layering.py on a fixture tree that breaks the layering and passes only when the check fails (exit 1)
# and prints every expected line (extended regular expressions), so that the layering test is shown to fail.
# Usage: expect_layering_failure.sh PYTHON CHECK_SCRIPT FIXTURE_DIR REGEX...
set -u
python=$1 check=$2 fixture=$3
shift 3
output=$("$python" "$check" "$fixture")
status=$?
echo "$output"
[ "$status" -eq 1 ] || { echo "FAIL: expected exit 1 from the layering check on $fixture, got $status"; exit 1; }
for expected in "$@"; do
  grep -Eq -- "$expected" <<<"$output" || { echo "FAIL: the layering check did not report: $expected"; exit 1; }
done
echo "PASS: the layering check fails on $fixture as expected"
