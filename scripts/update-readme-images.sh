#!/usr/bin/env bash
# Regenerates docs/images/*.png: a few small gallery frames the README shows, so a
# visitor sees the result without building. Each is one lit frame on lavapipe with
# fixed weather (no timeline), so the same build gives the same files.
# Look at every image (and git diff --stat docs/images) before committing.
# WG_SKIP_BUILD=1 uses the existing build/weathergen.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -n "${WG_SKIP_BUILD:-}" ] || scripts/build.sh
out=docs/images
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
size=480x270
render() {  # NAME, then render's arguments
  local name=$1
  shift
  build/weathergen render "$@" --size "$size" --device cpu -q -o "$tmp/$name.png"
}
render valley-snowfall --scene valley --camera orbit:210,22,45 --weather precipitation=0.7,temperature=-6,snowLevel=0.7,windIntensity=0.3,frostLevel=0.4
render rocks-moss --scene rocks --camera orbit:130,28,22 --weather temperature=11,mossLevel=0.6,wetnessLevel=0.5
render river-frozen --scene river --camera orbit:100,6,30 --weather temperature=-12,snowLevel=0.35,frostLevel=0.9
render road-rain --scene road --camera orbit:60,4,18 --weather precipitation=0.8,temperature=7,wetnessLevel=0.8,puddleLevel=0.8,windIntensity=0.3
render road-after-rain --scene road --camera orbit:60,4,18 --weather precipitation=0,temperature=9,wetnessLevel=1,puddleLevel=0.8
render stand-rock-snow --material graphs/rock.json --camera sun-side --weather temperature=-4,snowLevel=0.6,frostLevel=0.5
render model-engine-snow --model /usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb \
  --model-scale 0.01 --weather temperature=-3,snowLevel=0.6,frostLevel=0.4
# A MaterialX material (the MaterialX project's procedural marble) on the stand, dry and in snow.
build/weathergen import -q "${WEATHERGEN_MATERIALX_EXAMPLES:-../shared/materialx}/StandardSurface/standard_surface_marble_solid.mtlx" \
  -o "$tmp/marble" 2>/dev/null
render materialx-marble-dry --material "$tmp/marble/standard_surface_marble_solid_Marble_3D.json"
render materialx-marble-snow --material "$tmp/marble/standard_surface_marble_solid_Marble_3D.json" \
  --weather temperature=-5,precipitation=0.5,snowLevel=0.5
rm -rf "$tmp/marble"
# A metal: MaterialX's gold (base colour, metalness 1, roughness 0.02), dry and in snow.
build/weathergen import -q "${WEATHERGEN_MATERIALX_EXAMPLES:-../shared/materialx}/StandardSurface/standard_surface_gold.mtlx" \
  -o "$tmp/gold" 2>/dev/null
render materialx-gold-dry --material "$tmp/gold/standard_surface_gold_Gold.json"
render materialx-gold-snow --material "$tmp/gold/standard_surface_gold_Gold.json" \
  --weather temperature=-4,precipitation=0.4,snowLevel=0.5
rm -rf "$tmp/gold"
# The snowfield writes a contact sheet of its key moments; keep the second: trails and ruts.
build/weathergen render --scene snowfield --size "$size" --device cpu -q --frames "$tmp/snowfield" -o "$tmp/sheet.png"
cp "$(ls "$tmp"/snowfield/*.png | sed -n 2p)" "$tmp/snowfield-prints.png"
rm -rf "$tmp/snowfield" "$tmp"/sheet*.png
# One material, two hosts: BoxTextured.glb's imported material under snow lit by Filament
# (tests/package/filament_host_test.sh keeps its frames) and by weathergen's own renderer,
# from the same view (Filament's camera at azimuth 37, elevation 27 degrees).
WG_FILAMENT_FRAMES="$tmp/filament" tests/package/filament_host_test.sh build . cmake ninja c++ >/dev/null
cp "$tmp/filament/snow.png" "$tmp/filament-box-snow.png"
build/weathergen render --model /usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb \
  --camera orbit:37,27 --size 480x360 --device cpu -q -o "$tmp/weathergen-box-snow.png" \
  --weather sunDirection=-0.497:0.795:0.348,sunMelt=0,temperature=-6,precipitation=0.6,snowLevel=1,sunIntensity=0.6,windIntensity=0.2
rm -rf "$tmp/filament"
mkdir -p "$out"
cp "$tmp"/*.png "$out/"
git --no-pager diff --stat -- "$out" || true
echo "update-readme-images: $(ls "$out"/*.png | wc -l) images in $out"
