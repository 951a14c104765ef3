# Helpers shared by the CLI regression scripts (tests/regression/*.sh); sourced, not run.
#   check "description" command...  runs the command, prints "ok   ..." or "FAIL ..."; a failure
#                                   sets fail=1 (the script's exit status at its end)
#   json FILE KEY                   the first scalar value of "KEY" in FILE (number, true, false,
#                                   null or a string without its quotes)
#   awk_true EXPR                   exit status 0 when the awk expression is true
fail=0
check() {
  local what=$1; shift
  if "$@"; then echo "ok   $what"; else echo "FAIL $what"; fail=1; fi
}
json() {
  grep -m1 "\"$2\":" "$1" | sed -E 's/.*: *([-+0-9.eE]+|true|false|null|"[^"]*").*/\1/' | tr -d '"'
}
awk_true() { awk "BEGIN { exit !($1) }"; }
