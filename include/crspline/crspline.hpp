// crspline: umbrella header. Cubic Catmull-Rom curves in any dimension.
#pragma once

#include "analysis.hpp"
#include "arc_length.hpp"
#include "bounds.hpp"
#include "catmull_rom.hpp"
#include "certify.hpp"
#include "end_condition.hpp"
#include "error.hpp"
#include "frames.hpp"
#include "intersections.hpp"
#include "nearest.hpp"
#include "parameterization.hpp"
#include "point_traits.hpp"
#include "segment.hpp"
#include "tessellate.hpp"
#include "vec.hpp"
#include "version.hpp"
