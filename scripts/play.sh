#!/usr/bin/env bash
# play.sh [--server auto|simspark|mj] [--against 'NAME=COMMAND'] [--half-time S] [--halves 1|2] [--dir DIR]
# Plays one whole game on this machine and prints its score: a private server on 127.0.0.1 (headless,
# agent-sync), our team against a copy of itself (or any scripts/phalanx match team command with
# {host} {port} {dir}), kick-offs, progress (game time, score), the score and the result JSON at the end;
# every process it started is stopped, also on Ctrl-C. The server: rcssserver3d (SimSpark, 11 Nao) when it
# is on PATH or named by $RCSSSERVER3D, else rcssservermj (MuJoCo, 7 Booster T1; scripts/setup.sh installs
# it into .venv); --server chooses. Installs the build tools and builds first.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
server=auto; against=""; half=""; halves=2; dir=""
while [ $# -gt 0 ]; do
  case "$1" in
    --server) server="${2:?--server needs auto, simspark or mj}"; shift ;;
    --against) against="${2:?--against needs NAME=COMMAND}"; shift ;;
    --half-time) half="${2:?--half-time needs seconds}"; shift ;;
    --halves) halves="${2:?--halves needs 1 or 2}"; shift ;;
    --dir) dir="${2:?--dir needs a folder}"; shift ;;
    -h|--help) sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "play.sh: unknown argument $1 (--help)" >&2; exit 2 ;;
  esac
  shift
done

case "$server" in auto|simspark|mj) ;; *) echo "play.sh: --server must be auto, simspark or mj, got '$server'" >&2; exit 2 ;; esac
case "$halves" in 1|2) ;; *) echo "play.sh: --halves must be 1 or 2, got '$halves'" >&2; exit 2 ;; esac
"$root/scripts/setup.sh"
if [ "$server" = auto ]; then
  if [ -n "${RCSSSERVER3D:-}" ] || command -v rcssserver3d >/dev/null 2>&1; then server=simspark
  elif [ -n "${PHALANX_RCSSSERVERMJ:-}" ] || [ -x "$root/.venv/bin/rcssservermj" ] || command -v rcssservermj >/dev/null 2>&1; then server=mj
  else
    echo "play.sh: no server: neither rcssserver3d (SimSpark, not packaged: docs/protocol.md) nor rcssservermj" >&2
    echo "  (scripts/setup.sh installs rcssservermj from PyPI when Python >= 3.10 and PyPI are there)" >&2
    exit 3
  fi
fi
case "$server" in
  simspark) flags=(--sync); robot=""; echo "play.sh: rcssserver3d (SimSpark), 11 Nao a side" ;;
  mj) flags=(--server mj); robot=" --mj"; echo "play.sh: rcssservermj (MuJoCo), 7 Booster T1 a side" ;;
esac
[ -n "$half" ] && flags+=(--half-time "$half")
[ -n "$dir" ] && flags+=(--dir "$dir")
copy='Phalanx2=scripts/start.sh {host} {port} Phalanx2'"$robot"' --log-dir {dir}'
right="$copy"; [ -n "$against" ] && right="$against"
cd "$root"
exec scripts/phalanx match "${flags[@]}" --halves "$halves" \
  --left "Phalanx=scripts/start.sh {host} {port} Phalanx$robot --log-dir {dir}" --right "$right"
