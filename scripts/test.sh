#!/usr/bin/env bash
# Runs every test of every module on a fresh Debian/Ubuntu machine: installs a JDK 17 and gradle
# if missing, runs `gradle test` (JUnit 5 through the console launcher), and ends with one line
# "N passed, N failed, N skipped" summed over all modules (after a line "FAILED class.test: message"
# for each failing test). Exit status non-zero on any failure.
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
# Each failing test by name, next to the summary: CI shows only the tail of a long run.
if [ "$failed" -gt 0 ]; then
  awk '/<testcase /{ match($0, / name="[^"]*"/); n = substr($0, RSTART + 7, RLENGTH - 8)
                     match($0, / classname="[^"]*"/); c = substr($0, RSTART + 12, RLENGTH - 13) }
       /<(failure|error)[ >]/{ m = ""; if (match($0, / message="[^"]*"/)) m = substr($0, RSTART + 10, RLENGTH - 11)
                     gsub(/&lt;/, "<", m); gsub(/&gt;/, ">", m); gsub(/&quot;/, "\"", m); gsub(/&amp;/, "\\&", m)
                     print "FAILED " c "." n ": " substr(m, 1, 400) }' */build/test-results/junit/TEST-junit-jupiter.xml
fi
passed=$(( tests - failed - skipped ))
echo "$passed passed, $failed failed, $skipped skipped"
if [ "$rc" -ne 0 ] && [ "$failed" -eq 0 ]; then
  echo "test: the build failed before or outside the tests (exit $rc); see above" >&2
fi
[ "$rc" -eq 0 ] && [ "$failed" -eq 0 ] && [ "$tests" -gt 0 ]
