#!/bin/sh
# CPU time of the `aniso` window while it refines the default scene and once it is still: starts
# ANISO (default: aniso on PATH) under xvfb-run, prints the process's CPU time (user + system,
# all threads, from /proc/PID/stat) used in each second, and after SECONDS (default 60) the
# total of the last IDLE (default 10) seconds. Usage: bench/idle_cpu.sh [ANISO] [SECONDS] [IDLE]
set -eu
aniso=${1:-aniso}
seconds=${2:-60}
idle=${3:-10}
tick=$(getconf CLK_TCK)
xvfb-run -a -s "-screen 0 1280x1024x24" "$aniso" &
runner=$!
pid=""
for _ in $(seq 1 100); do
  pid=$(pgrep -n -f "^$aniso\$" || true)
  [ -n "$pid" ] && break
  sleep 0.1
done
if [ -z "$pid" ]; then
  echo "idle_cpu: $aniso did not start" >&2
  kill "$runner" 2>/dev/null || true
  exit 1
fi
cpu() { awk '{print $14 + $15}' "/proc/$1/stat"; }
start=$(cpu "$pid")
previous=$start
mark=0
for second in $(seq 1 "$seconds"); do
  sleep 1
  now=$(cpu "$pid")
  echo "second $second: $(( (now - previous) * 1000 / tick )) ms of CPU"
  previous=$now
  [ "$second" -eq $((seconds - idle)) ] && mark=$now
done
echo "last $idle s: $(( (previous - mark) * 1000 / tick )) ms of CPU in total"
kill "$pid" 2>/dev/null || true
wait "$runner" 2>/dev/null || true
