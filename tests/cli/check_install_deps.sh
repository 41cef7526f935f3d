#!/usr/bin/env bash
# scripts/install-deps never removes a package the user has: with apt-get and dpkg-query stubbed
# (an installed python3-paraview that python3-vtk9 would remove, and two packages missing), it
# skips python3-vtk9 and says why, installs the other with --no-remove, and with nothing left to
# install it installs nothing.
set -euo pipefail
root="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/bin"
calls="$work/apt-calls"

# Every package is installed except those in $MISSING.
cat > "$work/bin/dpkg-query" <<'STUB'
#!/usr/bin/env bash
pkg="${!#}"
for m in $MISSING; do [[ "$pkg" == "$m" ]] && exit 1; done
printf 'install ok installed'
STUB
# Simulations print apt's Inst/Remv lines; a real install is recorded.
cat > "$work/bin/apt-get" <<'STUB'
#!/usr/bin/env bash
if [[ " $* " == *" -s "* ]]; then
  for a in "$@"; do
    case "$a" in
      python3-vtk9) echo "Remv python3-paraview [5.11.0]"; echo "Inst python3-vtk9 (9.1.0)" ;;
      -*|install) ;;
      *) echo "Inst $a (1.0)" ;;
    esac
  done
  exit 0
fi
echo "$*" >> "$CALLS"
STUB
printf '#!/usr/bin/env bash\n"$@"\n' > "$work/bin/sudo"
chmod +x "$work/bin/"*

fail() { echo "check_install_deps: $*" >&2; exit 1; }

out=$(PATH="$work/bin:$PATH" MISSING="python3-vtk9 libstb-dev" CALLS="$calls" \
  bash "$root/scripts/install-deps" 2>&1) || fail "install-deps failed: $out"
echo "$out"
grep -q "skipping python3-vtk9: installing it would remove python3-paraview" <<< "$out" ||
  fail "the skipped package and what it would remove are not named"
[[ $(wc -l < "$calls") -eq 1 ]] || fail "expected one install, got: $(cat "$calls")"
grep -q -- "--no-remove" "$calls" || fail "the install may remove packages: $(cat "$calls")"
grep -q "libstb-dev" "$calls" || fail "the package without conflict was not installed"
if grep -q "python3-vtk9" "$calls"; then fail "the conflicting package was installed"; fi

# Only the conflicting package missing: nothing is installed.
: > "$calls"
PATH="$work/bin:$PATH" MISSING="python3-vtk9" CALLS="$calls" \
  bash "$root/scripts/install-deps" > /dev/null 2>&1 || fail "install-deps failed"
[[ ! -s "$calls" ]] || fail "installed with nothing to install: $(cat "$calls")"
echo "check_install_deps: passed"
