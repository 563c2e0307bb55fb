// An accelerator that tests every primitive with YOUR ray-sphere (A2.2) and
// ray-triangle (A2.3). raycast uses it when intersection=student, so what
// you write is what you see. (Framework code: nothing to edit here.)
#pragma once

#include <memory>

#include "accel/accelerator.h"

namespace ll::a2 {

std::unique_ptr<Accelerator> makeStudentIntersector();

}  // namespace ll::a2
