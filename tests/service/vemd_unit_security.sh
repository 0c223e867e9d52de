#!/bin/sh
# Scores systemd/vemd.service's sandbox with `systemd-analyze security --offline=true` and fails
# when the overall exposure is above the threshold (0.0 = fully locked down ... 10.0 = unsafe).
# Exits 77 (ctest SKIP_RETURN_CODE) when systemd-analyze is not installed (package `systemd`).
# Usage: vemd_unit_security.sh UNIT_FILE MAX_EXPOSURE   (e.g. 2.5)
set -u
unit=$1
max=$2
if ! command -v systemd-analyze >/dev/null 2>&1; then
  echo "systemd-analyze not found (Debian package systemd): skipped"
  exit 77
fi
# --threshold counts tenths: exposure 2.5 is 25.
threshold=$(awk -v m="$max" 'BEGIN { printf "%d", m * 10 + 0.5 }')
report=$(systemd-analyze security --offline=true --threshold="$threshold" "$unit" 2>&1)
status=$?
printf '%s\n' "$report" | grep -E '^(✗|Overall|→)|exposure level' || printf '%s\n' "$report"
if ! printf '%s\n' "$report" | grep -q 'Overall exposure level'; then
  echo "systemd-analyze gave no score for $unit"
  exit 1
fi
if [ "$status" -ne 0 ]; then
  echo "$unit: exposure above $max (or systemd-analyze failed, status $status)"
  exit 1
fi
echo "$unit: exposure at most $max"
