#!/usr/bin/env bash
# stop.sh [LOG_DIR]: stops exactly the players that start.sh started, by the PIDs it recorded in
# LOG_DIR/pids (default: the newest run under ${PHALANX_LOG_DIR:-/tmp/phalanx-logs}).
set -euo pipefail
dir="${1:-}"
if [ -z "$dir" ]; then
  base="${PHALANX_LOG_DIR:-${TMPDIR:-/tmp}/phalanx-logs}"
  dir=$(ls -1dt "$base"/*/ 2>/dev/null | head -1 || true)
  [ -n "$dir" ] || { echo "stop.sh: no run found under $base" >&2; exit 1; }
fi
pids="$dir/pids"
[ -f "$pids" ] || { echo "stop.sh: no pids file in $dir" >&2; exit 1; }
stopped=0
while read -r pid; do
  [ -n "$pid" ] || continue
  # Only a process that is still our player: a PID may have been reused since.
  if [ -r "/proc/$pid/cmdline" ] && tr '\0' ' ' < "/proc/$pid/cmdline" | grep -q ' phalanx[.]agent[.]Player '; then
    kill "$pid" && stopped=$((stopped + 1))
  fi
done < "$pids"
echo "stop.sh: stopped $stopped player(s) of $dir"
