# The layers of the code and which folders each may include (README "Layout"); sourced by
# tests/regression/layers.sh. A folder is a core subfolder ("core/aero") or a top-level folder
# ("trim"). Lower layers first:
#   core/model  <  core/aero, core/integrate, core/structure, core/analysis  <  core/dynamics
#   <  trim  <  optimize  <  studies  <  python
# core/version.hpp (generated) may be included from anywhere; tests/ and examples/ from anything.
layer_allows() {  # layer_allows FROM TO: exit 0 when a file in FROM may include a header in TO
  local from=$1 to=$2
  [[ $from == "$to" ]] && return 0
  case $from in
    core/model) return 1 ;;
    core/aero|core/structure|core/analysis) [[ $to == core/model ]] ;;
    core/integrate) return 1 ;;
    core/dynamics) [[ $to == core/* ]] ;;
    trim) [[ $to == core/* ]] ;;
    optimize) [[ $to == core/* || $to == trim ]] ;;
    studies) [[ $to == core/* || $to == trim || $to == optimize ]] ;;
    python) [[ $to == core/* || $to == trim || $to == optimize || $to == studies ]] ;;
    *) return 0 ;;
  esac
}

folder_of() {  # folder_of PATH (relative to the root): core/<sub> or the top-level folder
  local p=$1
  if [[ $p == core/*/* ]]; then p=${p#core/}; echo "core/${p%%/*}"; else echo "${p%%/*}"; fi
}

# Prints one line per include that runs against the layers under ROOT; exit 1 when there is one.
check_layers() {  # check_layers ROOT
  local root=$1 bad=0 file rel from inc to
  while IFS= read -r file; do
    rel=${file#"$root"/}
    from=$(folder_of "$rel")
    while IFS= read -r inc; do
      [[ $inc == core/version.hpp ]] && continue
      [[ $inc == */* ]] || continue  # a header beside the file
      to=$(folder_of "$inc")
      [[ -d $root/$to ]] || continue  # not ours (a library's header in quotes)
      if ! layer_allows "$from" "$to"; then
        echo "$rel includes $inc: $from may not include $to"
        bad=1
      fi
    done < <(sed -nE 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"([^"]+)".*/\1/p' "$file")
  done < <(find "$root/core" "$root/trim" "$root/optimize" "$root/studies" "$root/python" \
             -type f \( -name '*.hpp' -o -name '*.cpp' -o -name '*.h' \) 2>/dev/null | sort)
  return $bad
}
