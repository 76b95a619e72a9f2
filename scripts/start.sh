#!/usr/bin/env bash
# Starts the Phalanx team against rcssserver3d. The player process does not exist yet (issue 8).
echo "start.sh: the Phalanx player is not written yet; only the foundation (comm, sim-stub) exists." >&2
echo "start.sh: run scripts/test.sh for the tests, scripts/sim-stub to replay a recording." >&2
exit 2
