#!/usr/bin/env bash
# CLI contract (docs/design.md section 3): every malformed file in tests/data/bad is rejected with
# exit status 2 and a message on stderr that names the file.
#   usage: bash bad_inputs.sh <ornithopter-binary> <repo-root> <scratch-dir>
# A file with a top-level `kind = ...` key (before the first table header) is a study and runs with
# `ornithopter run FILE`; any other file is a vehicle and runs with `ornithopter simulate FILE`.
set -u

bin=${1:?usage: bad_inputs.sh <ornithopter> <repo-root> <scratch-dir>}
root=${2:?usage: bad_inputs.sh <ornithopter> <repo-root> <scratch-dir>}
scratch=${3:?usage: bad_inputs.sh <ornithopter> <repo-root> <scratch-dir>}
mkdir -p "$scratch"

is_study() {
  awk '/^[[:space:]]*\[/ { exit 1 } /^[[:space:]]*kind[[:space:]]*=/ { found = 1; exit 0 }
       END { exit found ? 0 : 1 }' "$1"
}

failures=0
count=0
shopt -s nullglob
for file in "$root"/tests/data/bad/*.toml; do
  count=$((count + 1))
  name=$(basename "$file")
  if is_study "$file"; then
    command=(run "$file" -o "$scratch/out_${name%.toml}")
  else
    command=(simulate "$file" -o "$scratch/out_${name%.toml}")
  fi
  "$bin" "${command[@]}" >"$scratch/stdout.txt" 2>"$scratch/stderr.txt"
  status=$?
  if [[ $status -ne 2 ]]; then
    echo "FAIL $name: ornithopter ${command[0]} exited with $status, expected 2"
    failures=$((failures + 1))
  elif ! grep -qF -- "$name" "$scratch/stderr.txt"; then
    echo "FAIL $name: stderr does not name the file: $(head -c 300 "$scratch/stderr.txt")"
    failures=$((failures + 1))
  else
    echo "ok   $name: $(head -n 1 "$scratch/stderr.txt")"
  fi
done

if [[ $count -eq 0 ]]; then
  echo "FAIL no files in $root/tests/data/bad"
  exit 1
fi
echo "$((count - failures)) of $count malformed inputs rejected correctly"
[[ $failures -eq 0 ]]
