#!/usr/bin/env bash
# GUI smoke test: the paraview executable under Xvfb loads the plugin, applies the filter from
# a --script, and saves a screenshot; fails unless the screenshot exists and is not blank.
set -eu
plugin=$1 script=$2 shot=$3
rm -f "$shot"
LSI_PLUGIN=$plugin LSI_SCREENSHOT=$shot timeout 300 xvfb-run -a paraview --script="$script" --exit
test -s "$shot" || { echo "FAILED: no screenshot"; exit 1; }
# A blank view compresses to a few KB; the isopoints make it larger.
size=$(stat -c %s "$shot")
echo "screenshot $shot: $size bytes"
test "$size" -gt 8000 || { echo "FAILED: screenshot looks blank"; exit 1; }
