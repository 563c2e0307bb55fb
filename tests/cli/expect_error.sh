#!/usr/bin/env bash
# Usage: expect_error.sh REGEX OUTPUT_FILE -- COMMAND...
# Passes when COMMAND exits non-zero, prints exactly one line on stderr that
# matches REGEX (extended), does not crash (exit < 128), and leaves no OUTPUT_FILE.
set -u
regex=$1; output=$2; shift 3
rm -f "$output"
err=$("$@" 2>&1 >/dev/null); status=$?
lines=$(printf '%s\n' "$err" | grep -c .)
if [ "$status" -eq 0 ]; then echo "FAIL: exit status 0, expected an error"; exit 1; fi
if [ "$status" -ge 128 ]; then echo "FAIL: crashed (status $status): $err"; exit 1; fi
if [ "$lines" -ne 1 ]; then echo "FAIL: expected one line on stderr, got $lines:"; echo "$err"; exit 1; fi
if ! printf '%s' "$err" | grep -Eq -- "$regex"; then echo "FAIL: stderr '$err' does not match '$regex'"; exit 1; fi
if [ -n "$output" ] && [ -e "$output" ]; then echo "FAIL: $output was written despite the error"; exit 1; fi
echo "ok: $err"
