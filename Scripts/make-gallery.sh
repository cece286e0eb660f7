#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# The README's gallery: installs and builds (as the main job does), generates the two synthetic
# cases at the paper's size (2M samples), then renders the gallery under Xvfb into
# Documentation/gallery/ (the Evrard glass comes from Data/ChaNGa).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/Scripts/setup-debian12.sh"
data="$here/Results/gallery-data"
mkdir -p "$data" "$here/Documentation/gallery"
"$here/build/bin/LevelSetGenerateData" one-component 2000000 "$data/one_component_2M.vtp"
"$here/build/bin/LevelSetGenerateData" multi-component 2000000 "$data/multi_component_2M.vtp" 1 \
  "$data/multi_component_exact.vtp"
# The multi-component case's seeds (SyntheticCases.h): two of its four blobs.
LSI_MULTI_SEEDS="44,64,64,14,70,64,64,14" LSI_MULTI_ISO=0.5 xvfb-run -a pvbatch \
  "$here/Scripts/gallery.py" \
  "$here/build/lib/paraview-5.11/plugins/LevelSetIsosurface/LevelSetIsosurface.so" "$data" \
  "$here/Data/ChaNGa/adiabtophat_glass_28721.bin" "$here/Data/ChaNGa/changa_run581.20000" \
  "$here/Documentation/gallery"
