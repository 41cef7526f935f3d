#!/usr/bin/env bash
# scripts/update-validation-doc turns a ctest log into docs/validation.md's table: each
# [validation] row under the test that printed it, with that test's result; a log without rows
# is an error (exit 1), not an empty document.
set -euo pipefail
root=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cat > "$dir/log" <<'LOG'
Start testing: Dec 04 02:01 UTC
----------------------------------------------------------
1/2 Testing: Suite.Passes
[validation] {"test": "Suite.Passes", "quantity": "floor layer / rho0 g d", "reference": "Pascal", "expected": "1", "bound": "within 5 %", "measured": 1.0291, "unit": ""}
Test Passed.
----------------------------------------------------------
2/2 Testing: Suite.Fails
[validation] {"test": "Suite.Fails", "quantity": "arrival | time", "reference": "MARIN", "expected": "0.395 s", "bound": "within 0.05 s", "measured": 0.5, "unit": "s"}
Test Failed.
LOG
python3 "$root/scripts/update-validation-doc" "$dir/log" "$dir/validation.md"
grep -qF '| `Suite.Passes` | floor layer / rho0 g d | Pascal | 1 | within 5 % | 1.029 | passed |' "$dir/validation.md"
grep -qF '| `Suite.Fails` | arrival \| time | MARIN | 0.395 s | within 0.05 s | 0.5 s | failed |' "$dir/validation.md"
printf 'Start testing: now\n1/1 Testing: A.B\nTest Passed.\n' > "$dir/empty"
if python3 "$root/scripts/update-validation-doc" "$dir/empty" "$dir/none.md" 2>/dev/null; then
  echo "a log without rows was accepted"; exit 1
fi
[[ ! -e $dir/none.md ]]
echo ok
