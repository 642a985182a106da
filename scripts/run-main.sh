#!/usr/bin/env bash
# The main job: set up, build, compile every bundled graph into out/materials (and
# every static-switch variant into out/variants), and
# render the gallery into out/gallery (every scene, every weather stage, both backends).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh
scripts/build.sh
rm -rf out/materials out/variants out/gallery
build/weathergen compile graphs/*.json -o out/materials --target all
echo "main: wrote $(ls out/materials | wc -l) files for $(ls graphs/*.json | wc -l) materials to out/materials"
# Every static-switch variant, files keyed by content hash; NAME.variants.json maps them.
build/weathergen compile graphs/*.json -o out/variants --variants all
echo "main: wrote $(ls out/variants | wc -l) files for every variant to out/variants (see out/variants/rock.variants.json)"
mkdir -p out/gallery
for scene in $(build/weathergen list-scenes | cut -f1); do
  for backend in glsl hlsl; do
    build/weathergen render --scene "$scene" --backend "$backend" --timeline timelines/seasons.json \
      --size 640x360 --frames "out/gallery/frames-$backend" -o "out/gallery/$scene-$backend.png"
  done
  # The weather's coverage terms for the same stages, as the AOVs show them.
  for aov in snow wet moss ice puddle; do
    build/weathergen render --scene "$scene" --aov "$aov" --timeline timelines/seasons.json \
      --size 320x180 -o "out/gallery/$scene-$aov.png" -q
  done
done
# Interactive snow (docs/deformable-snow.md): walkers and a vehicle leave prints, the
# camera leaves the deformation window and comes back to find them restored.
build/weathergen render --scene snowfield --size 640x360 --frames out/gallery/frames-snowfield \
  -o out/gallery/snowfield.png
# One material on the preview stand (sphere, rock, ramp, cube on a post, roof) through the
# seasons: render --material takes any graph file.
build/weathergen render --material graphs/rock.json --timeline timelines/seasons.json \
  --size 640x360 --frames out/gallery/frames-stand -o out/gallery/stand-rock.png
# Content nobody here wrote: glTF 2.0 models from Debian's assimp-testmodels, their
# materials imported as graphs (docs/gltf-import.md) and weathered through the seasons.
models=/usr/share/assimp/models/glTF2
rm -rf out/imported
build/weathergen import "$models/BoxTextured-glTF-Binary/BoxTextured.glb" -o out/imported/BoxTextured
build/weathergen import "$models/2CylinderEngine-glTF-Binary/2CylinderEngine.glb" -o out/imported/2CylinderEngine
build/weathergen render --model "$models/BoxTextured-glTF-Binary/BoxTextured.glb" --timeline timelines/seasons.json \
  --size 640x360 --frames out/gallery/frames-models -o out/gallery/model-BoxTextured.png
# The engine is about 600 units across (authored in millimetres); --model-scale 0.01 shows
# it as a 6 m engine, large against the weather's centimetre snow depths.
build/weathergen render --model "$models/2CylinderEngine-glTF-Binary/2CylinderEngine.glb" --model-scale 0.01 \
  --timeline timelines/seasons.json --size 640x360 --frames out/gallery/frames-models \
  -o out/gallery/model-2CylinderEngine.png
echo "main: gallery in out/gallery ($(ls out/gallery/*.png | wc -l) contact sheets and strips; start with out/gallery/valley-glsl.png)"
