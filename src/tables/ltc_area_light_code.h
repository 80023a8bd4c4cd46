// The shader code of rectangular area lights lit with a linearly transformed
// cosine table (ltc_ggx): what lutbake.<ext> adds when such a table is baked.
// Conventions in ltc_area_light_code.cpp and docs/formats.md ("Rectangular
// area lights").
#pragma once

#include <string>

#include "lutbake/tables/shader_dialect.h"
#include "lutbake/tables/table.h"

namespace lutbake {

// The functions shared by every LTC table (the edge integral, the clipped
// polygon integral, the rectangle's form factor in the LTC frame, the
// Lambertian rectangle): emitted once.
std::string LtcPolygonFunctions(const source_text::Dialect &d);

// The rectangle of table `ltc` (six channels m00, m20, m02, m22, magnitude,
// fresnel, read by lutbake_sample_<T>_ch0_3 and lutbake_sample_<T>_ch4_5):
// lutbake_rect_light_<T> and lutbake_rect_light_<T>_f1.
std::string LtcRectangleFunctions(const source_text::Dialect &d, const Table &ltc);

}  // namespace lutbake
