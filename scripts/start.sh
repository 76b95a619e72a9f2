#!/usr/bin/env bash
# start.sh [host] [port] [team] [--nine | --mj] [--log-dir DIR] [--only "1 2 ..."]
# Starts the Phalanx team (11 players, or 9 with --nine for server 0.6.5) against rcssserver3d, or
# 7 Booster T1 players against rcssservermj with --mj (docs/rcssservermj.md);
# --only starts just those uniform numbers (e.g. --only 1 for the goalkeeper test of thesis 6.3).
# Installs the build tools if missing and builds first. Players connect one after another, each once
# the previous one is in the game, so no two robots are created in the same cycle. Each player gets
# its own log file; PIDs go to DIR/pids for scripts/stop.sh.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"

host=127.0.0.1; port=3100; team=Phalanx; players=11; logdir=""; only=""; mj=0
pos=()
while [ $# -gt 0 ]; do
  case "$1" in
    --nine) players=9 ;;
    --mj) mj=1; players=7 ;;
    --log-dir) logdir="${2:?--log-dir needs a directory}"; shift ;;
    --only) only="${2:?--only needs uniform numbers}"; shift ;;
    -h|--help) sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "start.sh: unknown option $1" >&2; exit 2 ;;
    *) pos+=("$1") ;;
  esac
  shift
done
[ ${#pos[@]} -ge 1 ] && host="${pos[0]}"
[ ${#pos[@]} -ge 2 ] && port="${pos[1]}"
[ ${#pos[@]} -ge 3 ] && team="${pos[2]}"
[ ${#pos[@]} -ge 4 ] && { echo "start.sh: too many arguments: ${pos[*]}" >&2; exit 2; }
[[ "$port" =~ ^[0-9]+$ ]] || { echo "start.sh: port must be a number, got '$port'" >&2; exit 2; }

# Is a server listening? Say how to get one if not. On this machine look the port up in the kernel's
# table instead of connecting: in agent-sync mode a probe connection that never sends (syn) would
# stall the server (docs/protocol.md). A remote server is probed with a connection.
listening() {
  case "$host" in
    127.*|localhost|::1)
      local hex; hex=$(printf '%04X' "$port")
      cat /proc/net/tcp /proc/net/tcp6 2>/dev/null | awk -v p=":$hex" '$4 == "0A" && substr($2, length($2) - 4) == p { found = 1 } END { exit !found }' ;;
    *) (exec 3<>"/dev/tcp/$host/$port") 2>/dev/null ;;
  esac
}
if ! listening && [ "$mj" -eq 1 ]; then
  cat >&2 <<MSG
start.sh: no rcssservermj is listening on $host:$port.
  scripts/setup.sh installs it into .venv; start it with
  .venv/bin/rcssservermj --host 127.0.0.1 --aport $port --mport M --sync --no-realtime --no-render
MSG
  exit 3
fi
if ! listening; then
  cat >&2 <<MSG
start.sh: no rcssserver3d is listening on $host:$port.
  Start one first (rcssserver3d, or rcssserver3d --agent-port $port --server-port M).
  rcssserver3d is not packaged by Debian/Ubuntu: build it from a SimSpark release
  (https://gitlab.com/robocup-sim/SimSpark) and put it on PATH; docs/protocol.md lists the
  spark.rb settings it needs on Debian 12 (Ruby 3).
MSG
  exit 3
fi

"$root/scripts/setup.sh"
(cd "$root" && gradle -q --console=plain :agent:classpathFile 2>&1 | grep -v -E '^(openjdk version|OpenJDK )' >&2; exit "${PIPESTATUS[0]}") \
  || { echo "start.sh: build failed" >&2; exit 2; }
cp="$(cat "$root/agent/build/runtime-classpath.txt")"

# Logs go where the user can write; never $HOME (competitions mount it read-only).
[ -n "$logdir" ] || logdir="${PHALANX_LOG_DIR:-${TMPDIR:-/tmp}/phalanx-logs}/$team-$(date +%Y%m%d-%H%M%S)"
mkdir -p "$logdir" || { echo "start.sh: cannot create log directory $logdir" >&2; exit 2; }

# Robot types: the server wants at least 3 types, at most 7 of one, the two most used at most 9
# together. Types 0, 2 and 4 share the same leg and arm lengths (2: faster ankle pitch, 4: toes),
# so every motion is tuned on one geometry. Override with PHALANX_TYPES="0 0 2 ...".
if [ "$players" -eq 11 ]; then default_types="0 0 0 2 2 0 2 0 2 4 4"; elif [ "$players" -eq 9 ]; then default_types="0 0 2 2 0 2 4 0 4"; else default_types="0 0 0 0 0 0 0"; fi
read -r -a types <<< "${PHALANX_TYPES:-$default_types}"
[ "${#types[@]}" -eq "$players" ] || { echo "start.sh: PHALANX_TYPES needs $players types, got ${#types[@]}" >&2; exit 2; }

# The team channel's per-match key (issue 4): one random key shared by this team's players only.
export PHALANX_TEAM_KEY="${PHALANX_TEAM_KEY:-$(head -c 12 /dev/urandom | od -An -tx1 | tr -d ' \n')}"

# JVM options for 11 JVMs on 2 cores: small fixed heap and the serial collector (short pauses,
# no GC threads), C1 only (less compile CPU and code cache), no perf data file.
jvm=(${PHALANX_JVM_OPTS:--Xms32m -Xmx96m -XX:+UseSerialGC -XX:TieredStopAtLevel=1 -XX:ReservedCodeCacheSize=24m -XX:MaxMetaspaceSize=48m -Xss512k -XX:-UsePerfData -Xshare:auto})

: > "$logdir/pids"
unums=$(seq 1 "$players")
if [ -n "$only" ]; then
  for u in $only; do
    [[ "$u" =~ ^[0-9]+$ ]] && [ "$u" -ge 1 ] && [ "$u" -le "$players" ] || { echo "start.sh: --only takes uniform numbers 1-$players, got '$u'" >&2; exit 2; }
  done
  unums="$only"
fi
for unum in $unums; do
  out="$logdir/player-$unum.out"
  # A log of an earlier run in the same folder (a replayed tournament game) still says "in the game" until
  # the new JVM truncates it, so the wait below would not wait and robots would connect in the same cycle,
  # which stalls a sync-mode server (docs/matches.md, issue 21's resumed tournament).
  rm -f "$logdir/player-$team-$unum.log"
  nohup java "${jvm[@]}" -Xlog:gc:file="$logdir/gc-$unum.log":uptime,level -cp "$cp" phalanx.agent.Player \
    --host "$host" --port "$port" --team "$team" --unum "$unum" $([ "$mj" -eq 1 ] && echo --server mj || echo --players "$players") \
    --type "${types[$((unum-1))]}" --log-dir "$logdir" --motions "$root/motions" ${PHALANX_PLAYER_OPTS:-} > "$out" 2>&1 &
  echo "$!" >> "$logdir/pids"
  # Wait until this player is in the game (or gone) before the next one connects.
  for _ in $(seq 1 100); do
    grep -q "in the game" "$out" "$logdir/player-$team-$unum.log" 2>/dev/null && break
    kill -0 "$!" 2>/dev/null || break
    sleep 0.1
  done
  if ! kill -0 "$!" 2>/dev/null; then
    echo "start.sh: player $unum exited at once; its output:" >&2
    tail -5 "$out" >&2
  fi
done
echo "start.sh: $(wc -l < "$logdir/pids") players of $team on $host:$port; logs and pids in $logdir"
echo "start.sh: stop them with scripts/stop.sh $logdir"
