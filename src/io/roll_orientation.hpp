// Frame3DD's roll angle of a beam as kinestat's orientation vector: used by the YAML structure reader
// (`roll:`) and the Frame3DD reader.
#pragma once

#include "kinestat/core/types.hpp"

namespace kinestat::io {

// The local y axis of a beam along `d` rolled by `roll` (rad) about its axis, as Frame3DD defines it
// (coord_trans with z vertical): unrolled, local y is global z x d normalized, and global y for an
// exactly vertical member only (kinestat's default switches within 2.6 deg of vertical); the roll
// turns local y towards local z. Used as the beam's orientation vector.
Vec3 roll_orientation(const Vec3& d, double roll);

}  // namespace kinestat::io
