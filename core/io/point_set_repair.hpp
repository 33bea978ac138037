#pragma once
// Internal to read_point_set: the small defects of real scans, repaired with a
// warning that counts them (and names the file and the first place), rather
// than refusing the whole file.
//   1. prepare_points, before the dimension is decided: points with a
//      non-finite coordinate are dropped; normals that are zero or non-finite
//      are marked for estimation (a file whose normals are all such is read as
//      one without normals); the others are normalised.
//   2. repair_points, in the set's dimension: points at exactly the position
//      of an earlier one are merged into it, and the marked normals are
//      estimated from the neighbours' positions (core/surface/normal_estimation)
//      and oriented to agree with the neighbours' normals.
#include <cstdint>
#include <vector>

#include "core/io/raw_point_file.hpp"

namespace amls::detail {

// Returns one flag a point: 1 where the normal is to be estimated (all 0 when
// the set has no normals). Such normals are set to zero.
std::vector<std::uint8_t> prepare_points(RawPointFile& raw);

// `dimension` is 2 (z = 0) or 3; `unusable_normal` as prepare_points returned it.
void repair_points(RawPointFile& raw, int dimension, std::vector<std::uint8_t> unusable_normal);

}  // namespace amls::detail
