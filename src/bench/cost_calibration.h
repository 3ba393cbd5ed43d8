// `reflect bench --costs`: what the planner's cost model (core/method_cost.h) is fitted to. On
// the scene, in this renderer, four settings' frames are timed interleaved: the reflectors drawn
// as plain Phong (nothing reflected), traced (search: exact), captured and searched as the scene
// moves (search: hierarchical, when-changed), and searched alone (the same, time held still, so
// no face is redrawn). With the planner's counts of the same frame (mirror pixels, triangles,
// faces, texels), it prints each method's cost per unit: what MethodCosts holds.
#pragma once

#include <string>

#include "bench/bench_commands.h"

namespace reflect {

std::string runCostCalibration(const BenchCommandOptions& options,
                               const BenchDemoFactory& makeDemo);

}  // namespace reflect
