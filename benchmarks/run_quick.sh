#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/run_quick.sh: every benchmarks/<name>/run.sh --quick in turn, with pass/fail and wall time of each.
#
# Usage, after the README's build (cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build -j2):
#   benchmarks/run_quick.sh [NAME ...]        NAME: a folder of benchmarks/ (default: every folder with a run.sh)
#   nice -n 19 benchmarks/run_quick.sh        beside other work
# Environment:
#   BUILD_DIR   the build directory (default: build in this checkout). Its fluid_surface is the program every
#               benchmark runs (passed on as EXE, FLUID_SURFACE and BINARY; the first two through a wrapper in LOGS
#               that notes every run the program refuses, exit status 2), its libfluid_surface_library.so the
#               library the drivers of equilibrium, output_formats and surface_stokes link (BUILD_DIR is passed on);
#               they are compiled there (geometry compiles its own in benchmarks/geometry/build). Another checkout's
#               build can be used by a directory that holds only links to its fluid_surface and
#               libfluid_surface_library.so (the drivers of this checkout then compile into that directory).
#   LOGS        where each benchmark's output goes, as <name>.log, and the table times.csv (default:
#               benchmarks/quick_logs, not committed).
#   LIMIT       seconds a benchmark may take before it is stopped and counted as failed (default 3600).
#   BUILD_LOCK  a lock file: the benchmarks' compiles run under `flock BUILD_LOCK` (passed on).
# A benchmark passes when its run.sh --quick exits with 0, its output holds no Python traceback, the program refused
# none of its runs (exit status 2: an entry it does not know or a value or combination it does not accept; the
# scripts go on after a failed run, so this is where a stale entry shows; fuzz, which feeds refused values on
# purpose, is not watched), and it leaves the committed files of its folder as they were (checked with git when this
# is a git checkout): --quick writes to quick/ or work/ subfolders, which are not committed, never over the committed
# tables and plots of the full runs. Exit status: 0 when every benchmark passed.
#
# Measured on the 2-core machine, 2026-12-06, each time in a fresh git clone of main with BUILD_DIR a directory of links
# to main's build (so the drivers were compiled on the way, under BUILD_LOCK) and everything under nice -n 19
# (benchmarks/quick_times.csv, seconds per benchmark):
#   loaded_s: beside other compiles and test runs (load average 4.7 to 7.5 when sampled): 2880 s in all, of which
#             convergence 1102 s with its former --quick (both mesh laws); its present --quick took 208 s on its own
#             afterwards (load falling from about 2.5), which makes 1983 s (33 min) for the present set. Every
#             benchmark passed.
#   idle_s:   with nothing else running (load average about 1): 1299 s (22 min); every benchmark passed but
#             surface_stokes, whose driver aborted (SIGABRT) after 60 s, and again after 159 s when rerun: a data race
#             in the library's threaded assembly (SurfaceFlow::node_frames calls SurfaceGeometry::normal_field(), which
#             computes the lazily cached curvature, from the WorkStream workers), not in the script. Loaded it passed
#             in 318 s, so the whole set takes about 26 minutes on an idle machine once it passes.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
build=$(cd "${BUILD_DIR:-build}" 2>/dev/null && pwd) || { echo "run_quick.sh: no build directory '${BUILD_DIR:-build}'; build the project first (README.md)" >&2; exit 2; }
[ -x "$build/fluid_surface" ] || { echo "run_quick.sh: no $build/fluid_surface; build the project first (README.md)" >&2; exit 2; }
logs=${LOGS:-$root/benchmarks/quick_logs}
mkdir -p "$logs"
logs=$(cd "$logs" && pwd)
limit=${LIMIT:-3600}
# The wrapper: runs the program, and on exit status 2 notes its arguments in $REFUSED (set per benchmark below).
cat > "$logs/fluid_surface" <<WRAPPER
#!/usr/bin/env bash
"$build/fluid_surface" "\$@" <&0 & child=\$!
trap 'kill -TERM \$child 2> /dev/null' TERM INT HUP
wait \$child; status=\$?
while kill -0 \$child 2> /dev/null; do wait \$child; status=\$?; done
[ \$status = 2 ] && [ -n "\${REFUSED:-}" ] && echo "\$*" >> "\$REFUSED"
exit \$status
WRAPPER
chmod +x "$logs/fluid_surface"
export BUILD_DIR=$build EXE=$logs/fluid_surface FLUID_SURFACE=$logs/fluid_surface BINARY=$build/fluid_surface
[ -n "${BUILD_LOCK:-}" ] && export BUILD_LOCK
names=${*:-$(for f in benchmarks/*/run.sh; do basename "$(dirname "$f")"; done)}
git=0; git -C "$root" rev-parse --is-inside-work-tree > /dev/null 2>&1 && git=1
# the committed files of a folder that differ from HEAD (or are deleted), and its files that git would add
changed() { git -C "$root" status --porcelain --untracked-files=all -- "benchmarks/$1" 2>/dev/null | sort; }

echo "benchmark,status,wall_s,note" > "$logs/times.csv"
failed=0; total_start=$(date +%s.%N)
printf '%-16s %-6s %9s  %s\n' benchmark status "wall [s]" note
for name in $names; do
  [ -x "benchmarks/$name/run.sh" ] || { echo "run_quick.sh: no benchmarks/$name/run.sh" >&2; failed=1; continue; }
  [ $git = 1 ] && before=$(changed "$name")
  export REFUSED=$logs/$name.refused; rm -f "$REFUSED"
  start=$(date +%s.%N)
  timeout "$limit" "benchmarks/$name/run.sh" --quick < /dev/null > "$logs/$name.log" 2>&1
  status=$?
  wall=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.0f", b - a }')
  note=""
  if [ $status = 124 ]; then note="stopped after $limit s"
  elif [ $status != 0 ]; then note="exit $status, see $logs/$name.log"
  fi
  # a script that goes on after a failed step (its last command a cat) still leaves the traceback in its log
  grep -q '^Traceback (most recent call last)' "$logs/$name.log" && note="${note:+$note; }a Python traceback in $logs/$name.log"
  if [ -s "$REFUSED" ] && [ "$name" != fuzz ]; then
    note="${note:+$note; }$(wc -l < "$REFUSED") runs refused (exit 2), see $REFUSED"
  fi
  if [ $git = 1 ]; then
    new=$(comm -13 <(echo "$before") <(changed "$name") | sed 's/^...//' | tr '\n' ' ')
    [ -n "$new" ] && note="${note:+$note; }wrote committed or unignored files: $new"
  fi
  result=pass; [ -n "$note" ] && { result=FAIL; failed=1; }
  printf '%-16s %-6s %9s  %s\n' "$name" $result "$wall" "$note"
  echo "$name,$result,$wall,\"$note\"" >> "$logs/times.csv"
done
total=$(awk -v a="$total_start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.0f", b - a }')
printf '%-16s %-6s %9s\n' total "" "$total"
echo "total,,$total," >> "$logs/times.csv"
echo "logs and times.csv in $logs"
exit $failed
