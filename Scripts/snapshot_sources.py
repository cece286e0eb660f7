# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The real snapshots as the scripts open them (through the plugin's readers, loaded first)."""
import os

from paraview.simple import OpenDataFile


def open_snapshot(data, path, types):
    """A reader on DATA/PATH with the particle types TYPES selected."""
    reader = OpenDataFile(os.path.join(data, path))
    reader.UpdatePipelineInformation()
    reader.ParticleTypes = types
    return reader
