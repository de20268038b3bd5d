// A plain reference: MidPointFM2D with addition written as Peitgen & Saupe print it (whole-grid
// loops, one point at a time), with the same random numbers and rounding rules as the fast
// generator. Benchmarks measure against it; tests check the fast generator equals it bit for bit.
#pragma once

#include "terrain/midpoint.hpp"

namespace sansui::reference {

Heightfield midpoint_displacement(const terrain::MidpointParams& params, int size);

}  // namespace sansui::reference
