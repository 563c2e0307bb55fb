// THE registration list. Adding a technique or an accelerator is one source
// file (which defines `TechniqueInfo nameTechnique()` or `AcceleratorInfo
// nameAccelerator()`) plus one line here. Order = order shown to users.
#pragma once

#define LIGHTLAB_ACCELERATORS(X) \
  X(bruteForceAccelerator)

#define LIGHTLAB_TECHNIQUES(X) \
  X(raycastTechnique)
