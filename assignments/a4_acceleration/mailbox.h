// Mailboxing for space partitions (KD-tree, octree): a primitive reaching
// into several cells sits in several leaves, and a ray crossing those cells
// would test it again in each. A mailbox remembers the last few primitives
// one ray tested, so a repeat is skipped. Exact: a repeated test gives the
// same answer, already kept in the hit. Per ray (on the stack), so threads
// share nothing. Framework code.
#pragma once

#include <cstdint>

#include "bvh_ray_tests.h"

namespace ll::a4 {

class Mailbox {
 public:
  // Whether `prim` was tested recently by this ray; if not, remembers it.
  bool seen(uint32_t prim) {
    bool found = false;
    for (uint32_t p : slots_) found |= p == prim;  // no early exit: the compiler compares all 8 at once
    if (found) return true;
    slots_[next_++ & (kSize - 1)] = prim;
    return false;
  }

  static constexpr uint32_t kSize = 8;  // the last 8 primitives: repeats come from neighbouring cells

 private:
  uint32_t slots_[kSize] = {~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u};
  uint32_t next_ = 0;
};

// A space partition's leaf: tests the primitives in slots [first, end) that
// `mailbox` has not seen (counting them in `tested`) and keeps the closest
// hit in `hit` (AnyHit: stops at the first). Returns whether anything was hit.
template <bool AnyHit>
bool testLeafOnce(const LeafPrimitives& prims, uint32_t first, uint32_t end, const TraversalRay& r, Hit& hit,
                  Mailbox& mailbox, uint64_t& tested) {
  bool found = false;
  for (uint32_t s = first; s < end; ++s) {
    if (mailbox.seen(prims.primIds[s])) continue;
    ++tested;
    if constexpr (AnyHit) {
      if (anyPrimitiveHit(prims, s, r)) return true;
    } else {
      found |= closerPrimitiveHit(prims, s, r, hit);
    }
  }
  return found;
}

}  // namespace ll::a4
