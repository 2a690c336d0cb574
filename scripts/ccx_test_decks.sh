#!/usr/bin/env bash
# Fetches CalculiX's own test decks (Debian's calculix-ccx-test package, GPL:
# they are fetched, never copied into this repository), picks the 2D ones
# (an *ELEMENT of type CPE*, CPS* or CAX*) and shows what tether makes of
# them: `tether check` over all of them (one table of what it refuses), then
# `tether run` deck by deck, counting the decks that run unchanged.
#
#   bash scripts/ccx_test_decks.sh [WORKDIR]   (default: out/ccx_test_decks)
#
# Needs apt-get (a Debian or Ubuntu machine; no root needed for `download`)
# and build/bin/tether. Each run gets 300 s.
set -euo pipefail
cd "$(dirname "$0")/.."
tether="$PWD/build/bin/tether"
work="$(realpath -m "${1:-out/ccx_test_decks}")"
mkdir -p "$work/deb" "$work/decks" "$work/runs"
if ! ls "$work"/deb/calculix-ccx-test_*.deb > /dev/null 2>&1; then
  (cd "$work/deb" && apt-get download calculix-ccx-test)
fi
deb="$(ls "$work"/deb/calculix-ccx-test_*.deb | head -1)"
echo "package: $(basename "$deb")"
rm -rf "$work/extract" && dpkg-deb -x "$deb" "$work/extract"
tests="$(find "$work/extract" -type d -path '*examples/test' | head -1)"
cp "$tests"/*.inp* "$work/decks/" 2> /dev/null || true
# Included files (*INCLUDE) and decks may come gzipped.
find "$work/decks" -name '*.gz' -exec gunzip -f {} +
mapfile -t decks < <(grep -liE '^\*element.*type *= *(cpe|cps|cax)' "$work"/decks/*.inp | sort)
echo "2D decks: ${#decks[@]} of $(ls "$work"/decks/*.inp | wc -l)"
echo
echo "== tether check --dialect calculix (all 2D decks) =="
"$tether" check --dialect calculix "${decks[@]}" || true
echo
echo "== tether run, deck by deck =="
ran=0
for deck in "${decks[@]}"; do
  name="$(basename "$deck" .inp)"
  if (cd "$(dirname "$deck")" && timeout 300 "$tether" run -q --dialect calculix "$deck" -o "$work/runs/$name" > "$work/runs/$name.log" 2>&1); then
    ran=$((ran + 1))
    echo "ran      $name"
  else
    echo "refused  $name: $(grep -m1 -E 'error|refus' "$work/runs/$name.log" | cut -c1-160)"
  fi
done
echo
echo "tether runs $ran of ${#decks[@]} 2D decks unchanged"
