#!/bin/bash
# User-facing text (README.md, docs/*.md, the plugin READMEs, the CLI's help and messages in tools/cli) names no
# work-log numbering or ticket numbers: no sessions, issue numbers, "seed 003" / "seed N" (the source papers are
# cited by authors and title), and no equation numbers. A random-number seed (`--seed 7`, "seed": 0, "seed 2")
# is not a paper's seed and passes.
# Usage: user_text_test.sh SOURCE_DIR
set -u
root=$1
cd "$root" || exit 2

files=$( { ls README.md docs/*.md tools/cli/*.cpp tools/cli/*.h; find renderer geometry integrators -name README.md; } | sort)

# name|regex (Perl, case-insensitive)
patterns=(
  'a work session|\bsessions?\b'
  'an issue or ticket number|\b(issues?|tickets?|bugs?|pull requests?|PRs?)\s*#?\s*\d+'
  'a ticket reference (#N)|(^|[\s(\[])#\d+\b(?![;"\w])'
  'a seed paper number (seed 003, seed N)|(?<![-\w"])seeds?\s+(0\d\d|N)\b'
  'an equation number|\beqs?\b\.?\s*\(?\s*\d|\bequations?\s*\(?\s*\d|\bformulae?\s*\(\d+\)'
)
# Exact phrases where a pattern's word means something else (removed from a line before it is matched).
allowed=(
  'each session gets a fair share'  # Linux scheduler autogroups, not a work session
  'GCC PR '                         # a compiler's bug tracker, not this project's
  'tests after about #'             # CTest's test numbers
)

hits=0
for file in $files; do
  for entry in "${patterns[@]}"; do
    what=${entry%%|*}
    regex=${entry#*|}
    while IFS= read -r line; do
      number=${line%%:*}
      text=${line#*:}
      for phrase in "${allowed[@]}"; do text=${text//"$phrase"/}; done
      if printf '%s\n' "$text" | grep -qiP -- "$regex"; then
        printf '%s:%s: %s: %s\n' "$file" "$number" "$what" "$(printf '%s' "$text" | cut -c1-160)"
        hits=$((hits + 1))
      fi
    done < <(grep -niP -- "$regex" "$file")
  done
done
if [ "$hits" -gt 0 ]; then
  echo "FAIL: $hits line(s) of user-facing text name work-log or ticket numbering (cite papers by authors and title)"
  exit 1
fi
echo "ok: $(echo "$files" | wc -l) files checked"
