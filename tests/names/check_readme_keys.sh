#!/usr/bin/env bash
# Checks that a stage's README lists all of its keys: the table of its "## Keys" section
# ("| `KEYS` | what they do |") is, row for row, the key list the program's --help
# prints, which stage_keys_test checks against what the keys really do.
#
# usage: check_readme_keys.sh PROGRAM README    exit 0 when they agree, else 1 with the
#        two lists
set -uo pipefail
program=${1:?usage: check_readme_keys.sh PROGRAM README} readme=${2:?usage: check_readme_keys.sh PROGRAM README}

# --help: the lines after "The keys of this stage ..." that start with two spaces,
# "  KEYS  meaning" with two spaces or more between.
help=$("$program" --help) || { echo "FAILED: $program --help did not run"; exit 1; }
from_help=$(awk '/^The keys of this stage/{p=1; next} p && /^  /{sub(/^  /, ""); print; next} p{exit}' <<<"$help" |
  sed -E 's/  +/\t/')
# The README: the table rows of its Keys section.
from_readme=$(awk '/^## Keys/{p=1; next} /^## /{p=0} p && /^\| `/' "$readme" |
  sed -E 's/^\| `([^`]*)` \| (.*) \|$/\1\t\2/')

if [[ -z "$from_help" ]]; then echo "FAILED: $program --help lists no keys"; exit 1; fi
if [[ "$from_help" != "$from_readme" ]]; then
  echo "FAILED: the Keys table of $readme is not the key list of --help"
  diff <(echo "$from_help") <(echo "$from_readme") | sed 's/^/  /'
  exit 1
fi
echo "the Keys table of $readme lists the $(wc -l <<<"$from_help") key lines of --help"
