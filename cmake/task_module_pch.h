// The precompiled header of every student task module (cmake/LightlabTaskModules.cmake):
// the framework and standard headers the assignments' task headers include, parsed once
// per build, so that rebuilding one task's module after a save (the GUI's hot reload) is
// the compile of the student's file alone. Framework headers only: nothing here is a task's.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "accel/accelerator.h"
#include "core/math.h"
#include "core/ray.h"
#include "render/student_task.h"
#include "render/tracer.h"
#include "scene/camera.h"
#include "scene/geometry.h"
#include "scene/scene.h"
