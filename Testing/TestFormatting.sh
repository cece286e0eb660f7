#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# The sources follow .clang-format, and every source file carries its SPDX licence line.
#   TestFormatting.sh SOURCE_DIR CLANG_FORMAT
set -u
cd "$1" || exit 1
status=0
cxx=$(git ls-files '*.h' '*.cxx' 2>/dev/null || find . -name '*.h' -o -name '*.cxx' | grep -v '^./build')
if ! "$2" --dry-run --Werror $cxx; then
  echo "FAILED: not formatted as .clang-format says (run: clang-format -i \$(git ls-files '*.h' '*.cxx'))"
  status=1
fi
sources=$(git ls-files '*.h' '*.cxx' '*.py' '*.sh' '*.xml' '*CMakeLists.txt' .ci/run)
missing=$(grep -L 'SPDX-License-Identifier' $sources)
if [ -n "$missing" ]; then
  echo "FAILED: no SPDX-License-Identifier line in:"
  echo "$missing"
  status=1
fi
# The filter, readers and plugin speak through VTK's messages (vtkWarningMacro, vtkErrorMacro),
# never to the terminal: a print left in them (a timer, say) is a leftover.
prints=$(git grep -nE 'std::(cout|cerr)|(^|[^a-zA-Z_])(f?printf|puts)\(' -- Filters IO Plugin 2>/dev/null)
if [ -n "$prints" ]; then
  echo "FAILED: direct prints in the library (use VTK's messages):"
  echo "$prints"
  status=1
fi
[ $status -eq 0 ] && echo "$(echo $cxx | wc -w) C++ files formatted; $(echo $sources | wc -w) files with SPDX lines"
exit $status
