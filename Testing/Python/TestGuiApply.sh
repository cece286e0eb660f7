#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# GUI test: the paraview executable under Xvfb runs TestGuiApply.py (--script), which applies the
# filter with the sphere widget visible, checks the chart view, and saves a screenshot. Fails
# unless the script recorded "passed" and the screenshot is not blank.
set -eu
plugin=$1 script=$2 glass=$3 shot=$4
status="$shot.status"
rm -f "$shot" "$status"
# A fresh settings folder that turns off the first-start welcome dialog (a modal dialog would
# wait for a click that never comes).
config=$(mktemp -d)
mkdir -p "$config/ParaView"
printf '[General]\nGeneralSettings.ShowWelcomeDialog=0\n' > "$config/ParaView/ParaView5.11.ini"
export XDG_CONFIG_HOME=$config
LSI_PLUGIN=$plugin LSI_GLASS=$glass LSI_SCREENSHOT=$shot LSI_STATUS=$status \
  timeout 300 bash "$(dirname "$0")/../RunWithXvfb.sh" paraview --dr --script="$script" || true
test "$(cat "$status" 2>/dev/null)" = passed || { echo "FAILED: the GUI script's checks (status: $(cat "$status" 2>/dev/null || echo none))"; exit 1; }
test -s "$shot" || { echo "FAILED: no screenshot"; exit 1; }
size=$(stat -c %s "$shot")
echo "screenshot $shot: $size bytes"
test "$size" -gt 20000 || { echo "FAILED: screenshot looks blank"; exit 1; }
