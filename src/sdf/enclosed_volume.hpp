// Whether a signed distance field has an inside at all. An open sheet (a
// single surface patch, flat or bent) has a generalized winding number below
// 1/2 everywhere, and so does a solid thinner than the gap between cell
// centres: the field is then negative at every cell and there is nothing to
// smooth. That is the input's fault, not the smoothing's, and is reported
// before any lattice work.
#pragma once

#include <cstddef>
#include <filesystem>

#include "lbmshape/band/band_field.hpp"
#include "lbmshape/core/volume.hpp"

namespace lbmshape {

// Cells with X > 0 (inside, in the paper's sign convention).
size_t insideCellCount(const Volume& field);

// Throws InputError naming `meshPath` when no cell of `field` is inside.
void requireEnclosedVolume(const Volume& field, const std::filesystem::path& meshPath);
// The same on the narrow band: no stored cell inside and no brick beyond it inside.
void requireEnclosedVolume(const BandField& field, const std::filesystem::path& meshPath);

// The largest X of `field`: how deep its inside reaches, in the field's
// units (the band's far value where a brick beyond the band is inside).
double deepestInside(const Volume& field);
double deepestInside(const BandField& field);

}  // namespace lbmshape
