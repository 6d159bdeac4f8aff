#!/usr/bin/env bash
# Runs two topocut binaries on the same inputs and compares every output file: images by their
# decoded pixels (PNG/PGM encoders may differ byte for byte), text files (JSON, SVG, YAML) byte
# for byte. Used to show that a refactoring changes no output.
#   scripts/compare_outputs.sh BASE_TOPOCUT NEW_TOPOCUT [WORK_DIR] [--quick] [-- SEGMENT_OPTIONS...]
# --quick: Bormann plain maps and the bundled maps only (no furnished maps, real maps, logs).
# SEGMENT_OPTIONS go to every `segment` run (e.g. -- --no-learned-merge for the hand rules' rooms).
# Exits 0 when every output is equal, 1 otherwise (listing the differing files), 2 on a bad call.
set -uo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
data="$here/../shared/datasets"
segment_options=()
for ((i = 1; i <= $#; ++i)); do
  if [[ "${!i}" == -- ]]; then segment_options=("${@:i+1}"); set -- "${@:1:i-1}"; break; fi
done
usage() { sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'; }
case "${1:-}" in -h|--help) usage; exit 0 ;; esac
# Checked before anything is deleted: a mistyped call must not wipe the work folder of another run.
if (( $# < 2 )) || [[ ! -x "$1" || ! -x "$2" ]]; then
  echo "compare_outputs.sh: BASE_TOPOCUT and NEW_TOPOCUT must be executable topocut binaries" >&2; usage >&2; exit 2
fi
base="$(realpath "$1")"; new="$(realpath "$2")"; work="${3:-/tmp/topocut_compare}"; quick="${4:-}"
[[ "${3:-}" == --quick ]] && { work=/tmp/topocut_compare; quick=--quick; }
rm -rf "$work"; mkdir -p "$work/base" "$work/new"

maps=("$here"/maps/*.yaml)
if [[ -d "$data/bormann" ]]; then
  for f in "$data"/bormann/*.png; do
    [[ "$f" == *_gt_segmentation.png ]] && continue
    [[ -n "$quick" && "$f" == *_furnitures.png ]] && continue
    maps+=("$f")
  done
  if [[ -z "$quick" ]]; then
    for f in "$data"/real_maps/*.png "$data"/real_maps/*.yaml "$data"/real_maps/Benedetti.pgm \
             "$data"/real_maps/EX1.pgm; do [[ -e "$f" ]] && maps+=("$f"); done
  fi
else
  echo "compare_outputs: $data absent: comparing the bundled maps only"
fi

run_all() {  # $1 = binary, $2 = output dir
  local bin="$1" out="$2" m name
  for m in "${maps[@]}"; do
    name="$(basename "${m%.*}")_$(basename "$(dirname "$m")")"
    "$bin" segment "$m" "${segment_options[@]}" --out-labels "$out/$name.labels.png" --out-json "$out/$name.json" \
      --out-svg "$out/$name.svg" --out-geojson "$out/$name.geojson" \
      >"$out/$name.stdout" 2>&1 || echo "exit $?" >>"$out/$name.stdout"
  done
  "$bin" segment "$here/maps/floorplan.yaml" --out-color "$out/floorplan.color.png" >/dev/null 2>&1
  "$bin" explore "$here/maps/floorplan.yaml" --gt "$here/maps/floorplan_gt_segmentation.png" \
    --frames "$out/explore_frames" --frame-every 5 >"$out/explore.stdout" 2>&1 || echo "exit $?" >>"$out/explore.stdout"
  if [[ -z "$quick" && -d "$data/carmen" ]]; then
    for log in "$data"/carmen/*.log.gz; do
      name="$(basename "${log%.log.gz}")"
      "$bin" walls "$log" --out-walls "$out/$name.walls.json" --out-map "$out/$name.map.yaml" \
        --out-rooms "$out/$name.rooms.json" >/dev/null 2>&1 || echo "exit $?" >"$out/$name.walls.exit"
    done
  fi
}

run_all "$base" "$work/base" & run_all "$new" "$work/new" & wait

/usr/bin/python3 - "$work" <<'PY'
import sys, os, re, numpy as np
from PIL import Image
work = sys.argv[1]
b, n = os.path.join(work, "base"), os.path.join(work, "new")
def files(root):
    return {os.path.relpath(os.path.join(d, f), root) for d, _, fs in os.walk(root) for f in fs}
names = sorted(files(b) | files(n))
bad = []
for f in names:
    pb, pn = os.path.join(b, f), os.path.join(n, f)
    if not (os.path.exists(pb) and os.path.exists(pn)):
        bad.append(f + " (only in one run)"); continue
    if f.endswith((".png", ".pgm")):
        if not np.array_equal(np.array(Image.open(pb)), np.array(Image.open(pn))):
            bad.append(f)
    elif f.endswith(".stdout"):
        # Timings and the run's own folder differ from run to run; compare the rest.
        def keep(p, own):
            t = open(p, errors="replace").read().replace(own, "OUT")
            return re.sub(r"[0-9.]+ ?(ms|s)\b", "T", t)
        if keep(pb, b) != keep(pn, n): bad.append(f)
    elif open(pb, "rb").read() != open(pn, "rb").read():
        bad.append(f)
print(f"compare_outputs: {len(names)} files, {len(bad)} differ")
for f in bad: print("  differs:", f)
sys.exit(1 if bad else 0)
PY
