# The layers of the code and which folders each may include (docs/layout.md); sourced by
# tests/regression/layers.sh. A folder is a core subfolder ("core/aero") or a top-level folder
# ("trim"). Lower layers first:
#   core/model  <  core/aero, core/integrate, core/structure, core/analysis  <  core/dynamics
#   <  trim  <  optimize  <  studies  <  python
# and core/grid (grid specs, sweep points, the point pool) beside aero..analysis: it includes
# core/model only; trim and the layers above may include it, core/dynamics (which does not link
# it) may not.
# Inside studies/runner the folders are layers too (docs/layout.md):
#   config < output < distributed < points < plotting < commands < cli, mpi (and main.cpp)
# so the figures and the writers never include a command, and no command includes the CLI.
# core/version.hpp (generated) may be included from anywhere; tests/ and examples/ from anything.
# Private headers: a core folder's internals (no public header of the folder includes them), which
# only files of the same folder may include (and the unit tests, which are not checked here).
ORNI_PRIVATE_HEADERS="core/dynamics/flexible_tethered.hpp core/dynamics/flight_path_frame.hpp \
core/dynamics/free_flight_recorder.hpp core/dynamics/history_window.hpp \
core/integrate/callback_guard.hpp \
core/integrate/linear_stage_solver.hpp core/integrate/serial_vector_ops.hpp \
core/structure/craig_bampton.hpp \
core/structure/rigid_body_vectors.hpp"
# Inside core/dynamics, the result types have headers of their own, below the drivers that make
# them: a result or recorder header (ORNI_LOW_HEADERS) never includes a driver header
# (ORNI_DRIVER_HEADERS), so no include runs back up inside the folder.
ORNI_LOW_HEADERS="core/dynamics/load_sample.hpp core/dynamics/simulation_result.hpp \
core/dynamics/free_flight_result.hpp core/dynamics/flight_path_frame.hpp \
core/dynamics/free_flight_recorder.hpp core/dynamics/history_window.hpp \
core/dynamics/simulation_options.hpp core/dynamics/last_cycle_harmonics.hpp"
ORNI_DRIVER_HEADERS="core/dynamics/flight_core.hpp core/dynamics/tethered_simulation.hpp \
core/dynamics/free_flight.hpp"
# One awk pass over every file (a loop in bash over ~260 files took 10-15 s).

# Prints one line per include that runs against the layers under ROOT; exit 1 when there is one.
check_layers() {  # check_layers ROOT
  local root=$1
  find "$root/core" "$root/trim" "$root/optimize" "$root/studies" "$root/python" \
    -type f \( -name '*.hpp' -o -name '*.cpp' -o -name '*.h' \) 2>/dev/null | sort |
    awk -v root="$root" -v private_list="$ORNI_PRIVATE_HEADERS" -v low_list="$ORNI_LOW_HEADERS" \
        -v driver_list="$ORNI_DRIVER_HEADERS" '
      BEGIN { n = split(private_list, p, /[[:space:]]+/); for (i = 1; i <= n; ++i) if (p[i] != "") private[p[i]] = 1
              n = split(low_list, p, /[[:space:]]+/); for (i = 1; i <= n; ++i) if (p[i] != "") low[p[i]] = 1
              n = split(driver_list, p, /[[:space:]]+/); for (i = 1; i <= n; ++i) if (p[i] != "") driver[p[i]] = 1 }
      # folder_of(PATH relative to the root): core/<sub> or the top-level folder
      function folder_of(p,   rest) {
        if (p ~ /^core\/.*\//) { rest = substr(p, 6); return "core/" substr(rest, 1, index(rest, "/") - 1) }
        if (index(p, "/") > 0) return substr(p, 1, index(p, "/") - 1)
        return p
      }
      # allows(FROM, TO): a file in FROM may include a header in TO
      function allows(from, to) {
        if (from == to) return 1
        if (from == "core/model" || from == "core/integrate") return 0
        if (from == "core/aero" || from == "core/structure" || from == "core/analysis" ||
            from == "core/grid") return to == "core/model"
        if (from == "core/dynamics") return to ~ /^core\// && to != "core/grid"
        if (from == "trim") return to ~ /^core\//
        if (from == "optimize") return to ~ /^core\// || to == "trim"
        if (from == "studies") return to ~ /^core\// || to == "trim" || to == "optimize"
        if (from == "python") return to ~ /^core\// || to == "trim" || to == "optimize" || to == "studies"
        return 1
      }
      # runner_rank(PATH): the layer of a file or header under studies/runner/ (0: not there)
      function runner_rank(p,   part) {
        if (p !~ /^studies\/runner\//) return 0
        part = substr(p, 16)
        if (index(part, "/") == 0) return 8  # main.cpp, ornithopter.hpp: the executable
        part = substr(part, 1, index(part, "/") - 1)
        if (part == "config") return 1
        if (part == "output") return 2
        if (part == "distributed") return 3
        if (part == "points") return 4
        if (part == "plotting") return 5
        if (part == "commands") return 6
        if (part == "cli" || part == "mpi") return 7
        return 9  # a new folder: place it in this list
      }
      # ours(TO): ROOT/TO is a folder (not a library header in quotes); asked once per folder
      function ours(to,   q) {
        if (!(to in is_dir)) {
          q = root "/" to; gsub(/\047/, "\047\\\047\047", q)
          is_dir[to] = (system("test -d \047" q "\047") == 0)
        }
        return is_dir[to]
      }
      { file = $0; rel = substr(file, length(root) + 2); from = folder_of(rel)
        while ((getline line < file) > 0) {
          if (!match(line, /^[[:space:]]*#[[:space:]]*include[[:space:]]*"[^"]+"/)) continue
          inc = substr(line, 1, RLENGTH); sub(/^[^"]*"/, "", inc); sub(/"$/, "", inc)
          if (inc == "core/version.hpp") continue
          if (index(inc, "/") == 0) continue  # a header beside the file
          to = folder_of(inc)
          if (!ours(to)) continue
          if (!allows(from, to)) { print rel " includes " inc ": " from " may not include " to; bad = 1 }
          else if ((inc in private) && from != to) { print rel " includes " inc ": private to " to; bad = 1 }
          else if ((rel in low) && (inc in driver)) { print rel " includes " inc ": a result header runs back up to a driver"; bad = 1 }
          else if (runner_rank(rel) > 0 && runner_rank(inc) > runner_rank(rel)) { print rel " includes " inc ": a studies/runner folder runs up to a higher one"; bad = 1 }
        }
        close(file)
      }
      END { exit bad }'
}
