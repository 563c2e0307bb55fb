// Assignment 3 -- Recursive (Whitted) ray tracing. The five functions you
// write. Each lives in its own .cpp file between the markers of its task ID;
// the technique `whitted` (whitted_technique.cpp) calls them through the
// framework's helpers in whitted_tracer.h. Until you write one, its stub
// reports the task as missing and the task's reference (the course's solution,
// object code) answers in its place, the pixels striped, so the tasks can be
// done in any order. See README.md for the handout and the --reference switches.
#pragma once

#include "core/math.h"
#include "core/ray.h"

namespace ll::a3 {

class WhittedTracer;
struct PathState;

// A3.1 Reflection. The mirror direction of the unit incoming direction d
// (pointing towards the surface) about the unit normal n (either side):
// r = d - 2 (d.n) n. Unit length.
Vec3 reflect(Vec3 d, Vec3 n);

// A3.2 Refraction (Snell's law). d: unit incoming direction; n: unit normal
// on the incoming side (d.n <= 0); eta = n1 / n2, the index of the medium d
// travels in over the index of the medium behind the surface. Sets t to the
// unit refracted direction and returns true; returns false (t untouched)
// under total internal reflection, when sin(theta_t) = eta sin(theta_i) > 1.
bool refract(Vec3 d, Vec3 n, float eta, Vec3& t);

// A3.3 Fresnel equations for a dielectric interface, unpolarised light split
// into its s and p parts. cosI = cos(theta_i) in [0, 1] on the side of index
// n1; the far side has index n2. Rs and Rp are the reflectances (squared
// amplitude ratios) of s- and p-polarised light; both are 1 under total
// internal reflection, and both 0 when n1 == n2 (no interface), even at
// grazing incidence. The unpolarised reflectance is (Rs + Rp) / 2.
struct FresnelTerms {
  float rs = 1.0f;
  float rp = 1.0f;
  float unpolarized() const { return 0.5f * (rs + rp); }
};
FresnelTerms fresnelDielectric(float cosI, float n1, float n2);

// A3.4 Recursion. The radiance arriving along `ray` (the lecture's
// trace(p, d, step)): stop (return black) when the path is too deep or
// carries too little weight (tracer.maxDepth(), tracer.minThroughput());
// otherwise find the hit with tracer.intersect(); on a miss return the
// sky it sees, tracer.background(ray); on a hit return emitted + local (tracer.emitted, tracer.local)
// plus, where the material calls for it, the reflected and transmitted
// radiance, each traced with tracer.trace() and weighted as the lecture
// writes it (mirror reflectance; for dielectrics the Fresnel reflectance F
// and 1 - F, times the transmission colour). `path` is this ray's state:
// depth (0 = camera ray), throughput (its weight in the pixel), media.
Rgb radiance(const WhittedTracer& tracer, const Ray& ray, const PathState& path);

// A3.5 Secondary-ray origins. A ray leaving the surface point p (geometric
// unit normal ng, either side) in direction dir must not hit that surface
// again: move p off the surface to the side dir leaves towards, by an
// amount that scales with the magnitude of p's coordinates (Wächter and
// Binder, Ray Tracing Gems ch. 6; see render/ray_offset.h), so it works
// near the origin and at 1e5 alike. Returns the ray with tmin = 0 and tmax = +inf.
Ray secondaryRay(Vec3 p, Vec3 ng, Vec3 dir);

}  // namespace ll::a3
