// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Turns isopoints with "Normals" and "SplatRadius" into oriented splats: one regular polygon per
// isopoint in its tangent plane, as ordinary polygons that any VTK renderer or exporter draws
// (a closed, shaded surface with the default Surface representation).
#ifndef LevelSetSplatOutput_h
#define LevelSetSplatOutput_h

#include "LevelSetParallel.h"

#include <vector>

class vtkPolyData;

namespace lsi
{
class SPHField;

/// Fills `splats` with `sides` corners per point of `isopoints` and one polygon per point; every
/// point array of `isopoints` (normals, radius, interpolated data) is copied to the corners of
/// its polygon. With an SPH field (`field` not null), each corner then slides along its splat's
/// normal onto the field's level `isoValue` (at most the splat's radius; where that fails, from
/// halfway in; else the corner moves to the centre) and takes the field's normal there: the
/// polygons bend with the surface, so the corners lie on it and their normals are the field's,
/// instead of tangent-plane approximations. Returns false only when aborted.
/// `normals` and `radii`, if given (3 doubles and 1 per point), are the splats' normals and
/// radii unrounded, which the corners are made from instead of the arrays' floats: a rounding
/// to float moves a corner by up to 6e-8 of its radius, by where the last bit fell (under MPI,
/// by the rank that found the point).
bool MakeSplatPolygons(vtkPolyData* isopoints, int sides, const SPHField* field, double isoValue,
  vtkPolyData* splats, const AbortCheck& aborted, const std::vector<double>* normals = nullptr,
  const std::vector<double>* radii = nullptr);

/// Moves the `sides` corners of each splat of `splats` (made by MakeSplatPolygons) as its centre
/// moved, from `from` to `to` (3 doubles per point): a periodic box's points moved by whole
/// boxes after their splats were made where the particles are.
void MoveSplatCorners(
  const std::vector<double>& from, const std::vector<double>& to, int sides, vtkPolyData* splats);

} // namespace lsi

#endif
