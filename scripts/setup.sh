#!/usr/bin/env bash
# Installs what Phalanx needs to build on Debian/Ubuntu when it is missing: a JDK 17 and Debian's
# gradle package, and GNU parallel and rsync for `scripts/phalanx tournament --jobs/--hosts` (games as
# parallel jobs; rsync brings a remote host's results back). Does nothing when all are there. Uses
# sudo when not run as root.
set -euo pipefail
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"

need=()
if ! command -v javac >/dev/null 2>&1 || ! javac -version 2>&1 | grep -Eq 'javac (1[7-9]|[2-9][0-9])'; then
  need+=(openjdk-17-jdk-headless)
fi
command -v gradle >/dev/null 2>&1 || need+=(gradle)
# Optional: only tournaments with --jobs/--hosts need them, so a failed install does not stop the set-up.
optional=()
{ parallel --version 2>/dev/null | grep -q "GNU parallel"; } || optional+=(parallel)  # not moreutils' parallel
command -v rsync >/dev/null 2>&1 || optional+=(rsync)

if [ $(( ${#need[@]} + ${#optional[@]} )) -gt 0 ]; then
  echo "setup: installing ${need[*]} ${optional[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q >/dev/null || [ ${#need[@]} -eq 0 ]
  [ ${#need[@]} -eq 0 ] || $SUDO apt-get install -y -q "${need[@]}" >/dev/null
  if [ ${#optional[@]} -gt 0 ] && ! $SUDO apt-get install -y -q "${optional[@]}" >/dev/null 2>&1; then
    echo "setup: could not install ${optional[*]}; tournaments with --jobs/--hosts need them (the rest does not)" >&2
  fi
fi

# rcssservermj (MuJoCo server, issue 20) into the project's own virtual environment, pinned, from PyPI:
# `.venv/bin/rcssservermj`. Skipped with a message when Python >= 3.10 or PyPI is missing: the build and
# the SimSpark path do not need it; the tests that do skip and say so. PHALANX_NO_MJ=1 skips it too.
root="$(cd "$(dirname "$0")/.." && pwd)"
req="$root/scripts/lib/rcssservermj-requirements.txt"
venv="$root/.venv"
stamp="$venv/.rcssservermj-requirements"
if [ "${PHALANX_NO_MJ:-0}" != 1 ] && ! cmp -s "$req" "$stamp" 2>/dev/null; then
  py=""
  for c in python3 python3.13 python3.12 python3.11 python3.10; do
    if command -v "$c" >/dev/null 2>&1 && "$c" -c 'import sys; sys.exit(sys.version_info < (3, 10))' 2>/dev/null; then py="$c"; break; fi
  done
  if [ -z "$py" ]; then
    echo "setup: no Python >= 3.10; rcssservermj not installed (the MJ server tests will skip)" >&2
  else
    if ! "$py" -c 'import venv, ensurepip' >/dev/null 2>&1; then
      # Debian splits venv/ensurepip into python3-venv.
      echo "setup: installing python3-venv" >&2
      export DEBIAN_FRONTEND=noninteractive
      { $SUDO apt-get update -q && $SUDO apt-get install -y -q python3-venv; } >/dev/null 2>&1 || true
    fi
    echo "setup: installing rcssservermj into $venv (pinned, from PyPI)" >&2
    if { [ -x "$venv/bin/pip" ] || "$py" -m venv "$venv"; } \
       && "$venv/bin/pip" install -q --disable-pip-version-check -r "$req" >&2; then
      cp "$req" "$stamp"
    else
      echo "setup: could not install rcssservermj (no PyPI?); the MJ server tests will skip" >&2
    fi
  fi
fi
