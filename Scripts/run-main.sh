#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# The main job: install, build, then run Level-Set Isosurface in pvbatch on the paper's
# one-component case (200,000 samples), writing Results/one_component_surface.vtp (binary
# XML, readable by this ParaView) and Results/one_component_surface.png.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/Scripts/setup-debian12.sh"
mkdir -p "$here/Results"
"$here/build/bin/LevelSetGenerateData" one-component 200000 "$here/Results/one_component_samples.vtp"
bash "$here/Testing/RunWithXvfb.sh" pvbatch "$here/Scripts/main_job.py" \
  "$here/build/lib/paraview-5.11/plugins/LevelSetIsosurface/LevelSetIsosurface.so" \
  "$here/Results/one_component_samples.vtp" "$here/Results/one_component_surface"
