// LIGHTLAB_ANSWER_FILE A2.2, A2.3: the student tree holds this file as object code only.
// The framework answers that live inline in headers, compiled out of line
// (with LIGHTLAB_EXPORT_ANSWERS) into liblightlab_private.a for the student
// tree, whose headers hold only their declarations (tasks/framework_answer.h).
#define LIGHTLAB_EXPORT_INLINE_ANSWERS 1
#include "accel/ray_sphere.h"
#include "accel/ray_triangle.h"
