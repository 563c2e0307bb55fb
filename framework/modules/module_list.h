// THE registration list. Adding a technique or an accelerator is one source
// file (which defines `TechniqueInfo nameTechnique()` or `AcceleratorInfo
// nameAccelerator()`) plus one line here. Order = order shown to users.
#pragma once

#ifdef LIGHTLAB_HAVE_EMBREE
#define LIGHTLAB_EMBREE_ACCELERATOR(X) X(embreeAccelerator)
#else
#define LIGHTLAB_EMBREE_ACCELERATOR(X)
#endif

#ifdef LIGHTLAB_HAVE_GPU
#define LIGHTLAB_GPU_TECHNIQUES(X) X(blinnPhongGlTechnique)
#else
#define LIGHTLAB_GPU_TECHNIQUES(X)
#endif

#define LIGHTLAB_ACCELERATORS(X) \
  X(bruteForceAccelerator)       \
  X(bvhAccelerator)              \
  X(wideBvhAccelerator)          \
  X(kdtreeAccelerator)           \
  X(bspAccelerator)              \
  X(octreeAccelerator)           \
  LIGHTLAB_EMBREE_ACCELERATOR(X)

#define LIGHTLAB_TECHNIQUES(X) \
  X(blinnPhongTechnique)       \
  X(raycastTechnique)          \
  X(whittedTechnique)          \
  X(radiosityTechnique)        \
  X(radiosityRasterTechnique)  \
  X(pathTechnique)             \
  LIGHTLAB_GPU_TECHNIQUES(X)
