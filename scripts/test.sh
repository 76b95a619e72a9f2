#!/usr/bin/env bash
# Runs every test of every module on a fresh Debian/Ubuntu machine: installs a JDK 17 and gradle
# if missing, runs `gradle test` (JUnit 5 through the console launcher), and ends with one line
# "N passed, N failed, N skipped" summed over all modules. Exit status non-zero on any failure.
# Tests that need ../shared/recordings skip with a message when it is missing.
set -uo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh || { echo "test: setup failed" >&2; exit 1; }

rm -rf -- */build/test-results/junit
gradle --no-daemon --console=plain -q --continue test
rc=$?

tests=0; failures=0; errors=0; skipped=0
for f in */build/test-results/junit/TEST-junit-jupiter.xml; do
  [ -f "$f" ] || continue
  line=$(grep -m1 -o '<testsuite [^>]*>' "$f")
  for k in tests failures errors skipped; do
    v=$(sed -n "s/.* $k=\"\([0-9]*\)\".*/\1/p" <<<"$line")
    eval "$k=\$(( $k + ${v:-0} ))"
  done
done
failed=$(( failures + errors ))
passed=$(( tests - failed - skipped ))
echo "$passed passed, $failed failed, $skipped skipped"
if [ "$rc" -ne 0 ] && [ "$failed" -eq 0 ]; then
  echo "test: the build failed before or outside the tests (exit $rc); see above" >&2
fi
[ "$rc" -eq 0 ] && [ "$failed" -eq 0 ] && [ "$tests" -gt 0 ]
